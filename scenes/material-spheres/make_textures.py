#!/usr/bin/env python3
"""Writes the two textures of this scene, so that nothing in it is a binary of unknown origin:
tiles.png (sRGB albedo: warm tiles with darker grout) and tiles_normal.png (a tangent-space normal
map, OpenGL convention: +y = +v; each tile a bevelled dome, the grout flat), both 256x256.

Usage: python3 make_textures.py   (writes beside this file)
"""
import math, struct, zlib
from pathlib import Path

N, TILES, GROUT = 256, 4, 0.06

def png(path, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", N, N, 8, 2, 0, 0, 0))
    data += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    Path(path).write_bytes(data)

def height(u, v):
    """Height of the tile surface at (u, v) in [0, 1)^2: 0 in the grout, a rounded bevel to 1."""
    fu, fv = (u * TILES) % 1.0, (v * TILES) % 1.0
    edge = min(fu, 1 - fu, fv, 1 - fv)
    if edge < GROUT: return 0.0
    return min(1.0, (edge - GROUT) / 0.12) ** 0.5

albedo, normal = [], []
for y in range(N):
    v = 1.0 - (y + 0.5) / N  # row 0 is the top of the image: v = 1 (v grows upward)
    arow, nrow = [], []
    for x in range(N):
        u = (x + 0.5) / N
        tile = (int(u * TILES) * 7 + int(v * TILES) * 3) % 5
        h = height(u, v)
        c = [0.55 + 0.06 * tile, 0.32 + 0.03 * tile, 0.2] if h > 0 else [0.12, 0.11, 0.1]
        arow += [round(255 * ch ** (1 / 2.2)) for ch in c]
        d = 0.5 / N
        dhdu = (height(u + d, v) - height(u - d, v)) / (2 * d) * 0.02
        dhdv = (height(u, v + d) - height(u, v - d)) / (2 * d) * 0.02
        n = [-dhdu, -dhdv, 1.0]
        l = math.sqrt(sum(a * a for a in n))
        nrow += [round(255 * (0.5 + 0.5 * a / l)) for a in n]
    albedo.append(arow); normal.append(nrow)
here = Path(__file__).resolve().parent
png(here / "tiles.png", albedo)
png(here / "tiles_normal.png", normal)
print("wrote tiles.png, tiles_normal.png")
