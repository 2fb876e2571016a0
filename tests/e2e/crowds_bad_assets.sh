#!/usr/bin/env bash
# crowds_bad_assets.sh STOA_CROWDS WORK_DIR ASSETS_DIR
# A map, a model or a skin that does not load stops stoa-crowds with exit 1 and
# a message that names the world file and the line that asked for it, and then
# the file itself with what is wrong (issue 25): never a picture with a piece missing.
set -euo pipefail
crowds=$1 work=$2 assets=$3
rm -rf "$work" && mkdir -p "$work"
cp "$assets/crowds/explorer.md2" "$assets/crowds/explorer_skin.png" "$assets/crowds/acropolis_collision.png" "$work/"
world() {   # world COLLISION MODEL SKIN
  cat > "$work/world.xml" <<XML
<world seed="3">
  <ground collision="$1" min="-15 -15" max="15 15"/>
  <type name="walker" model="$2" skin="$3" behaviour="walk"/>
  <behaviour name="walk" kind="fsm">
    <state name="go"><wander/></state>
  </behaviour>
  <spawn type="walker" count="3" x="0" z="0"/>
</world>
XML
}
expect() {   # expect WHAT PATTERN...: exit 1 and every pattern on stderr
  local what=$1; shift
  local status=0
  "$crowds" "$work/world.xml" --steps 2 --render "$work/out.png" > "$work/out.txt" 2> "$work/err.txt" || status=$?
  [ "$status" -eq 1 ] || { cat "$work/err.txt"; echo "FAIL: $what: exit $status, expected 1"; exit 1; }
  for pattern in "$@"; do
    grep -qF -- "$pattern" "$work/err.txt" || { cat "$work/err.txt"; echo "FAIL: $what: no '$pattern'"; exit 1; }
  done
  echo "ok: $what: $(head -1 "$work/err.txt")"
}
world missing_collision.png explorer.md2 explorer_skin.png
expect "a missing collision map" "world.xml:2: <ground> collision map:" "missing_collision.png"
world acropolis_collision.png missing.md2 explorer_skin.png
expect "a missing model" "world.xml:3: the type 'walker' cannot be drawn:" "missing.md2"
world acropolis_collision.png explorer.md2 missing_skin.png
expect "a missing skin" "world.xml:3: the type 'walker' cannot be drawn:" "missing_skin.png"
printf 'not an image' > "$work/broken_skin.png"
world acropolis_collision.png explorer.md2 broken_skin.png
expect "a skin that is not an image" "world.xml:3: the type 'walker' cannot be drawn:" "broken_skin.png"
echo "PASS: every asset that does not load stops stoa-crowds at the line that named it"
