#!/usr/bin/env bash
# window_editor_click.sh LAB11_PROGRAM WORK_DIR click|drag
# Lab 11 in a window under Xvfb, on case select_column (its script selects the
# column at the first frame):
#   click  a click (press and release without moving) on the crate selects it
#          through the stencil pick ("selected crate"), a click on the empty sky
#          selects nothing ("selected nothing");
#   drag   after the crate is clicked, a press on its gizmo's x arrow, four
#          mouse moves along it and a release move the crate along x so that the
#          point grabbed stays under the mouse ("moved crate to (x, 0.500, 0.900)",
#          x within 0.02 of where the mouse's last ray passes the axis closest);
#          the whole drag is one undo step (u: "undo", u again: "nothing to undo").
# Quits on Escape.
#
# The pixels come from the case's camera (orbit about (0, 0.8, 0), distance 10,
# yaw 20, pitch 28, the default 50 degree vertical field of view) at the
# window's size: the window may have another aspect ratio than the case's
# 480 x 360 picture, which changes the horizontal field of view, so pixels of
# the picture cannot simply be scaled.
set -euo pipefail
program=$1 work=$2 mode=$3

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output

start_lab_window --case select_column
wait_for_output "^selected column$" "the case's script did not select the column at the first frame"
eval "$(xdotool getwindowgeometry --shell "$window")"

# camera MODE ARGS: the case's camera at WIDTH x HEIGHT, in awk.
#   camera pixel X Y Z            the window pixel (x from the left, y down) where the world point shows
#   camera axis X Y Z DX DY DZ PX PY
#                                 the parameter s of the point X Y Z + s * (DX DY DZ) (unit) closest to
#                                 the mouse ray through window pixel (PX, PY), as the app casts it
camera() {
  awk -v w="$WIDTH" -v h="$HEIGHT" -v mode="$1" -v args="${*:2}" '
    function dot(a, b) { return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] }
    BEGIN {
      pi = atan2(0, -1); split(args, v, " ")
      yaw = 20 * pi / 180; pitch = 28 * pi / 180; distance = 10
      f = 1 / (sin(25 * pi / 180) / cos(25 * pi / 180)); aspect = w / h
      target[1] = 0; target[2] = 0.8; target[3] = 0
      back[1] = cos(pitch) * sin(yaw); back[2] = sin(pitch); back[3] = cos(pitch) * cos(yaw)
      for (i = 1; i <= 3; ++i) eye[i] = target[i] + distance * back[i]
      # right = normalize(up x back) with up = (0, 1, 0); trueUp = back x right
      n = sqrt(back[3] * back[3] + back[1] * back[1])
      right[1] = back[3] / n; right[2] = 0; right[3] = -back[1] / n
      up[1] = back[2] * right[3] - back[3] * right[2]
      up[2] = back[3] * right[1] - back[1] * right[3]
      up[3] = back[1] * right[2] - back[2] * right[1]
      if (mode == "pixel") {
        for (i = 1; i <= 3; ++i) p[i] = v[i] - eye[i]
        x = dot(right, p); y = dot(up, p); z = dot(back, p)
        printf "%d %d\n", ((f / aspect * x / -z) + 1) / 2 * w, (1 - f * y / -z) / 2 * h
      } else {
        # The ray from the eye through the pixel centre, in world space, unit.
        nx = (v[7] + 0.5) / w * 2 - 1; ny = 1 - (v[8] + 0.5) / h * 2
        for (i = 1; i <= 3; ++i) d[i] = nx * aspect / f * right[i] + ny / f * up[i] - back[i]
        l = sqrt(dot(d, d)); for (i = 1; i <= 3; ++i) d[i] /= l
        for (i = 1; i <= 3; ++i) { e[i] = v[i + 3]; q[i] = eye[i] - v[i] }
        # (q + t d - s e) is perpendicular to d and e:  s = (q.e - b q.d) / (1 - b^2), b = d.e
        b = dot(d, e)
        printf "%.6f\n", (dot(q, e) - b * dot(q, d)) / (1 - b * b)
      }
    }'
}

# The crate stands at (0.4, 0.5, 0.9), one unit across.
read -r cx cy <<< "$(camera pixel 0.4 0.5 0.9)"
xdotool mousemove --window "$window" "$cx" "$cy" click 1
wait_for_output "^selected crate$" "a click on the crate (window pixel $cx, $cy) did not print \"selected crate\""
kill -0 "$pid" 2>/dev/null || fail "the program died after the click"

if [ "$mode" = click ]; then
  # The sky: the window's top-left corner shows nothing within the pick radius.
  xdotool mousemove --window "$window" 12 12 click 1
  wait_for_output "^selected nothing$" "a click on the sky did not print \"selected nothing\""
  quit_with_escape
  echo "a click on the crate selected it, a click on the sky nothing"
  exit 0
fi

# The gizmo's x arrow runs from the crate's centre to 1.1 units along +x (gizmoLength:
# 0.6 + half the largest scale). Press 60% along it, then move by another 60% of it
# in four steps, and release.
read -r tx ty <<< "$(camera pixel 1.5 0.5 0.9)"
px=$(( cx + (tx - cx) * 6 / 10 )) py=$(( cy + (ty - cy) * 6 / 10 ))
xdotool mousemove --window "$window" "$px" "$py" mousedown 1
for step in 1 2 3 4; do
  mx=$(( px + (tx - cx) * 6 * step / 40 )) my=$(( py + (ty - cy) * 6 * step / 40 ))
  xdotool mousemove --window "$window" "$mx" "$my"
  sleep 0.05
done
xdotool mouseup 1
wait_for_output "^moved crate to " "a drag along the crate's x arrow (from $px, $py to $mx, $my) did not print \"moved crate to ...\""
moved=$(grep -m1 "^moved crate to " "$work/stdout.txt")
pressed=$(camera axis 0.4 0.5 0.9 1 0 0 "$px" "$py")
released=$(camera axis 0.4 0.5 0.9 1 0 0 "$mx" "$my")
expected=$(awk -v a="$pressed" -v b="$released" 'BEGIN { printf "%.3f", 0.4 + b - a }')
x=$(sed -E 's/^moved crate to \((-?[0-9.]+), 0\.500, 0\.900\)$/\1/' <<< "$moved")
[ "$x" != "$moved" ] || fail "the crate left its x axis or the line reads otherwise: \"$moved\" (expected y 0.500, z 0.900)"
awk -v x="$x" -v e="$expected" 'BEGIN { exit !(x - e < 0.02 && e - x < 0.02 && e > 0.6) }' ||
  fail "\"$moved\": the point grabbed did not stay under the mouse (x should be $expected)"

# The drag's moves are one edit: one undo takes it back, a second has nothing left.
xdotool key u
wait_for_output "^undo$" "u after the drag did not print \"undo\""
xdotool key u
wait_for_output -F "nothing to undo" "a second u printed no \"nothing to undo\": the drag was more than one edit"

quit_with_escape
echo "the drag along x: \"$moved\" (expected x $expected), one undo step"
