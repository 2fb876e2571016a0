#!/usr/bin/env bash
# editor_shader_error_keeps_drawing.sh STOA_EDITOR WORK_DIR
# stoa-editor in a window under Xvfb on assets/scenes/example.json, the panels
# on: a click selects the ball, the Shader panel opens (its title bar's arrow)
# on the ball's material's shader, editor/lit.frag. "oops;" typed on its blank
# line 6 must fail to compile at that line ("shader editor/lit: .../lit.frag:6:
# ..."), and the scene must go on drawing with the last program that compiled
# (F12: the ball is lit). "//" typed before it comments it out: "compiled".
#
# The panels' places are those drawUi() gives them at the start (editor_app.hpp,
# drawShaderPanel) in Dear ImGui's default style: 13-pixel font and lines, title
# bars 19 pixels high, windows padded by 8 pixels, text fields by 4 x 3.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot, measure_frame, press_on_panel

cd "$work"
rm -f ./*.png
scene="$editor_tests_dir/../../assets/scenes/example.json"

start_lab_window "$scene"
screenshot first-frame.png
measure_frame
eval "$(xdotool getwindowgeometry --shell "$window")"

read -r bx by <<< "$(checker pixel "$scene" "$WIDTH" "$HEIGHT" 0 0.5 2)"
click_off_panels "$bx" "$by"
wait_for_output "^selected ball$" "a click on the ball (window pixel $bx, $by) did not print \"selected ball\""

# The Shader panel starts collapsed at (WIDTH - 470, 220): open it with its arrow.
panel_x=$((WIDTH - 470)) panel_y=220
press_on_panel $((panel_x + 10)) $((panel_y + 9))
# Its text field starts below the title bar and the line naming the file; the
# first column of line 6 is 4 pixels in, 3 + 5 * 13 pixels down (the line's middle: + 6).
text_x=$((panel_x + 8 + 4 + 1)) line6_y=$((panel_y + 19 + 8 + 13 + 4 + 3 + 5 * 13 + 6))
press_on_panel "$text_x" "$line6_y"
xdotool type --delay 80 "oops;"
wait_for_output "^shader editor/lit: " "typing \"oops;\" into the shader panel gave no \"shader editor/lit: ...\" line"
error=$(grep -m1 "^shader editor/lit: " "$work/stdout.txt")
line=$(sed -nE 's/^shader editor\/lit: .*lit\.frag:([0-9]+): .*/\1/p' <<< "$error")
[ "$line" = 6 ] || fail "the error should name lit.frag:6, where \"oops;\" was typed: \"$error\""

# A click on the sky leaves the text field (so that F12 reaches the app) and selects nothing.
click_off_panels $((WIDTH / 2)) 5
wait_for_output "^selected nothing$" "a click on the sky did not print \"selected nothing\""
screenshot broken.png
read -r r g b <<< "$(checker colour broken.png "$bx" "$by")"
[ $((r + g + b)) -gt 300 ] ||
  fail "with the broken shader the ball at ($bx, $by) is not drawn lit: ($r, $g, $b) (broken.png in $work)"

# "//" before "oops;" comments it out: the text compiles again.
press_on_panel "$text_x" "$line6_y"
xdotool type --delay 80 "//"
wait_for_output "^shader editor/lit: compiled$" "commenting out \"oops;\" did not print \"shader editor/lit: compiled\""
quit_with_escape
trap - EXIT
echo "PASS: the error named line 6 ($(grep -m1 -o "lit\.frag:6: error.*" "$work/stdout.txt" || echo "$error")); the ball stayed lit ($r, $g, $b); the fixed text compiled"
