#!/usr/bin/env python3
"""Writes texture/checker.bmp: a 64 x 64 two-colour checkerboard (8 x 8 squares)
with a thin grid line, as a 24-bit BMP. Deterministic: the same bytes on every
run. Used by testcases/showcase.txt.

    python3 scripts/make_texture.py [OUT.bmp]
"""

import os
import struct
import sys

SIZE, SQUARE = 64, 8
LIGHT, DARK, LINE = (230, 220, 200), (60, 90, 140), (20, 20, 20)


def texel(x, y):
    if x % SQUARE == 0 or y % SQUARE == 0:
        return LINE
    return LIGHT if (x // SQUARE + y // SQUARE) % 2 == 0 else DARK


def bmp(width, height, pixel):
    row_size = (width * 3 + 3) & ~3
    data = bytearray()
    for y in range(height - 1, -1, -1):  # BMP rows run bottom to top
        row = bytearray()
        for x in range(width):
            r, g, b = pixel(x, y)
            row += bytes((b, g, r))
        data += row + bytes(row_size - len(row))
    header = struct.pack("<2sIHHI", b"BM", 54 + len(data), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(data), 2835, 2835, 0, 0)
    return header + info + bytes(data)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "texture", "checker.bmp")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "wb") as f:
        f.write(bmp(SIZE, SIZE, texel))


if __name__ == "__main__":
    main()
