#!/usr/bin/env bash
# web_window.sh LAB_PROGRAM WORK_DIR
# The dev container's way to see a lab (tools/web-window.sh), tried as a student
# would: the lab runs under the script, headless Chromium opens the printed
# noVNC address, connects, types h (the lab prints its keys) and F12 (the lab
# saves its own screenshot), and the browser's screenshot of the window must
# show the lab's own picture. Then the script is stopped as Ctrl+C stops it,
# and nothing it started may be left running.
# Skipped (exit 77) on a machine without Chromium, x11vnc, websockify or noVNC.
set -euo pipefail
program=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
for tool in chromium x11vnc websockify Xvfb; do
  command -v "$tool" >/dev/null 2>&1 || { echo "SKIP: no $tool (.ci/install-deps.sh installs it)"; exit 77; }
done
[ -f /usr/share/novnc/vnc.html ] || { echo "SKIP: no noVNC in /usr/share/novnc (Debian package novnc)"; exit 77; }

rm -rf "$work"
mkdir -p "$work"
cd "$work"   # F12 saves in screenshots/ here
# A free port: the kernel's pick for a socket bound to port 0.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
setsid "$root/tools/web-window.sh" --port "$port" "$program" --case sun > stdout.txt 2> stderr.txt &
script=$!
stop() { kill -TERM "$script" 2>/dev/null || true; }
trap stop EXIT
fail() {
  echo "FAIL: $*"
  echo "--- web-window.sh and the lab said:"
  cat stderr.txt stdout.txt
  exit 1
}

address=
for _ in $(seq 1 200); do
  address=$(grep -o 'http://localhost:[0-9]*/vnc.html[^ ]*' stderr.txt || true)
  [ -n "$address" ] && break
  kill -0 "$script" 2>/dev/null || fail "web-window.sh ended before it printed an address"
  sleep 0.1
done
[ -n "$address" ] || fail "web-window.sh printed no address within 20 s"
echo "web-window.sh says: open $address"
# The address as printed, but resize=off (not scale) and quality=9, so that the
# page shows the screen pixel for pixel, for the comparison.
python3 "$here/novnc_browser.py" "${address/resize=scale/resize=off}&quality=9" --screenshot browser.png \
  --key h --key F12 --compare-with "screenshots/$(basename "$program")-1.png" || fail "the browser did not see the lab"
for _ in $(seq 1 50); do
  grep -q "1..9         jump to a graded case's view" stdout.txt && break
  sleep 0.1
done
grep -q "1..9         jump to a graded case's view" stdout.txt || fail "h typed in the browser did not reach the lab (no key list printed)"
echo "h typed in the browser: the lab printed its keys"

# Ctrl+C in the terminal: everything the script started stops with it.
kill -INT -- "-$script"
for _ in $(seq 1 100); do
  kill -0 "$script" 2>/dev/null || break
  sleep 0.1
done
kill -0 "$script" 2>/dev/null && fail "web-window.sh still runs 10 s after Ctrl+C"
left=$(pgrep -s "$script" -a || true)
[ -z "$left" ] || fail "left running after Ctrl+C: $left"
trap - EXIT
echo "PASS: the lab's window seen and driven in a browser through noVNC; all stopped on Ctrl+C"
