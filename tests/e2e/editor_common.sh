# Sourced by the stoa-editor window tests (editor_*.sh) after window_common.sh:
#   checker ARGS...         tests/e2e/editor_check.py (pixels of the scene, PNGs, saved files)
#   wait_for_count PATTERN N [FAILURE]
#                           wait up to 10 s until N lines of the program's output match
#                           the grep -E PATTERN
#   screenshot FILE         F12, wait for its "saved" line, move the picture to FILE
#                           (F12 reaches the app only while no ImGui text field has the
#                           keyboard); the first one also waits for the first frame
#   measure_frame           sets `hold`: seconds that span a few of the window's frames,
#                           measured with a screenshot's round trip (llvmpipe under load
#                           draws a frame in 0.1 s or more)
#   press_on_panel X Y      press the left button at window pixel (X, Y) of an ImGui
#                           panel, release it `hold` seconds later, wait `hold` seconds
#   click_off_panels X Y    move the mouse to window pixel (X, Y) off the panels, press
#                           the left button `hold` seconds later, release it, wait: the
#                           app gets the click, and ImGui sees it (a text field loses
#                           the keyboard)
# Dear ImGui 1.86's GLUT backend (Debian 12) keeps the buttons and keys as
# "down now" flags read once a frame: a press and release that arrive between
# two frames (xdotool click, xdotool key) never reach a widget. And the window
# asks ImGui whether it wants an event with what ImGui knew at the last frame:
# a press right after the mouse moved off a panel goes to the panel only, a
# key right after a click on a widget goes to ImGui only (F12 is lost). So
# clicks near the panels move, press, release and go on frames apart; text is
# typed, which ImGui queues.
editor_tests_dir=$(cd "$(dirname "$0")" && pwd)   # before the script changes folder
checker() { python3 "$editor_tests_dir/editor_check.py" "$@"; }

wait_for_count() {
  for _ in $(seq 1 100); do
    [ "$(grep -cE -- "$1" "$work/stdout.txt" 2>/dev/null || true)" -ge "$2" ] && return 0
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  [ "$(grep -cE -- "$1" "$work/stdout.txt" 2>/dev/null || true)" -ge "$2" ] && return 0
  fail "${3:-the program did not print $2 lines matching: $1}"
}

shots=0
screenshot() {
  shots=$((shots + 1))
  xdotool key F12
  wait_for_count "^saved .*/screenshots/[a-z0-9_-]+-[0-9]+\.png$" "$shots" "F12 saved no screenshot (number $shots)"
  mv "$(grep -E "^saved .*/screenshots/[a-z0-9_-]+-[0-9]+\.png$" "$work/stdout.txt" | sed -n "${shots}p" | cut -c7-)" "$1"
}

measure_frame() {
  local start
  start=$(date +%s.%N)
  screenshot "$work/frame-timing.png"
  hold=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { h = 2 * (b - a); printf "%.2f", h < 0.2 ? 0.2 : h }')
}

press_on_panel() {
  xdotool mousemove --window "$window" "$1" "$2" mousedown 1
  sleep "$hold"
  xdotool mouseup 1
  sleep "$hold"
}

click_off_panels() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep "$hold"
  xdotool mousedown 1
  sleep "$hold"
  xdotool mouseup 1
  sleep "$hold"
}
