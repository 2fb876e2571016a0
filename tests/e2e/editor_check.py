#!/usr/bin/env python3
"""Helpers of the stoa-editor window tests (editor_*.sh), standard library only.

  editor_check.py pixel SCENE.json WIDTH HEIGHT X Y Z
      The window pixel "x y" (from the top-left) where the world point (X, Y, Z)
      shows, seen by the scene file's orbit camera in a WIDTH x HEIGHT window.
  editor_check.py colour IMAGE.png X Y
      The mean colour "r g b" (0..255) of the 5 x 5 pixels around (X, Y).
  editor_check.py write-png IMAGE.png R G B
      A 64 x 64 RGB PNG of one colour (0..255 each).
  editor_check.py band IMAGE.png TOP BOTTOM
      Over rows TOP..BOTTOM-1 (fractions of the height, 0..1): "r g b coloured"
      with the mean colour (0..255) and the percentage of strongly coloured
      pixels (brightest channel at least 60 above the dimmest).
  editor_check.py showcase IMAGE.png
      Passes (exit 0) when IMAGE looks like the showcase: sky at the top (the
      top eighth bluish and bright) and the point lights' coloured pools on the
      ground (3 % or more of the bottom two fifths strongly coloured); says what
      it measured, and what is wrong (exit 1).
  editor_check.py differ A.png B.png
      The percentage of pixels whose colours differ by more than 24 in a channel
      (the two pictures the same size).
  editor_check.py moved ORIGINAL.json SAVED.json OBJECT
      Passes (exit 0) when SAVED differs from ORIGINAL only in OBJECT's x
      position, by more than 0.1, and says by how much; otherwise says what
      differs (exit 1).

The camera is the editor's (stoa-editor passes the scene's camera to its
case): an orbit camera (eyePosition(OrbitState), lab 01) looking at the
target with +Y up, a vertical field of view of 50 degrees (CameraRig's default)
and the window's aspect ratio. The PNG reader handles what Stoa writes:
8-bit RGB or RGBA, not interlaced.
"""

import json
import math
import struct
import sys
import zlib

from check_ui_panel import read_png   # (width, height, channels, rows) of an 8-bit RGB/RGBA PNG


def scene_pixel(scene_file, width, height, point):
    with open(scene_file) as f:
        camera = json.load(f).get("camera", {})
    target = camera.get("target", [0.0, 0.0, 0.0])
    distance = camera.get("distance", 12.0)
    yaw = math.radians(camera.get("yaw", 30.0))
    pitch = math.radians(camera.get("pitch", 25.0))
    back = [math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)]
    eye = [target[i] + distance * back[i] for i in range(3)]
    # right = normalize(up x back), up = (0, 1, 0); the view's up = back x right.
    n = math.hypot(back[0], back[2])
    right = [back[2] / n, 0.0, -back[0] / n]
    up = [back[1] * right[2] - back[2] * right[1],
          back[2] * right[0] - back[0] * right[2],
          back[0] * right[1] - back[1] * right[0]]
    p = [point[i] - eye[i] for i in range(3)]
    x = sum(right[i] * p[i] for i in range(3))
    y = sum(up[i] * p[i] for i in range(3))
    z = sum(back[i] * p[i] for i in range(3))   # negative in front of the eye
    f = 1.0 / math.tan(math.radians(50.0) / 2.0)
    aspect = width / height
    ndc_x = f / aspect * x / -z
    ndc_y = f * y / -z
    return (ndc_x + 1.0) / 2.0 * width, (1.0 - ndc_y) / 2.0 * height


def write_png(path, rgb):
    size = 64
    row = b"\x00" + bytes(rgb) * size
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(row * size)))
        f.write(chunk(b"IEND", b""))


def mean_colour(path, x, y):
    width, height, channels, rows = read_png(path)
    total, count = [0, 0, 0], 0
    for yy in range(max(0, y - 2), min(height, y + 3)):
        for xx in range(max(0, x - 2), min(width, x + 3)):
            for c in range(3):
                total[c] += rows[yy][xx * channels + c]
            count += 1
    return [round(t / count) for t in total]


