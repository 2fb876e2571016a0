#!/usr/bin/env bash
# web-window.sh: shows a Stoa program's window in a web browser, for machines
# with no display of their own (the dev container, a server, Codespaces).
#
#   tools/web-window.sh [--port PORT] [--size WIDTHxHEIGHT] [--listen ADDRESS] PROGRAM [ARGS...]
#   tools/web-window.sh build/bin/lab02_blinn_phong
#   tools/web-window.sh build/bin/stoa-editor assets/scenes/temple.json
#
# It starts a virtual display (Xvfb), a VNC server on it (x11vnc, on this
# machine only) and noVNC (websockify serving Debian's noVNC pages), prints the
# address to open, then runs PROGRAM on that display. The page shows the
# display and sends it your keys and clicks. When PROGRAM ends, or on Ctrl+C,
# everything it started stops.
#
#   --port PORT        the web page's port (default 6080, or $STOA_WEB_PORT)
#   --size WxH         the virtual screen (default 1024x768); the window sits at its top left
#   --listen ADDRESS   where the page is served (default 127.0.0.1, this machine only;
#                      0.0.0.0 for a Docker port published with -p). Nobody is asked for
#                      a password: serve on 0.0.0.0 only inside a container or a trusted network.
#
# Needs Debian's xvfb, x11vnc, websockify and novnc (.ci/install-deps.sh installs them).
set -euo pipefail

usage() {
  echo "usage: tools/web-window.sh [--port PORT] [--size WIDTHxHEIGHT] [--listen ADDRESS] PROGRAM [ARGS...]" >&2
  exit 2
}

port=${STOA_WEB_PORT:-6080}
size=1024x768
listen=127.0.0.1
while [ $# -gt 0 ]; do
  case $1 in
    --port) [ $# -ge 2 ] || usage; port=$2; shift 2 ;;
    --size) [ $# -ge 2 ] || usage; size=$2; shift 2 ;;
    --listen) [ $# -ge 2 ] || usage; listen=$2; shift 2 ;;
    --help|-h) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --) shift; break ;;
    -*) echo "web-window.sh: unknown option '$1'" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || usage
if ! [[ $port =~ ^[0-9]+$ ]] || (( port < 1024 || port > 65535 )); then
  echo "web-window.sh: --port '$port' is not a port from 1024 to 65535" >&2
  exit 2
fi
if ! [[ $size =~ ^[0-9]+x[0-9]+$ ]]; then
  echo "web-window.sh: --size '$size' is not WIDTHxHEIGHT (such as 1024x768)" >&2
  exit 2
fi
program=$1
if ! command -v "$program" >/dev/null 2>&1; then
  echo "web-window.sh: '$program' is not a program (build first: cmake --build build; the programs are in build/bin/)" >&2
  exit 2
fi

novnc=${STOA_NOVNC_DIR:-/usr/share/novnc}
missing=()
for tool in Xvfb x11vnc websockify; do command -v "$tool" >/dev/null 2>&1 || missing+=("$tool"); done
[ -f "$novnc/vnc.html" ] || missing+=("noVNC's pages in $novnc")
if [ ${#missing[@]} -gt 0 ]; then
  echo "web-window.sh: missing ${missing[*]}; on Debian or Ubuntu: sudo apt-get install xvfb x11vnc websockify novnc" >&2
  exit 1
fi
if (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then
  echo "web-window.sh: port $port is taken (another web-window.sh?); choose another with --port" >&2
  exit 1
fi

dir=$(mktemp -d)
pids=()
stop_all() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$dir"
}
trap stop_all EXIT
trap 'exit 130' INT TERM

# -displayfd: Xvfb picks a free display and writes its number once it accepts
# connections; -noreset keeps it up between clients (as tests/e2e/run_in_xvfb.sh).
Xvfb -displayfd 3 -noreset -screen 0 "${size}x24" -nolisten tcp 3> "$dir/display" 2> "$dir/xvfb.log" &
pids+=($!)
for _ in $(seq 1 100); do
  [ -s "$dir/display" ] && break
  kill -0 "${pids[0]}" 2>/dev/null || { echo "web-window.sh: Xvfb did not start:" >&2; cat "$dir/xvfb.log" >&2; exit 1; }
  sleep 0.1
done
display=:$(head -n 1 "$dir/display")
[ "$display" != : ] || { echo "web-window.sh: Xvfb reported no display within 10 s" >&2; exit 1; }

# The VNC server listens on this machine only; the browser reaches it through websockify.
vnc_port=$(( 5900 + ${display#:} ))
x11vnc -display "$display" -rfbport "$vnc_port" -localhost -forever -shared -nopw -noxdamage -quiet \
       > "$dir/x11vnc.log" 2>&1 &
pids+=($!)
websockify --web "$novnc" "$listen:$port" "127.0.0.1:$vnc_port" > "$dir/websockify.log" 2>&1 &
pids+=($!)
ready=0
for _ in $(seq 1 100); do
  (exec 3<>"/dev/tcp/127.0.0.1/$vnc_port") 2>/dev/null && (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && { ready=1; break; }
  for pid in "${pids[@]:1}"; do
    kill -0 "$pid" 2>/dev/null && continue
    echo "web-window.sh: the VNC server or websockify stopped:" >&2
    cat "$dir/x11vnc.log" "$dir/websockify.log" >&2
    exit 1
  done
  sleep 0.1
done
if [ "$ready" -ne 1 ] && [ "$listen" != 127.0.0.1 ] && [ "$listen" != 0.0.0.0 ]; then
  ready=1   # served on another address only: this machine's loopback cannot tell
fi
if [ "$ready" -ne 1 ]; then
  echo "web-window.sh: the VNC server (port $vnc_port) or the page (port $port) did not answer within 10 s:" >&2
  cat "$dir/x11vnc.log" "$dir/websockify.log" >&2
  exit 1
fi

echo "web-window.sh: open http://localhost:$port/vnc.html?autoconnect=true&resize=scale in a browser" >&2
echo "web-window.sh: (display $display; Ctrl+C here stops it)" >&2
DISPLAY=$display "$@" &
pids+=($!)
status=0
wait "${pids[-1]}" || status=$?
exit "$status"
