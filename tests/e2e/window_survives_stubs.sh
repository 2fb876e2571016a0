#!/usr/bin/env bash
# window_survives_stubs.sh STUB_PROGRAM WORK_DIR
# Lab 01 built from the stubs, in a window under Xvfb: jump to case 4 (key 4,
# first_person_walk, which makes the first-person camera the active one) and
# hold W, which calls the stub move(FirstPersonState) from the window's
# update step. The program must
# still be running afterwards, have said "not implemented: move(FirstPersonState)"
# in the terminal, and quit cleanly on Escape.
set -euo pipefail
program=$1 work=$2

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window

start_lab_window
sleep 0.3
xdotool key --delay 100 4
xdotool keydown w
sleep 1
xdotool keyup w
sleep 0.5

kill -0 "$pid" 2>/dev/null || fail "the program died while W was held"
grep -q "not implemented: move(FirstPersonState)" "$work/stderr.txt" ||
  fail "the terminal does not say 'not implemented: move(FirstPersonState)'"
if [ "$(grep -c "not implemented: move(FirstPersonState)" "$work/stderr.txt")" -ne 1 ]; then
  fail "the same problem was printed more than once"
fi
title=$(xdotool getwindowname "$window")
case $title in
  *"move(FirstPersonState)"*) ;;
  *) fail "the window title does not name the stub: '$title'" ;;
esac

quit_with_escape
status=0
wait "$pid" || status=$?
trap - EXIT
echo "window title: $title"
echo "program exit status after Escape: $status"
echo "PASS: the window kept running after a stub threw in an input callback"
