#!/usr/bin/env bash
# editor_keys_turn_scale.sh STOA_EDITOR WORK_DIR
# stoa-editor in a window under Xvfb on a copy of assets/scenes/example.json:
# a click selects the ball; `.` turns it 15 degrees about y and `=` scales it
# by 1.1, one edit each; Ctrl+S saves them (rotation y 15, scale 1.1); u twice
# takes both back, and the next save is the original file again. Then p
# switches to the deferred pipeline, whose first frame loads the meshes again
# with lab 04's tangents: the floor, whose material gets a normal map here,
# must be lit (not black, as a normal map without tangents draws it).
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot, wait_for_count

cd "$work"
rm -f ./*.png scene.json
source_scene="$editor_tests_dir/../../assets/scenes/example.json"
# The floor's material gets a normal map (a height map the editor turns into one).
python3 - "$source_scene" scene.json <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
next(m for m in scene["materials"] if m["name"] == "limestone")["normal_map"] = "acropolis/wall_height.pgm"
json.dump(scene, open(sys.argv[2], "w"), indent=2)
PY
cp scene.json original.json

start_lab_window scene.json
screenshot first-frame.png
xdotool key F1
wait_for_output "^ui panel off$" "F1 did not hide the panels"
eval "$(xdotool getwindowgeometry --shell "$window")"
read -r bx by <<< "$(checker pixel scene.json "$WIDTH" "$HEIGHT" 0 0.5 2)"   # the ball
xdotool mousemove --window "$window" "$bx" "$by" click 1
wait_for_output "^selected ball$" "a click on the ball (window pixel $bx, $by) did not select it"

xdotool key period
wait_for_output "^ball: turned to 15 degrees about y$" "'.' did not turn the ball"
xdotool key equal
wait_for_output "^ball: scaled to \(1\.100, 1\.100, 1\.100\)$" "'=' did not scale the ball"
xdotool key ctrl+s
wait_for_count "^saved .*scene\.json$" 1 "Ctrl+S did not save"
python3 - original.json scene.json <<'PY' || fail "the saved file is not the original with the ball turned and scaled"
import json, sys
original, saved = (json.load(open(f)) for f in sys.argv[1:3])
ball = next(o for o in saved["objects"] if o["name"] == "ball")
before = next(o for o in original["objects"] if o["name"] == "ball")
assert abs(ball["rotation"][1] - (before["rotation"][1] + 15)) < 1e-4, ball
assert all(abs(s - 1.1 * b) < 1e-4 for s, b in zip(ball["scale"], before["scale"])), ball
for o in saved["objects"]:
    if o["name"] != "ball":
        assert o == next(p for p in original["objects"] if p["id"] == o["id"]), o
print("saved: ball rotation", ball["rotation"], "scale", ball["scale"])
PY
xdotool key u
wait_for_count "^undo$" 1 "u did not undo"
xdotool key u
wait_for_count "^undo$" 2 "the second u did not undo"
xdotool key ctrl+s
wait_for_count "^saved .*scene\.json$" 2 "the second Ctrl+S did not save"
python3 -c "import json,sys; sys.exit(json.load(open('original.json')) != json.load(open('scene.json')))" ||
  fail "after two undos the saved file is not the original"

xdotool key p
wait_for_output "^pipeline: deferred" "p did not switch to the deferred pipeline"
screenshot deferred.png
read -r fx fy <<< "$(checker pixel scene.json "$WIDTH" "$HEIGHT" -4 0 4)"   # the floor, left of the ball
read -r r g b <<< "$(checker colour deferred.png "$fx" "$fy")"
echo "the floor in the deferred pipeline at ($fx, $fy): ($r, $g, $b)"
[ $((r + g + b)) -gt 60 ] || fail "the normal-mapped floor is black in the deferred pipeline (tangents missing?)"
if grep -E "normal maps off|needs" "$work/stdout.txt"; then fail "a pass of the deferred pipeline is missing (above)"; fi
xdotool key u   # the switch was an edit: undone, nothing is left unsaved
wait_for_count "^undo$" 3 "u did not undo the switch of pipeline"
quit_with_escape
echo "turned, scaled, saved, undone; the deferred pipeline draws the normal-mapped floor"
