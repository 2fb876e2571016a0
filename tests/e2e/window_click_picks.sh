#!/usr/bin/env bash
# window_click_picks.sh LAB07_PROGRAM WORK_DIR
# Lab 07 in a window under Xvfb, on case pick_column's view: a click (press and
# release without moving) where the case picks must select the third column
# through the ID buffer and name it, with the distance along the student's ray
# through the BVH; a drag must pick nothing (it turns the camera). Quits on Escape.
set -euo pipefail
program=$1 work=$2

if [ "${STOA_INSIDE_XVFB:-}" != 1 ]; then
  mkdir -p "$work"
  STOA_INSIDE_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi

fail() {
  echo "FAIL: $*"
  echo "--- the program's terminal output:"
  cat "$work/stdout.txt" "$work/stderr.txt" 2>/dev/null || true
  exit 1
}

ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$program" --case pick_column > "$work/stdout.txt" 2> "$work/stderr.txt" &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT

window=
for _ in $(seq 1 100); do
  window=$(xdotool search --onlyvisible --name "Stoa lab" 2>/dev/null | head -n 1 || true)
  [ -n "$window" ] && break
  kill -0 "$pid" 2>/dev/null || fail "the program ended before its window opened"
  sleep 0.1
done
[ -n "$window" ] || fail "no window titled 'Stoa lab' appeared within 10 s"
xdotool windowfocus --sync "$window"
sleep 0.5

# The case picks pixel (228, 200) of a 512 x 384 picture; the window may have
# another size (the same 4:3 view, scaled), so click at the same fraction of it.
eval "$(xdotool getwindowgeometry --shell "$window")"
x=$((228 * WIDTH / 512)) y=$((200 * HEIGHT / 384))
xdotool mousemove --window "$window" "$x" "$y" click 1
sleep 1
kill -0 "$pid" 2>/dev/null || fail "the program died after the click"
grep -q "picked 'column 3' at [0-9.]* m" "$work/stdout.txt" ||
  fail "a click on the third column did not print \"picked 'column 3' at ... m\""

# A drag turns the camera and picks nothing.
before=$(grep -c "^picked" "$work/stdout.txt" || true)
xdotool mousemove --window "$window" 100 100 mousedown 1 mousemove --window "$window" 160 130 mouseup 1
sleep 0.5
after=$(grep -c "^picked" "$work/stdout.txt" || true)
[ "$before" = "$after" ] || fail "a drag picked something"

xdotool key Escape
for _ in $(seq 1 50); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
kill -0 "$pid" 2>/dev/null && fail "Escape did not quit"
echo "the click picked column 3 and the drag picked nothing"
