#!/usr/bin/env python3
"""check_ui_panel.py BEFORE.png AFTER.png

The window before and after F1: where LabApp puts the UI panel (10, 10, 280 x
120 pixels) ImGui's dark style draws a blue title bar and light text, which
the frame before F1 does not have there, and elsewhere the frame must be the same. Reads the 8-bit RGBA PNGs that
Image::savePng writes (png_file.py).
"""
import sys

from png_file import pixel, read_png


def changed_fraction(before, after, x0, y0, x1, y1, step=3):
    changed = total = 0
    for y in range(y0, y1, step):
        for x in range(x0, x1, step):
            total += 1
            if max(abs(p - q) for p, q in zip(pixel(before, x, y), pixel(after, x, y))) > 8:
                changed += 1
    return changed / total


def title_blue(image):
    """The fraction of the title bar's pixels in ImGui's title blue (b well above r)."""
    blue = total = 0
    for y in range(14, 26, 2):
        for x in range(80, 280, 3):
            r, g, b = pixel(image, x, y)
            total += 1
            blue += b > r + 40 and b > 80
    return blue / total


def text_pixels(image):
    """Light pixels in the panel's body, where its lines of text are."""
    return sum(1 for y in range(32, 90) for x in range(16, 250) if min(pixel(image, x, y)) > 150)


def main():
    before, after = read_png(sys.argv[1]), read_png(sys.argv[2])
    assert before[:2] == after[:2], "the screenshots differ in size"
    width, height = before[:2]
    outside = changed_fraction(before, after, 320, 160, width - 10, height - 10, step=7)
    print(f"title bar blue: before {title_blue(before):.0%}, after {title_blue(after):.0%}; "
          f"text pixels: before {text_pixels(before)}, after {text_pixels(after)}; "
          f"changed outside the panel: {outside:.1%}")
    if title_blue(after) < 0.6 or title_blue(before) > 0.1:
        print("FAIL: no ImGui title bar where the panel goes, after F1")
        return 1
    if text_pixels(after) < 100 + text_pixels(before):
        print("FAIL: no text in the panel")
        return 1
    if outside > 0.01:
        print("FAIL: the frame changed outside the panel")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
