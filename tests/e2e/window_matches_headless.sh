#!/usr/bin/env bash
# window_matches_headless.sh LAB_PROGRAM CASE COMPARE_TOOL WORK_DIR
# Renders CASE in the freeglut window under Xvfb and headless on both backends,
# and checks that the three images agree within the grader's tolerance.
set -euo pipefail
program=$1 case_name=$2 compare=$3 work=$4
mkdir -p "$work"
window="$work/$case_name.window.png"
rm -f "$window"
# freeglut unloads the GLX driver when the window closes, so in a sanitizer build
# LeakSanitizer cannot tell the driver's allocations from Stoa's; the headless
# runs below check the same lab code with leak detection on.
ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" \
  "$(dirname "$0")/run_in_xvfb.sh" "$program" --case "$case_name" --screenshot "$window"
for backend in osmesa egl; do
  headless="$work/$case_name.$backend.png"
  "$program" --render "$case_name" --output "$headless" --backend "$backend"
  "$compare" "$window" "$headless"
done
