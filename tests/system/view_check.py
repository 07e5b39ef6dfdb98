#!/usr/bin/python3
"""Pixel check of an `fsi view` PNG (tests/system/test_view.sh): particles were drawn.

    view_check.py PNG [--drawn F] [--coloured F] [--panels N] [--time TEXT] [--blank OUT]

Inside each axes box that fsi view records in the PNG's text (fsi:axes: left, top,
right, bottom in pixels; shrunk by 3 pixels so the frame is left out, the ticks point
outwards) it counts the pixels that are not white and those with colour (channels more
than 40 apart: grey walls and neutral participants are not coloured). Fails (exit 1)
when a panel has less than F of its area drawn or coloured, when the PNG has not N
panels, or when fsi:time does not contain TEXT. --blank OUT writes a copy with the
axes boxes painted white, on which the check must fail (the check can fail).
"""
import argparse
import sys

import numpy as np
from PIL import Image


def boxes(im):
    """The axes boxes of the PNG's fsi:axes text, shrunk by 3 pixels."""
    text = im.text.get("fsi:axes")
    if not text:
        sys.exit("FAIL: no fsi:axes text in the PNG")
    out = []
    for part in text.split(";"):
        left, top, right, bottom = (int(v) for v in part.split(","))
        out.append((left + 3, top + 3, right - 3, bottom - 3))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("--drawn", type=float, default=0.01)
    ap.add_argument("--coloured", type=float, default=0.0)
    ap.add_argument("--panels", type=int, default=None)
    ap.add_argument("--time", default=None)
    ap.add_argument("--blank", default=None)
    a = ap.parse_args()
    im = Image.open(a.png)
    rgb = np.asarray(im.convert("RGB")).astype(int)
    panels = boxes(im)
    if a.blank:
        blank = rgb.copy()
        for left, top, right, bottom in panels:
            blank[top:bottom, left:right] = 255
        out = Image.fromarray(blank.astype(np.uint8))
        info = __import__("PIL.PngImagePlugin", fromlist=["PngInfo"]).PngInfo()
        for k, v in im.text.items():
            info.add_text(k, v)
        out.save(a.blank, pnginfo=info)
    if a.panels is not None and len(panels) != a.panels:
        sys.exit("FAIL: %s has %d panels, expected %d" % (a.png, len(panels), a.panels))
    if a.time is not None and a.time not in im.text.get("fsi:time", ""):
        sys.exit("FAIL: %s shows %r, expected %r" % (a.png, im.text.get("fsi:time"), a.time))
    for i, (left, top, right, bottom) in enumerate(panels):
        px = rgb[top:bottom, left:right].reshape(-1, 3)
        if not len(px):
            sys.exit("FAIL: %s: panel %d is empty (%s)" % (a.png, i, im.text["fsi:axes"]))
        drawn = float((px.min(axis=1) < 245).mean())
        coloured = float(((px.max(axis=1) - px.min(axis=1)) > 40).mean())
        print("%s panel %d: %.3f drawn, %.3f coloured" % (a.png, i, drawn, coloured))
        if drawn < a.drawn:
            sys.exit("FAIL: %s panel %d: %.4f of the axes drawn, expected >= %g"
                     % (a.png, i, drawn, a.drawn))
        if coloured < a.coloured:
            sys.exit("FAIL: %s panel %d: %.4f of the axes coloured, expected >= %g"
                     % (a.png, i, coloured, a.coloured))


if __name__ == "__main__":
    main()
