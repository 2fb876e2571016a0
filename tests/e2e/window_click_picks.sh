#!/usr/bin/env bash
# window_click_picks.sh LAB07_PROGRAM WORK_DIR
# Lab 07 in a window under Xvfb, on case pick_column's view: a click (press and
# release without moving) where the case picks must select the third column
# through the ID buffer and name it, with the distance along the student's ray
# through the BVH; a drag must pick nothing (it turns the camera). Quits on Escape.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

start_lab_window --case pick_column
sleep 0.5

# The case picks pixel (228, 200) of a 512 x 384 picture; the window may have
# another size (the same 4:3 view, scaled), so click at the same fraction of it.
eval "$(xdotool getwindowgeometry --shell "$window")"
x=$((228 * WIDTH / 512)) y=$((200 * HEIGHT / 384))
xdotool mousemove --window "$window" "$x" "$y" click 1
wait_for_output "picked 'column 3' at [0-9.]* m" \
  "a click on the third column did not print \"picked 'column 3' at ... m\""
kill -0 "$pid" 2>/dev/null || fail "the program died after the click"

# A drag turns the camera and picks nothing. (A click prints the ray's pick at
# once and the ID buffer's a frame later; count the ray's, "picked ... at".)
before=$(grep -cE "^picked .* at " "$work/stdout.txt" || true)
xdotool mousemove --window "$window" 100 100 mousedown 1 mousemove --window "$window" 160 130 mouseup 1
sleep 0.5
after=$(grep -cE "^picked .* at " "$work/stdout.txt" || true)
[ "$before" = "$after" ] || fail "a drag picked something"

quit_with_escape
echo "the click picked column 3 and the drag picked nothing"
