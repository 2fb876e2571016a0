#!/usr/bin/env bash
# editor_texture_reload.sh STOA_EDITOR WORK_DIR
# stoa-editor in a window under Xvfb on a scene whose one material's diffuse
# map is tex.png beside the scene file: red at the start. A green tex.png
# written elsewhere and renamed over it (as editors save) must reload within a
# second ("reloaded tex.png", AssetCache through the student's assetsToReload),
# and the cube it paints must turn from red to green in the window (F12).
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot

cd "$work"
rm -f ./*.png scene.json
checker write-png tex.png 230 20 20
# A cube 2 m across seen face on, lit head-on by a white sun: its face is the texture.
cat > scene.json <<'JSON'
{
  "stoa_scene": 1,
  "ambient": [0.2, 0.2, 0.2],
  "sun": { "direction": [0, 0, -1], "color": [0.9, 0.9, 0.9] },
  "camera": { "target": [0, 1, 0], "distance": 6, "yaw": 0, "pitch": 0 },
  "materials": [
    { "name": "painted", "diffuse": [1, 1, 1], "specular": [0, 0, 0], "diffuse_map": "tex.png" }
  ],
  "objects": [
    { "id": 1, "name": "box", "mesh": "shape:cube", "material": "painted", "position": [0, 1, 0], "scale": [2, 2, 2] }
  ]
}
JSON

start_lab_window scene.json
screenshot first-frame.png
xdotool key F1
wait_for_output "^ui panel off$" "F1 did not hide the panels"
screenshot red.png
eval "$(xdotool getwindowgeometry --shell "$window")"
read -r cx cy <<< "$(checker pixel scene.json "$WIDTH" "$HEIGHT" 0 1 1)"

checker write-png tex.png.new 20 200 40
start=$(date +%s.%N)
mv tex.png.new tex.png
wait_for_output "^reloaded tex\.png$" "no \"reloaded tex.png\" after tex.png was replaced"
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
awk -v s="$seconds" 'BEGIN { exit !(s < 1.0) }' || fail "tex.png reloaded $seconds s after it changed (expected under 1 s)"
screenshot green.png
quit_with_escape
trap - EXIT

read -r r0 g0 b0 <<< "$(checker colour red.png "$cx" "$cy")"
read -r r1 g1 b1 <<< "$(checker colour green.png "$cx" "$cy")"
[ "$r0" -gt 120 ] && [ "$r0" -gt $((2 * g0)) ] && [ "$r0" -gt $((2 * b0)) ] ||
  fail "the cube at ($cx, $cy) is not red before the change: ($r0, $g0, $b0)"
[ "$g1" -gt 120 ] && [ "$g1" -gt $((2 * r1)) ] && [ "$g1" -gt $((2 * b1)) ] ||
  fail "the cube at ($cx, $cy) is not green after the reload: ($r1, $g1, $b1)"
echo "PASS: tex.png reloaded $seconds s after it was replaced; the cube went from ($r0, $g0, $b0) to ($r1, $g1, $b1)"
