#!/usr/bin/env bash
# window_ui_panel.sh LAB_PROGRAM WORK_DIR
# A lab in a window under Xvfb: F12 saves the window, F1 shows the Dear ImGui
# panel (fed from the window's events), F12 saves it again. The second
# screenshot must show the panel in its corner and the scene elsewhere as before
# (check_ui_panel.py).
set -euo pipefail
program=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

cd "$work"
name=$(basename "$program")
rm -rf screenshots before.png after.png
start_lab_window
sleep 0.5

# save NAME COUNT: F12, then wait for the COUNT-th "saved" line, which names
# screenshots/PROGRAM-N.png under the current folder (N the first number free).
save() {
  local shot=""
  xdotool key F12
  for _ in $(seq 1 100); do
    shot=$(grep -E "^saved $work/screenshots/$name-[0-9]+\.png\$" stdout.txt | sed -n "$2p" | cut -c7- || true)
    [ -n "$shot" ] && [ -f "$shot" ] && break
    sleep 0.1
  done
  [ -n "$shot" ] && [ -f "$shot" ] || fail "F12 saved no screenshots/$name-N.png (number $2)"
  mv "$shot" "$1"
}
save before.png 1
xdotool key F1
for _ in $(seq 1 50); do
  grep -q "ui panel on" stdout.txt && break
  sleep 0.2
done
grep -q "ui panel on" stdout.txt || fail "F1 did not turn the UI panel on"
sleep 0.3   # a frame or two with the panel
save after.png 2
kill -0 "$pid" 2>/dev/null || fail "the program died with the panel on"
quit_with_escape
trap - EXIT
python3 "$here/check_ui_panel.py" before.png after.png || fail "the panel is not in the screenshot"
echo "PASS: the ImGui panel draws over the lab (screenshots in $work)"
