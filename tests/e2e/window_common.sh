# Sourced by the window tests (window_*.sh) after they set `program` and `work`:
# runs the calling script again inside Xvfb (once), then gives it
#   fail MESSAGE            print MESSAGE and the program's output, exit 1
#   start_lab_window ARGS   start $program ARGS (output in $work/stdout.txt and
#                           stderr.txt; killed when the script exits), wait up to
#                           10 s for its window, focus it; sets `pid` and `window`
#   wait_for_output [-F] PATTERN [FAILURE]
#                           wait up to 10 s for a line matching the grep -E
#                           PATTERN (with -F: holding the text PATTERN) in the
#                           program's output; fail with FAILURE (or a message
#                           naming PATTERN) if none comes
#   quit_with_escape        press Escape, wait up to 5 s for the program to end, fail if it does not
# Wait for what the program prints rather than sleeping a fixed time: on a
# loaded machine a key or click may take seconds to reach the program.
# No window manager runs under Xvfb: the window gets the keyboard focus directly.

if [ "${STOA_INSIDE_XVFB:-}" != 1 ]; then
  mkdir -p "$work"
  STOA_INSIDE_XVFB=1 exec "$(dirname "$0")/run_in_xvfb.sh" "$0" "$@"
fi

fail() {
  echo "FAIL: $*"
  echo "--- the program's terminal output:"
  cat "$work/stdout.txt" "$work/stderr.txt" 2>/dev/null || true
  exit 1
}

start_lab_window() {
  # freeglut unloads the GLX driver at exit, which LeakSanitizer cannot tell
  # apart from Stoa's allocations (as in window_matches_headless.sh).
  ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=0" "$program" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt" &
  pid=$!
  trap 'kill "$pid" 2>/dev/null || true' EXIT
  window=
  for _ in $(seq 1 100); do
    window=$(xdotool search --onlyvisible --name "^Stoa (lab|editor|crowds) " 2>/dev/null | head -n 1 || true)
    [ -n "$window" ] && break
    kill -0 "$pid" 2>/dev/null || fail "the program ended before its window opened"
    sleep 0.1
  done
  [ -n "$window" ] || fail "no window titled 'Stoa lab ...', 'Stoa editor -- ...' or 'Stoa crowds -- ...' appeared within 10 s"
  xdotool windowfocus --sync "$window"
}

wait_for_output() {
  local mode=-E
  if [ "$1" = -F ]; then mode=-F; shift; fi
  for _ in $(seq 1 100); do
    grep -q "$mode" -- "$1" "$work/stdout.txt" 2>/dev/null && return 0
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  grep -q "$mode" -- "$1" "$work/stdout.txt" 2>/dev/null && return 0
  fail "${2:-the program did not print a line matching: $1}"
}

quit_with_escape() {
  xdotool key Escape   # to the focused window (XTEST; --window would send a synthetic event)
  for _ in $(seq 1 50); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  fail "the program did not quit on Escape"
}
