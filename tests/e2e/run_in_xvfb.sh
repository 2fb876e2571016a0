#!/usr/bin/env bash
# run_in_xvfb.sh COMMAND [ARGS...]
# Runs COMMAND with DISPLAY on a fresh Xvfb (one 1280x1024x24 screen) and exits
# with its status, after stopping the server and waiting until it is gone.
#
# -noreset: by default an X server resets when its last client disconnects and
# refuses connections meanwhile. The window scripts poll with xdotool while the
# lab starts, so a lab that opens its display late (lab 07 loads its scene
# first) could arrive during such a reset: "failed to open display", about one
# run in eight under xvfb-run. -displayfd: the server picks a free display
# number itself (lock file and sockets, where xvfb-run -a looks at the lock
# files only) and writes it once it accepts connections.
set -uo pipefail
if [ $# -eq 0 ]; then
  echo "usage: run_in_xvfb.sh COMMAND [ARGS...]" >&2
  exit 2
fi
dir=$(mktemp -d)
Xvfb -displayfd 3 -noreset -screen 0 1280x1024x24 -nolisten tcp 3> "$dir/display" 2> "$dir/xvfb.log" &
xvfb=$!
stop_server() {
  kill "$xvfb" 2>/dev/null && wait "$xvfb" 2>/dev/null
  rm -rf "$dir"
}
trap stop_server EXIT
for _ in $(seq 1 100); do
  [ -s "$dir/display" ] && break
  if ! kill -0 "$xvfb" 2>/dev/null; then
    echo "run_in_xvfb.sh: Xvfb did not start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 1
  fi
  sleep 0.1
done
display=$(head -n 1 "$dir/display")
if [ -z "$display" ]; then
  echo "run_in_xvfb.sh: Xvfb did not report a display within 10 s:" >&2
  cat "$dir/xvfb.log" >&2
  exit 1
fi
DISPLAY=":$display" "$@"
