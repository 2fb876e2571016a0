#!/usr/bin/env bash
# A lab's window keys do what its help says: presses KEYS (one xdotool key name
# each) in the window of PROGRAM showing CASE, then checks that the program
# printed every line of EXPECTED (lines separated by '|', each a grep -F
# pattern), that it is still running, and that Escape quits.
#
#   window_keys_switch.sh PROGRAM WORK CASE "r r v" "renderer: tiled|view: albedo"
set -euo pipefail
program=$1 work=$2 case_name=$3 keys=$4 expected=$5

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

start_lab_window --case "$case_name"
sleep 0.5
for key in $keys; do
  xdotool key --window "$window" "$key"
  sleep 0.4
  kill -0 "$pid" 2>/dev/null || fail "the program died after the key '$key'"
done
sleep 0.5
IFS='|' read -r -a lines <<< "$expected"
for line in "${lines[@]}"; do
  wait_for_output -F "$line" "after the keys '$keys' the program did not print \"$line\""
done

quit_with_escape
echo "the keys '$keys' printed: ${expected//|/; }"
