#!/usr/bin/env python3
"""Compares two 8-bit PNGs (any colour type the ssfx writers use: grey, RGB, RGBA; no
palette, no interlace) channel by channel: prints the largest difference in levels and the
share of pixels that differ by more than one level, and exits 1 when they exceed the limits
given (--max LEVELS, --share FRACTION) or the sizes differ. Standard library only."""
import argparse
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    w, h, depth, ctype, _, _, interlace = header
    if depth != 8 or interlace != 0 or ctype not in (0, 2, 4, 6):
        sys.exit(f"{path}: only 8-bit non-interlaced grey/RGB/RGBA PNGs")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(idat)
    stride = w * channels
    rows, prev = [], bytearray(stride)
    for y in range(h):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # undo the row filter (PNG spec, section 9)
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
        rows.append(line)
        prev = line
    return w, h, channels, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--max", type=int, default=0, help="largest difference allowed, in levels")
    ap.add_argument("--share", type=float, default=0.0, help="share of pixels allowed to differ by more than 1")
    args = ap.parse_args()
    wa, ha, ca, ra = read_png(args.a)
    wb, hb, cb, rb = read_png(args.b)
    if (wa, ha, ca) != (wb, hb, cb):
        print(f"sizes differ: {wa}x{ha}x{ca} vs {wb}x{hb}x{cb}")
        return 1
    largest, over = 0, 0
    for y in range(ha):
        for x in range(wa):
            d = max(abs(ra[y][x * ca + k] - rb[y][x * ca + k]) for k in range(ca))
            largest = max(largest, d)
            over += d > 1
    share = over / (wa * ha)
    print(f"largest difference {largest} levels, {share:.5f} of the pixels differ by more than 1")
    return 0 if largest <= args.max and share <= args.share else 1


if __name__ == "__main__":
    sys.exit(main())
