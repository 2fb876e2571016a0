#!/usr/bin/env bash
# editor_edit_save_reload.sh STOA_EDITOR COMPARE_TOOL WORK_DIR
# stoa-editor in a window under Xvfb on a copy of assets/scenes/example.json
# (its textures and models resolve from assets/, as the copy's folder has none):
# with the panels hidden (F1), a click on the ball selects it ("selected ball"),
# a drag on its gizmo's x arrow moves it, u and r undo and redo the drag, Ctrl+S
# saves. The saved file differs from the original only in the ball's x position
# (by more than 0.1). A click on the sky deselects, F12 saves the window; the
# saved file opened again draws the same picture (compare_images).
set -euo pipefail
program=$1 compare=$2 work=$3

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot, wait_for_count

cd "$work"
rm -f ./*.png scene.json
source_scene="$editor_tests_dir/../../assets/scenes/example.json"
cp "$source_scene" scene.json
cp "$source_scene" original.json

start_lab_window scene.json
screenshot first-frame.png   # the first frame is drawn: the panels are on
xdotool key F1
wait_for_output "^ui panel off$" "F1 did not hide the panels"
eval "$(xdotool getwindowgeometry --shell "$window")"

# The ball: a sphere 1 m across at (0, 0.5, 2).
read -r bx by <<< "$(checker pixel scene.json "$WIDTH" "$HEIGHT" 0 0.5 2)"
xdotool mousemove --window "$window" "$bx" "$by" click 1
wait_for_output "^selected ball$" "a click on the ball (window pixel $bx, $by) did not print \"selected ball\""

# Its gizmo's x arrow runs from its centre to 1.1 m along +x (0.6 + half its
# largest scale). Press 85% along it, move another arrow's length along it in
# four steps, release.
read -r tx ty <<< "$(checker pixel scene.json "$WIDTH" "$HEIGHT" 1.1 0.5 2)"
px=$(( bx + (tx - bx) * 85 / 100 )) py=$(( by + (ty - by) * 85 / 100 ))
xdotool mousemove --window "$window" "$px" "$py" mousedown 1
for step in 1 2 3 4; do
  xdotool mousemove --window "$window" $(( px + (tx - bx) * step / 4 )) $(( py + (ty - by) * step / 4 ))
  sleep 0.05
done
xdotool mouseup 1

# The drag is one edit: u takes it back, r does it again (in the order sent).
xdotool key u
wait_for_output "^undo$" "u after the drag did not print \"undo\" (did the drag from $px, $py move the ball?)"
xdotool key r
wait_for_output "^redo$" "r after the undo did not print \"redo\""
xdotool key ctrl+s
wait_for_output "^saved .*scene\.json$" "Ctrl+S did not print \"saved .../scene.json\""
moved=$(checker moved original.json scene.json ball) ||
  fail "the saved scene.json is not the original with the ball moved along x: $moved"

# A click on the sky (the top of the window, above the floor's far edge) selects nothing.
xdotool mousemove --window "$window" $(( WIDTH * 3 / 4 )) 8 click 1
wait_for_output "^selected nothing$" "a click on the sky did not print \"selected nothing\""
screenshot edited.png
quit_with_escape

# The saved file, opened again, draws what the editor showed.
shots=0
start_lab_window scene.json
screenshot reopened-first-frame.png
xdotool key F1
wait_for_output "^ui panel off$" "F1 did not hide the panels in the reopened scene"
screenshot reopened.png
quit_with_escape
trap - EXIT
"$compare" reopened.png edited.png || fail "the reopened scene does not draw as the edited one (edited.png, reopened.png in $work)"
echo "PASS: $moved, saved; the saved file draws as the editor did"