def check_moved(original_file, saved_file, name):
    with open(original_file) as f:
        original = json.load(f)
    with open(saved_file) as f:
        saved = json.load(f)
    problems = []
    before = [o for o in original["objects"] if o["name"] == name]
    after = [o for o in saved["objects"] if o["name"] == name]
    if len(before) != 1 or len(after) != 1:
        return [f"expected one object named {name!r} in each file"]
    moved_x = after[0]["position"][0] - before[0]["position"][0]
    if not abs(moved_x) > 0.1:
        problems.append(f"{name} moved along x by {moved_x:.4f}, expected more than 0.1")
    else:
        print(f"{name} moved along x by {moved_x:.3f}")
    if after[0]["position"][1:] != before[0]["position"][1:]:
        problems.append(f"{name}'s y and z changed: {before[0]['position']} -> {after[0]['position']}")
    # Everything else is as it was: the object with its x put back, every other
    # object, the materials, lights, camera and settings.
    after[0]["position"][0] = before[0]["position"][0]
    for key in sorted(set(original) | set(saved)):
        if original.get(key) != saved.get(key):
            problems.append(f"{key!r} changed: {original.get(key)!r} -> {saved.get(key)!r}")
    return problems


def band_statistics(path, top, bottom):
    width, height, channels, rows = read_png(path)
    sums, coloured, count = [0, 0, 0], 0, 0
    for y in range(int(top * height), int(bottom * height)):
        row = rows[y]
        for x in range(width):
            pixel = row[x * channels:x * channels + 3]
            for i in range(3):
                sums[i] += pixel[i]
            coloured += max(pixel) - min(pixel) >= 60
            count += 1
    return [round(v / max(count, 1)) for v in sums] + [round(100.0 * coloured / max(count, 1), 1)]


def check_showcase(path):
    r, g, b, _ = band_statistics(path, 0.0, 0.12)
    print(f"sky band: ({r}, {g}, {b})")
    if not (b > 150 and b >= r):
        print(f"the top of {path} is not sky: ({r}, {g}, {b})")
        return 1
    r, g, b, coloured = band_statistics(path, 0.6, 1.0)
    print(f"ground band: ({r}, {g}, {b}), {coloured} % strongly coloured")
    if coloured < 3:
        print(f"too few coloured pixels on the ground of {path} ({coloured} %): the point lights are missing")
        return 1
    return 0


def differing_percent(a_path, b_path):
    wa, ha, ca, a = read_png(a_path)
    wb, hb, cb, b = read_png(b_path)
    if (wa, ha) != (wb, hb):
        raise SystemExit(f"{a_path} is {wa}x{ha}, {b_path} is {wb}x{hb}")
    differing = 0
    for y in range(ha):
        for x in range(wa):
            pa, pb = a[y][x * ca:x * ca + 3], b[y][x * cb:x * cb + 3]
            differing += any(abs(pa[i] - pb[i]) > 24 for i in range(3))
    return round(100.0 * differing / (wa * ha), 1)


def main(argv):
    command = argv[1] if len(argv) > 1 else ""
    if command == "pixel" and len(argv) == 8:
        x, y = scene_pixel(argv[2], int(argv[3]), int(argv[4]), [float(v) for v in argv[5:8]])
        print(f"{round(x)} {round(y)}")
    elif command == "colour" and len(argv) == 5:
        print(*mean_colour(argv[2], int(argv[3]), int(argv[4])))
    elif command == "band" and len(argv) == 5:
        print(*band_statistics(argv[2], float(argv[3]), float(argv[4])))
    elif command == "showcase" and len(argv) == 3:
        return check_showcase(argv[2])
    elif command == "differ" and len(argv) == 4:
        print(differing_percent(argv[2], argv[3]))
    elif command == "write-png" and len(argv) == 6:
        write_png(argv[2], [int(v) for v in argv[3:6]])
    elif command == "moved" and len(argv) == 5:
        problems = check_moved(argv[2], argv[3], argv[4])
        for problem in problems:
            print(problem)
        return 1 if problems else 0
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
