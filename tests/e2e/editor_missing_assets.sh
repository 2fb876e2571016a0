#!/usr/bin/env bash
# editor_missing_assets.sh STOA_EDITOR WORK_DIR EXAMPLE_SCENE
# A picture made from the command line stops at an asset the scene names that
# does not load (missing, not an OBJ, outside the asset folders), with exit 1
# and the scene file's line that names it (issue 25): never exit 0 with the
# object just missing.
set -euo pipefail
editor=$1 work=$2 example=$3
rm -rf "$work" && mkdir -p "$work"
line_of() { grep -n -F -- "\"$2\"" "$1" | head -1 | cut -d: -f1; }
expect() {   # expect NAME FROM TO PATTERN: the example with FROM replaced by TO fails at its line
  local name=$1 from=$2 to=$3 pattern=$4 status=0
  sed "s|\"$from\"|\"$to\"|" "$example" > "$work/$name.json"
  local line; line=$(line_of "$work/$name.json" "$to")
  "$editor" "$work/$name.json" --size 160x120 --render "$work/$name.png" > "$work/$name.out" 2> "$work/$name.err" || status=$?
  [ "$status" -eq 1 ] || { cat "$work/$name.err"; echo "FAIL: $name: exit $status, expected 1"; exit 1; }
  grep -qF -- "$work/$name.json:$line: $pattern" "$work/$name.err" ||
    { cat "$work/$name.err"; echo "FAIL: $name: expected '$name.json:$line: $pattern'"; exit 1; }
  [ ! -e "$work/$name.png" ] || { echo "FAIL: $name: a picture was written"; exit 1; }
  echo "ok: $name: $(tail -1 "$work/$name.err")"
}
expect missing_mesh acropolis/column.obj acropolis/missing.obj "cannot load the mesh acropolis/missing.obj"
expect not_an_obj acropolis/column.obj /etc/passwd "cannot load the mesh /etc/passwd: an asset name is a path inside"
expect climbing_out acropolis/column.obj ../../etc/hostname "cannot load the mesh ../../etc/hostname: an asset name"
printf '# a comment and nothing to draw\nv 0 0 0\n' > "$work/empty.obj"
expect no_faces acropolis/column.obj empty.obj "cannot load the mesh empty.obj: $work/empty.obj: the file has no faces"
expect missing_texture acropolis/floor_diffuse.jpg acropolis/missing.jpg "cannot load the texture acropolis/missing.jpg"
status=0
"$editor" "$example" --size 160x120 --render "$work/fine.png" > /dev/null 2> "$work/fine.err" || status=$?
[ "$status" -eq 0 ] && [ -s "$work/fine.png" ] || { cat "$work/fine.err"; echo "FAIL: the example scene itself did not render"; exit 1; }
echo "PASS: every asset that does not load stops the picture at the scene's line that names it"
