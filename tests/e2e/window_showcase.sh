#!/usr/bin/env bash
# window_showcase.sh STOA_EDITOR WORK_DIR
# `stoa-editor --scene showcase` in a window under Xvfb (docs/showcase.md): the
# window opens with the renderer panel's deferred pipeline, F1 hides the
# panels, F12 saves a frame with the sky at the top and the point lights'
# coloured pools on the ground, and the crowd walks: two frames seconds apart
# differ where the agents are. b throws lab 07's ball, which bounces off the
# scene's BVH and throws sparks ("sparks at ..."). Escape quits.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot

cd "$work"
rm -f ./*.png
start_lab_window --scene showcase --size 480x270
screenshot first-frame.png
xdotool key F1
wait_for_output "^ui panel off$" "F1 did not hide the panels"
screenshot showcase.png
checker showcase showcase.png || fail "the window does not look like the showcase (above)"
sleep 2
screenshot later.png
percent=$(checker differ showcase.png later.png)
echo "two seconds later $percent % of the pixels changed"
awk "BEGIN { exit !($percent >= 0.5) }" || fail "nothing moved in two seconds: the crowd and the lights stand still"
xdotool key b
wait_for_output "^ball thrown$" "b threw no ball"
wait_for_output "^sparks at " "the ball hit nothing within 10 s: no sparks (lab 07's bounce)"
if grep -E "needs|normal maps off" "$work/stdout.txt"; then fail "a pass of the showcase is missing (above)"; fi
quit_with_escape
echo "the showcase ran in a window"
