#!/usr/bin/env bash
# crowds_window.sh STOA_CROWDS COMPARE_TOOL WORK_DIR WORLD...
# stoa-crowds runs each example world in a window under Xvfb: 90 steps, the
# first frame saved (--screenshot), which must match the same world rendered
# headless on both backends within the grader's tolerance. Then the window is
# run with a bad world file and must say which file and line is wrong.
set -euo pipefail
program=$1 compare=$2 work=$3
shift 3
mkdir -p "$work"
for world in "$@"; do
  name=$(basename "$world" .xml)
  window="$work/$name.window.png"
  rm -f "$window"
  ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" \
    "$(dirname "$0")/run_in_xvfb.sh" "$program" "$world" --steps 90 --screenshot "$window"
  [ -s "$window" ] || { echo "FAIL: stoa-crowds $world saved no screenshot"; exit 1; }
  for backend in osmesa egl; do
    headless="$work/$name.$backend.png"
    "$program" "$world" --steps 90 --render "$headless" --backend "$backend"
    "$compare" "$window" "$headless"
  done
  echo "$name: the window matches both headless backends"
done

# A world whose <spawn> names a type nobody defined.
bad="$work/bad_world.xml"
cat > "$bad" <<'XML'
<world seed="1">
  <ground collision="BAD_MAP" min="-5 -5" max="5 5" scenery="none"/>
  <spawn type="dragon" count="3" x="0" z="0" radius="1"/>
</world>
XML
set +e
output=$("$program" "$bad" --steps 1 --render "$work/bad.png" 2>&1)
status=$?
set -e
if [ "$status" -eq 0 ] || ! grep -q "bad_world.xml:3" <<< "$output"; then
  echo "FAIL: a bad world file should fail naming bad_world.xml:3; status $status, output:"
  echo "$output"
  exit 1
fi
echo "a bad world file is named with its line: $(grep -m1 'bad_world.xml' <<< "$output")"
