#!/usr/bin/env python3
"""Writes the image fixtures of tests/assets/image_read_stb_test.cpp into this folder: small
files in the variants where two decoders could disagree (bit depths, palettes, transparency
keys, interlacing, row order, run-length encoding), for checking that stb_image decodes
them to the same texels as OpenImageIO. Deterministic: rerunning it rewrites identical files.
Python 3 standard library only.

Usage: python3 tests/data/images/make_fixtures.py
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


# --- PNG ------------------------------------------------------------------------------------

def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))


def png(width, height, rows, color_type, bit_depth=8, extra=b"", interlace=0, sub_filter=0):
    """rows: packed scanlines without filter bytes (already split into Adam7 passes when
    interlaced). sub_filter: bytes per pixel for filter type 1 (Sub), 0 for no filter."""
    def filtered(row):
        if not sub_filter:
            return b"\x00" + row
        return b"\x01" + bytes((row[i] - (row[i - sub_filter] if i >= sub_filter else 0)) & 255
                               for i in range(len(row)))
    raw = b"".join(filtered(row) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, interlace)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + extra +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


# 256x256 16-bit gray holding every value 0..65535 once (row y, column x: 256 * y + x):
# pins the 16- to 8-bit rounding.
RAMP16 = png(256, 256, [b"".join(struct.pack(">H", 256 * y + x) for x in range(256))
                        for y in range(256)], color_type=0, bit_depth=16, sub_filter=2)

# 4x2 palette image whose tRNS chunk makes entries 0 and 2 transparent / half transparent.
PALETTE = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255), (10, 20, 30)]
PALETTE_TRNS = png(4, 2, [bytes([0, 1, 2, 3]), bytes([4, 3, 2, 1])], color_type=3,
                   extra=chunk(b"PLTE", bytes(c for rgb in PALETTE for c in rgb)) +
                   chunk(b"tRNS", bytes([0, 255, 128])))

# 3x1 gray + alpha.
GRAY_ALPHA = png(3, 1, [bytes([0, 255, 100, 128, 250, 0])], color_type=4)

# 3x1 8-bit gray with a transparency key (gray 100 is transparent).
GRAY_TRNS = png(3, 1, [bytes([0, 100, 200])], color_type=0, extra=chunk(b"tRNS", b"\x00\x64"))

# 8x1 2-bit gray: 0, 1, 2, 3, 3, 2, 1, 0 (expanded to 0, 85, 170, 255).
GRAY2 = png(8, 1, [bytes([0b00011011, 0b11100100])], color_type=0, bit_depth=2)


def adam7_rows(width, height, pixel):
    """Scanlines of the seven Adam7 passes (8-bit RGB; pixel(x, y) -> 3 bytes)."""
    passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4),
              (1, 0, 2, 2), (0, 1, 1, 2)]
    rows = []
    for x0, y0, dx, dy in passes:
        for y in range(y0, height, dy):
            row = b"".join(pixel(x, y) for x in range(x0, width, dx))
            if row:
                rows.append(row)
    return rows


# 9x9 RGB, Adam7 interlaced: every texel distinct.
INTERLACED = png(9, 9, adam7_rows(9, 9, lambda x, y: bytes([x * 28, y * 28, (x * 9 + y) * 3])),
                 color_type=2, interlace=1)


# --- BMP and TGA ----------------------------------------------------------------------------

def texel(x, y):
    return (40 * x + 10, 60 * y + 20, 200 - 30 * x)  # RGB, distinct per texel


# 3x2 24-bit BMP, stored bottom row first, rows padded to 4 bytes.
def bmp(width, height):
    rows = []
    for y in reversed(range(height)):
        row = b"".join(bytes(reversed(texel(x, y))) for x in range(width))
        rows.append(row + b"\x00" * (-len(row) % 4))
    pixels = b"".join(rows)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    header = struct.pack("<2sIHHI", b"BM", 14 + len(info) + len(pixels), 0, 0, 14 + len(info))
    return header + info + pixels


# 3x2 24-bit uncompressed TGA, stored bottom row first (descriptor 0).
def tga_bottom_up(width, height):
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, width, height, 24, 0)
    return header + b"".join(bytes(reversed(texel(x, y)))
                             for y in reversed(range(height)) for x in range(width))


# 4x2 32-bit run-length encoded TGA, stored top row first (descriptor 0x28): per row a run of
# two equal texels and a raw packet of two.
def tga_rle_top_down():
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, 4, 2, 32, 0x28)
    body = b""
    for y in range(2):
        bgra = lambda x: bytes(reversed(texel(x, y))) + bytes([255 - 60 * x])
        body += bytes([0x80 | 1]) + bgra(0)              # run: texel 0 twice
        body += bytes([1]) + bgra(2) + bgra(3)           # raw: texels 2 and 3
    return header + body


# --- Radiance HDR ---------------------------------------------------------------------------

def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes([int(r * scale), int(g * scale), int(b * scale), exponent + 128])


def rle_component(values):
    """New-style RLE of one component of a scanline: runs of 3+ equal bytes, else raw dumps."""
    out, i = b"", 0
    while i < len(values):
        run = 1
        while i + run < len(values) and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 3:
            out += bytes([128 + run, values[i]])
            i += run
            continue
        start = i
        while i < len(values) and i - start < 128:
            if i + 2 < len(values) and values[i] == values[i + 1] == values[i + 2]:
                break
            i += 1
        out += bytes([i - start]) + bytes(values[start:i])
    return out


# 16x3 run-length encoded HDR: a bright ramp, a flat run, and a black texel (exponent 0).
def hdr_rle(width=16, height=3):
    lines = []
    for y in range(height):
        texels = []
        for x in range(width):
            if y == 1 and x < 10:
                texels.append(rgbe(0.5, 0.5, 0.5))
            elif y == 2 and x == 5:
                texels.append(rgbe(0.0, 0.0, 0.0))
            else:
                texels.append(rgbe(0.01 * (x + 1) * (y + 1), 2.0 ** (x - 6), 100.0 / (x + 1)))
        line = bytes([2, 2, width >> 8, width & 255])
        for c in range(4):
            line += rle_component([t[c] for t in texels])
        lines.append(line)
    return (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width) +
            b"".join(lines))


FIXTURES = {
    "ramp16.png": RAMP16,
    "palette_trns.png": PALETTE_TRNS,
    "gray_alpha.png": GRAY_ALPHA,
    "gray_trns.png": GRAY_TRNS,
    "gray2.png": GRAY2,
    "interlaced.png": INTERLACED,
    "rgb24.bmp": bmp(3, 2),
    "bottom_up.tga": tga_bottom_up(3, 2),
    "rle_top_down.tga": tga_rle_top_down(),
    "rle.hdr": hdr_rle(),
}

if __name__ == "__main__":
    for name, data in FIXTURES.items():
        with open(os.path.join(HERE, name), "wb") as f:
            f.write(data)
        print(name, len(data), "bytes")
