#!/usr/bin/env bash
# editor_bad_scene_named.sh STOA_EDITOR WORK_DIR
# stoa-editor on a broken scene file exits 1, before any window opens, with
# one line naming the file, the line and the problem; a bad command line exits
# 2 with the usage. No display is needed: the scene is read first.
set -euo pipefail
program=$1 work=$2
mkdir -p "$work"
cd "$work"
failures=0

# expect STATUS PATTERN ARGS...: stoa-editor ARGS exits STATUS and a line of its stderr
# matches the grep -E PATTERN; with status 2 another line is the usage.
expect() {
  local status=$1 pattern=$2 output actual
  shift 2
  set +e
  output=$(DISPLAY= "$program" "$@" 2>&1 >/dev/null)
  actual=$?
  set -e
  if [ "$actual" -ne "$status" ] || ! grep -qE -- "$pattern" <<< "$output" ||
     { [ "$status" -eq 2 ] && ! grep -q "^usage: stoa-editor SCENE.json" <<< "$output"; }; then
    echo "FAIL: stoa-editor $* should exit $status with a message matching: $pattern"
    echo "  it exited $actual with:"
    sed 's/^/    /' <<< "$output"
    failures=$((failures + 1))
  else
    echo "ok: stoa-editor $* -> $actual: $(head -n 1 <<< "$output")"
  fi
}

# JSON that does not parse: the comma after the camera's last member.
printf '{\n  "stoa_scene": 1,\n  "camera": {\n    "distance": 12,\n  }\n}\n' > bad_syntax.json
expect 1 "^stoa-editor: .*/bad_syntax\.json:5: a ',' before '\}': JSON allows no comma" bad_syntax.json

# A scene that parses, with an object whose material does not exist (line 8).
cat > bad_material.json <<'JSON'
{
  "stoa_scene": 1,
  "materials": [
    { "name": "stone" }
  ],
  "objects": [
    { "id": 1, "name": "block", "mesh": "shape:cube",
      "material": "granite" }
  ]
}
JSON
expect 1 '^stoa-editor: .*/bad_material\.json:8: objects\[0\]\.material: no material is called "granite"; the materials are: stone' \
  bad_material.json

# A value out of range: a shadow filter width of 4 (line 4).
printf '{\n  "stoa_scene": 1,\n  "renderer": {\n    "pcf": 4\n  }\n}\n' > bad_pcf.json
expect 1 "^stoa-editor: .*/bad_pcf\.json:4: renderer\.pcf: expected 1, 3 or 5" bad_pcf.json

# An empty file.
: > empty.json
expect 1 "^stoa-editor: .*/empty\.json:1: the file is empty" empty.json

# The command line: an unknown flag, a flag without its value, no scene, a missing scene.
expect 2 "unknown or incomplete flag --frobnicate" bad_material.json --frobnicate
expect 2 "unknown or incomplete flag --render" bad_material.json --render
expect 2 "^usage: stoa-editor SCENE\.json"
expect 2 "no scene file no_such_scene\.json" no_such_scene.json
# What is there but is not a file (issue 25): said as what it is, and a FIFO never blocks.
rm -rf a_folder.json pipe.json && mkdir a_folder.json && mkfifo pipe.json
expect 2 "a_folder\.json is a folder, not a scene file" a_folder.json
expect 2 "pipe\.json is a FIFO \(a named pipe\), not a scene file" pipe.json

[ "$failures" -eq 0 ] || exit 1
echo "PASS: broken scenes are named with their line (exit 1), bad command lines get the usage (exit 2)"
