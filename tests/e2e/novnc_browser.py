#!/usr/bin/env python3
"""Looks at a noVNC page the way a student does, in headless Chromium.

    novnc_browser.py URL --screenshot OUT.png [--key K ...] (--size WxH | --compare-with PNG) [--timeout S]

Opens URL (tools/web-window.sh's page) and waits until noVNC has connected and
the remote screen shows a window at its top left; clicks into the page and
types each --key, as a student's keyboard would; then saves a browser
screenshot of the window's region (its size from --size, or from the picture
given to --compare-with, which the program saves on a key such as F12) and,
with --compare-with, checks that the two show the same picture. Chromium is
driven through its DevTools protocol over a WebSocket; the client below uses
the standard library only. Exit status 0, or 1 with a message on stderr.
"""
import argparse
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request


class WebSocket:
    """The client side of RFC 6455, enough for DevTools: text frames, masked."""

    def __init__(self, url):
        assert url.startswith("ws://")
        host_port, _, path = url[len("ws://"):].partition("/")
        host, _, port = host_port.partition(":")
        self.sock = socket.create_connection((host, int(port)), timeout=30)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (f"GET /{path} HTTP/1.1\r\nHost: {host_port}\r\nUpgrade: websocket\r\n"
                   f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.sock.sendall(request.encode())
        response = b""
        while b"\r\n\r\n" not in response:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise RuntimeError("the DevTools connection closed during the handshake")
            response += chunk
        if b" 101 " not in response.split(b"\r\n", 1)[0]:
            raise RuntimeError("DevTools refused the WebSocket: " + response.split(b"\r\n", 1)[0].decode())
        self.buffer = response.split(b"\r\n\r\n", 1)[1]

    def send(self, text):
        payload = text.encode()
        header = bytes([0x81])
        if len(payload) < 126:
            header += bytes([0x80 | len(payload)])
        elif len(payload) < 65536:
            header += bytes([0x80 | 126]) + struct.pack(">H", len(payload))
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", len(payload))
        mask = os.urandom(4)
        self.sock.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def _read(self, count):
        while len(self.buffer) < count:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise RuntimeError("the DevTools connection closed")
            self.buffer += chunk
        data, self.buffer = self.buffer[:count], self.buffer[count:]
        return data

    def receive(self):
        message = b""
        while True:
            first, second = self._read(2)
            length = second & 0x7F
            if length == 126:
                length = struct.unpack(">H", self._read(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", self._read(8))[0]
            message += self._read(length)
            if first & 0x80:
                return message.decode()


class Page:
    """One browser tab, through the DevTools protocol."""

    def __init__(self, websocket):
        self.ws = websocket
        self.next_id = 0

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            reply = json.loads(self.ws.receive())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"the page's script failed: {result['exceptionDetails'].get('text')}")
        return result["result"].get("value")


def start_chromium(profile):
    browser = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if not browser:
        sys.exit("novnc_browser.py: no chromium on PATH (Debian: apt-get install chromium)")
    # The flags keep Chromium off the network it would otherwise try (updates, sync).
    process = subprocess.Popen(
        [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic",
         f"--user-data-dir={profile}", "--remote-debugging-port=0", "--window-size=1280,1000", "about:blank"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    port_file = os.path.join(profile, "DevToolsActivePort")
    for _ in range(300):
        if os.path.exists(port_file) and open(port_file).read().strip():
            port = open(port_file).read().split()[0]
            targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10))
            pages = [t for t in targets if t.get("type") == "page"]
            if pages:
                return process, pages[0]["webSocketDebuggerUrl"]
        if process.poll() is not None:
            sys.exit("novnc_browser.py: chromium ended at start-up")
        time.sleep(0.1)
    process.kill()
    sys.exit("novnc_browser.py: chromium did not open its DevTools port within 30 s")


# True once the noVNC canvas shows the lab's window: a pixel well inside the
# WxH region that is not the empty X screen's black.
WINDOW_DRAWN = """(() => {
  const canvas = document.querySelector('#noVNC_container canvas');
  if (!canvas || canvas.width < %(w)d || canvas.height < %(h)d) return false;
  const pixels = canvas.getContext('2d').getImageData(0, 0, %(w)d, %(h)d).data;
  let lit = 0;
  for (let i = 0; i < pixels.length; i += 4 * 97) lit += (pixels[i] + pixels[i + 1] + pixels[i + 2]) > 30;
  return lit > pixels.length / (4 * 97) / 4;
})()"""

CANVAS_RECT = """(() => {
  const r = document.querySelector('#noVNC_container canvas').getBoundingClientRect();
  return [r.left, r.top];
})()"""


# The mean difference of two same-sized pictures (0-255 a channel) and the share
# of pixels that differ by more than 32 in a channel, both decoded by the page.
COMPARE = """(async () => {
  const load = (url) => new Promise((done, failed) => {
    const image = new Image();
    image.onload = () => done(image);
    image.onerror = () => failed(new Error('not a picture'));
    image.src = url;
  });
  const [a, b] = await Promise.all([load(%(a)s), load(%(b)s)]);
  if (a.width !== b.width || a.height !== b.height) return {size: [a.width, a.height, b.width, b.height]};
  const pixels = (image) => {
    const canvas = document.createElement('canvas');
    canvas.width = image.width; canvas.height = image.height;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    return context.getImageData(0, 0, image.width, image.height).data;
  };
  const p = pixels(a), q = pixels(b);
  let sum = 0, far = 0;
  for (let i = 0; i < p.length; i += 4) {
    let most = 0;
    for (let c = 0; c < 3; ++c) { const d = Math.abs(p[i + c] - q[i + c]); sum += d; most = Math.max(most, d); }
    far += most > 32;
  }
  return {mean: sum / (p.length / 4 * 3), far: far / (p.length / 4)};
})()"""


def data_url(path):
    return json.dumps("data:image/png;base64," + base64.b64encode(open(path, "rb").read()).decode())


def wait_for_file(path, timeout):
    deadline = time.time() + timeout
    while not os.path.exists(path) and time.time() < deadline:
        time.sleep(0.1)
    time.sleep(0.5)   # the program may still be writing it
    return os.path.exists(path)


def png_size(path):
    """A PNG's width and height, from its IHDR chunk."""
    header = open(path, "rb").read(24)
    if header[:8] != b"\x89PNG\r\n\x1a\n" or header[12:16] != b"IHDR":
        sys.exit(f"novnc_browser.py: {path} is not a PNG file")
    return struct.unpack(">II", header[16:24])


def compare(page, own, shot):
    """0 when the browser screenshot `shot` shows the program's own picture `own`."""
    result = page.call("Runtime.evaluate", expression=COMPARE % {"a": data_url(own), "b": data_url(shot)},
                       awaitPromise=True, returnByValue=True)["result"].get("value") or {}
    if "size" in result:
        print(f"FAIL: the program's picture is {result['size'][0]}x{result['size'][1]}, the browser's "
              f"{result['size'][2]}x{result['size'][3]}", file=sys.stderr)
        return 1
    # VNC's encodings are a little lossy at edges: a mean of about 1 and under 1% of
    # pixels far off is the same picture; another view or case is a mean of 20 to 50.
    verdict = result.get("mean", 255) < 3.0 and result.get("far", 1.0) < 0.02
    print(f"{'the same picture' if verdict else 'FAIL: not the same picture'}: mean difference "
          f"{result.get('mean', 0):.2f} of 255, {100 * result.get('far', 0):.2f}% of pixels off by more than 32")
    return 0 if verdict else 1


# Keys other than letters and digits, as DevTools names them, with their key codes.
NAMED_KEYS = {"F12": 123, "Escape": 27, "Tab": 9}


def type_key(page, key):
    """Presses and releases one key: a letter, a digit or one of NAMED_KEYS."""
    if key in NAMED_KEYS:
        down = {"key": key, "code": key, "windowsVirtualKeyCode": NAMED_KEYS[key]}
    elif len(key) == 1 and key.isalnum():
        code = f"Key{key.upper()}" if key.isalpha() else f"Digit{key}"
        down = {"key": key, "code": code, "text": key, "windowsVirtualKeyCode": ord(key.upper())}
    else:
        sys.exit(f"novnc_browser.py: --key {key}: expected a letter, a digit or one of {', '.join(NAMED_KEYS)}")
    page.call("Input.dispatchKeyEvent", type="keyDown", **down)
    up = {k: v for k, v in down.items() if k != "text"}
    page.call("Input.dispatchKeyEvent", type="keyUp", **up)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--size", type=lambda text: tuple(int(v) for v in text.split("x")),
                        help="the window's WIDTHxHEIGHT (without --compare-with)")
    parser.add_argument("--screenshot", required=True)
    parser.add_argument("--key", action="append", default=[])
    parser.add_argument("--compare-with", metavar="PNG",
                        help="after the keys, wait for this picture (the program's own screenshot, F12) "
                             "and check that the browser screenshot shows the same")
    parser.add_argument("--timeout", type=float, default=30.0)
    args = parser.parse_args()

    profile = tempfile.mkdtemp(prefix="stoa-chromium-")
    process, url = start_chromium(profile)
    try:
        page = Page(WebSocket(url))
        page.call("Page.enable")
        page.call("Page.navigate", url=args.url)
        deadline = time.time() + args.timeout
        connected = drawn = False
        last_error = None
        while time.time() < deadline and not drawn:
            time.sleep(0.25)
            # While the page is still loading, a script may find no document or no canvas
            # yet and throw (a loaded machine showed it): that is "not yet", not a failure.
            try:
                connected = bool(page.evaluate("document.documentElement.classList.contains('noVNC_connected')"))
                drawn = connected and bool(page.evaluate(WINDOW_DRAWN % {"w": 64, "h": 64}))
            except RuntimeError as error:
                last_error = error
                connected = drawn = False
        if not connected:
            print(f"FAIL: noVNC did not connect within {args.timeout:.0f} s"
                  + (f" (the page's last script error: {last_error})" if last_error else ""), file=sys.stderr)
            return 1
        if not drawn:
            print(f"FAIL: noVNC connected, but no window showed at the screen's top left within {args.timeout:.0f} s",
                  file=sys.stderr)
            return 1
        left, top = page.evaluate(CANVAS_RECT)
        print(f"noVNC connected; the remote screen is at ({left:.0f}, {top:.0f}) of the page")
        if args.key:
            # A click gives noVNC's canvas the keyboard, as a student's click does.
            for kind in ("mousePressed", "mouseReleased"):
                page.call("Input.dispatchMouseEvent", type=kind, x=left + 32, y=top + 32, button="left", clickCount=1)
            for key in args.key:
                type_key(page, key)
                print(f"typed {key} into the page")
        size = args.size
        if args.compare_with:
            if not wait_for_file(args.compare_with, args.timeout):
                print(f"FAIL: the program did not save {args.compare_with} within {args.timeout:.0f} s", file=sys.stderr)
                return 1
            size = png_size(args.compare_with)
        if not size:
            parser.error("give --size WIDTHxHEIGHT or --compare-with PNG")
        width, height = size
        time.sleep(1.0)   # the last updates of the frame reach the page
        shot = page.call("Page.captureScreenshot", format="png",
                         clip={"x": left, "y": top, "width": width, "height": height, "scale": 1})
        with open(args.screenshot, "wb") as out:
            out.write(base64.b64decode(shot["data"]))
        print(f"saved the page's {width}x{height} at the screen's top left to {args.screenshot}")
        if args.compare_with:
            return compare(page, args.compare_with, args.screenshot)
        return 0
    finally:
        process.kill()
        process.wait()
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
