#!/usr/bin/env python3
"""Writes terrains/heightmaps/dunes.png: a 16-bit grayscale heightmap of gentle dunes (standard
library only). Row 0 is the largest y. Usage: python3 tools/make-dunes.py [OUT]"""
import math, struct, sys, zlib

W, H = 161, 101
def height(c, r):
    x, y = c / (W - 1), 1 - r / (H - 1)
    v = 0.5 + 0.3 * math.sin(2 * math.pi * (1.7 * x + 0.4 * y)) + 0.2 * math.cos(2 * math.pi * (0.6 * x - 1.3 * y))
    return max(0.0, min(1.0, v))

raw = b"".join(b"\0" + b"".join(struct.pack(">H", round(65535 * height(c, r))) for c in range(W)) for r in range(H))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 16, 0, 0, 0, 0)) \
    + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
out = sys.argv[1] if len(sys.argv) > 1 else "terrains/heightmaps/dunes.png"
open(out, "wb").write(png)
