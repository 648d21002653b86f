"""Pixel statistics of a PNG screenshot, with the standard library only (zlib).

png_stats.py FILE X0 Y0 X1 Y1 prints, over the box [X0, X1) x [Y0, Y1), the fraction of pixels
that differ from the box's most common colour (the background) and the number of distinct
colours, as JSON. Handles 8-bit RGB and RGBA, non-interlaced (what Chromium writes)."""
import json
import struct
import sys
import zlib
from collections import Counter


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise SystemExit(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs are read here")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        kind = raw[at]
        line = bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


def main():
    path, x0, y0, x1, y1 = sys.argv[1], *map(int, sys.argv[2:6])
    width, height, channels, rows = read_png(path)
    x1, y1 = min(x1, width), min(y1, height)
    colours = Counter()
    for y in range(y0, y1, 2):  # every other row and column: plenty for statistics
        row = rows[y]
        for x in range(x0, x1, 2):
            colours[row[x * channels:x * channels + 3]] += 1
    total = sum(colours.values())
    background, count = colours.most_common(1)[0]
    print(json.dumps({"width": width, "height": height, "background": list(background),
                      "foreground_fraction": 1.0 - count / total,
                      "distinct_colours": len(colours)}))


main()
