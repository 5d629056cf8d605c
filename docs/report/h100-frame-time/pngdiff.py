#!/usr/bin/env python3
"""Compares two 8-bit PNGs (as fxdemo writes them) pixel by pixel: prints the pixels that differ,
the largest channel difference and the bounding box of the differing pixels. Standard library only
(zlib), so it runs on a bare device machine; identical files are not decoded.

usage: pngdiff.py A.png B.png   (exit 0 identical pixels, 1 different, 2 usage or unreadable)"""
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace != 0 or colour not in (0, 2, 4, 6):
                raise ValueError(f"{path}: only 8-bit non-interlaced grey/RGB/RGBA PNGs are read")
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filter_type = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if filter_type == 1:
            for i in range(channels, stride):
                row[i] = (row[i] + row[i - channels]) & 255
        elif filter_type == 2:
            row = bytearray((a + b) & 255 for a, b in zip(row, previous))
        elif filter_type == 3:
            for i in range(stride):
                left = row[i - channels] if i >= channels else 0
                row[i] = (row[i] + ((left + previous[i]) >> 1)) & 255
        elif filter_type == 4:
            for i in range(stride):
                a = row[i - channels] if i >= channels else 0
                b = previous[i]
                c = previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        previous = row
    return width, height, channels, rows


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        with open(argv[1], "rb") as a, open(argv[2], "rb") as b:
            if a.read() == b.read():
                print(f"{argv[1]} {argv[2]}: identical files")
                return 0
        wa, ha, ca, ra = read_png(argv[1])
        wb, hb, cb, rb = read_png(argv[2])
    except (OSError, ValueError, zlib.error) as e:
        print(f"pngdiff: {e}", file=sys.stderr)
        return 2
    if (wa, ha, ca) != (wb, hb, cb):
        print(f"{argv[1]} {argv[2]}: sizes differ ({wa}x{ha}x{ca} vs {wb}x{hb}x{cb})")
        return 1
    differing, largest, box = 0, 0, None
    for y in range(ha):
        if ra[y] == rb[y]:
            continue
        for x in range(wa):
            pa, pb = ra[y][x * ca:(x + 1) * ca], rb[y][x * ca:(x + 1) * ca]
            if pa != pb:
                differing += 1
                largest = max(largest, max(abs(p - q) for p, q in zip(pa, pb)))
                box = (x, y, x, y) if box is None else (min(box[0], x), min(box[1], y), max(box[2], x), max(box[3], y))
    print(f"{argv[1]} {argv[2]}: {differing} of {wa * ha} pixels differ, largest channel difference {largest}"
          + (f", in x {box[0]}..{box[2]}, y {box[1]}..{box[3]}" if box else ""))
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
