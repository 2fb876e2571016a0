#!/usr/bin/env bash
# window_events.sh PROBE_PROGRAM WORK_DIR
# The event probe (event_probe.cpp, a Lab that prints what it receives) in a
# window under Xvfb: keys down and up (a letter, F5, an arrow, Shift+b), mouse
# buttons, the wheel and a resize must each reach the lab's handleEvent(), and
# its update step must run; a key the lab takes (H) the app leaves alone.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

start_lab_window
sleep 0.3
xdotool key --delay 100 a F5 Left shift+b h
xdotool mousemove --window "$window" 100 80
sleep 0.2
xdotool click --delay 100 3
xdotool click --delay 100 1
xdotool click --delay 100 5
xdotool windowsize "$window" 400 300
sleep 0.5

# Waits up to 10 s for the line (a loaded machine may be slow to deliver).
expect() {
  for _ in $(seq 1 50); do
    grep -q -- "$1" "$work/stdout.txt" && return 0
    sleep 0.2
  done
  fail "the lab did not receive: $1"
}
expect "^event KeyDown a$"
expect "^event Text a$"
expect "^event KeyUp a$"
expect "^event KeyDown F5$"
expect "^event KeyUp F5$"
expect "^event KeyDown Left$"
expect "^event KeyUp Left$"
expect "^event KeyDown LeftShift"
expect "^event Text B +shift$"
expect "^event KeyDown b +shift$"
expect "^event MouseDown Right at 100,80"
expect "^event MouseUp Right at 100,80"
expect "^event MouseDown Left at 100,80"
expect "^event MouseUp Left"
expect "^event Wheel -1"
expect "^event MouseMove"
expect "^event Resize 400x300"
expect "^update 0.0"
expect "^event KeyDown h$"
[ "$(grep -c "Shaders reload by themselves" "$work/stdout.txt")" -eq 1 ] ||
  fail "the app printed its help for H, which the lab took"
kill -0 "$pid" 2>/dev/null || fail "the program died"

quit_with_escape
wait "$pid" || fail "the program's exit status after Escape was not 0"
trap - EXIT
echo "PASS: keys down and up, special keys, modifiers, text, mouse buttons, the wheel and a resize reached the lab"
