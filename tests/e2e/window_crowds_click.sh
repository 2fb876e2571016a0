#!/usr/bin/env bash
# window_crowds_click.sh STOA_CROWDS WORK_DIR
# stoa-crowds in a window on the Mars explorers, paused at once (space): a
# click on the base, where the robots start, selects one of them and prints
# its type, state and place; a click on empty ground far from everyone says so.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

start_lab_window mars_explorers.xml
xdotool key space
wait_for_output "^paused at" "space did not pause the simulation"

# The top view fits the 30 m footprint around (0, 0): +x to the right, +z down.
# The base is at (0, 9); the far corner (-13, -13) is empty ground.
eval "$(xdotool getwindowgeometry --shell "$window")"
half=$(awk -v w="$WIDTH" -v h="$HEIGHT" 'BEGIN { a = w / h; m = 15 / a; if (m < 15) m = 15; print m * 1.02 }')
pixel() {   # x z -> "column row"
  awk -v w="$WIDTH" -v h="$HEIGHT" -v m="$half" -v x="$1" -v z="$2" \
    'BEGIN { a = w / h; printf "%d %d", w / 2 + x / (m * a) * w / 2, h / 2 + z / m * h / 2 }'
}
read -r bx by <<< "$(pixel 0 9)"
xdotool mousemove --window "$window" "$bx" "$by" click 1
wait_for_output "^agent [0-9]+ \(explorer\): search at \(-?[0-9.]+, [0-9.]+\)" \
  "a click on the base (pixel $bx, $by) selected no explorer"
read -r ex ey <<< "$(pixel -13 -13)"
xdotool mousemove --window "$window" "$ex" "$ey" click 1
wait_for_output "^no agent there" "a click on empty ground did not say \"no agent there\""

quit_with_escape
echo "a click on the base selected: $(grep -m1 '^agent' "$work/stdout.txt")"
