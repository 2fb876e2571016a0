#!/usr/bin/env bash
# window_survives_stubs.sh STUB_PROGRAM WORK_DIR
# Lab 01 built from the stubs, in a window under Xvfb: jump to case 4 (key 4,
# first_person_walk, which makes the first-person camera the active one) and
# hold W, which calls the stub FirstPersonCamera::move() from the window's
# update step. The program must
# still be running afterwards, have said "not implemented: FirstPersonCamera::move()"
# in the terminal, and quit cleanly on Escape.
set -euo pipefail
program=$1 work=$2

if [ "${STOA_INSIDE_XVFB:-}" != 1 ]; then
  mkdir -p "$work"
  STOA_INSIDE_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi

fail() {
  echo "FAIL: $*"
  echo "--- the program's terminal output:"
  cat "$work/stdout.txt" "$work/stderr.txt" 2>/dev/null || true
  exit 1
}

# freeglut unloads the GLX driver at exit, which LeakSanitizer cannot tell apart
# from Stoa's allocations (as in window_matches_headless.sh).
ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$program" > "$work/stdout.txt" 2> "$work/stderr.txt" &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT

window=
for _ in $(seq 1 100); do
  window=$(xdotool search --onlyvisible --name "Stoa lab" 2>/dev/null | head -n 1 || true)
  [ -n "$window" ] && break
  kill -0 "$pid" 2>/dev/null || fail "the program ended before its window opened"
  sleep 0.1
done
[ -n "$window" ] || fail "no window titled 'Stoa lab' appeared within 10 s"

# No window manager runs under Xvfb: give the window the keyboard focus directly.
xdotool windowfocus --sync "$window"
sleep 0.3
xdotool key --delay 100 4
xdotool keydown w
sleep 1
xdotool keyup w
sleep 0.5

kill -0 "$pid" 2>/dev/null || fail "the program died while W was held"
grep -q "not implemented: FirstPersonCamera::move()" "$work/stderr.txt" ||
  fail "the terminal does not say 'not implemented: FirstPersonCamera::move()'"
if [ "$(grep -c "not implemented: FirstPersonCamera::move()" "$work/stderr.txt")" -ne 1 ]; then
  fail "the same problem was printed more than once"
fi
title=$(xdotool getwindowname "$window")
case $title in
  *"FirstPersonCamera::move()"*) ;;
  *) fail "the window title does not name the stub: '$title'" ;;
esac

xdotool key Escape
status=0
for _ in $(seq 1 50); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
kill -0 "$pid" 2>/dev/null && fail "the program did not quit on Escape"
wait "$pid" || status=$?
trap - EXIT
echo "window title: $title"
echo "program exit status after Escape: $status"
echo "PASS: the window kept running after a stub threw in an input callback"
