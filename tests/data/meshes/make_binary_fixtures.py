#!/usr/bin/env python3
"""Writes the binary PLY fixtures of this folder. Run once from here; the outputs are committed."""
import gzip
import struct

# The cube [-1,1]^3; every face counter-clockwise seen from outside (normal points out).
CUBE_POSITIONS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                  (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
CUBE_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5)]


def header(fmt, elements):
    lines = ["ply", f"format {fmt} 1.0", "comment written by make_binary_fixtures.py"]
    for name, count, props in elements:
        lines.append(f"element {name} {count}")
        lines += [f"property {p}" for p in props]
    lines.append("end_header")
    return ("\n".join(lines) + "\n").encode("ascii")


def cube(endian, coord, count, index):
    codes = {"float": "f", "double": "d", "uchar": "B", "int": "i", "uint": "I"}
    fmt = "binary_little_endian" if endian == "<" else "binary_big_endian"
    out = header(fmt, [("vertex", 8, [f"{coord} x", f"{coord} y", f"{coord} z"]),
                       ("face", 6, [f"list {count} {index} vertex_indices"])])
    for p in CUBE_POSITIONS:
        out += struct.pack(endian + codes[coord] * 3, *p)
    for q in CUBE_QUADS:
        out += struct.pack(endian + codes[count] + codes[index] * 4, 4, *q)
    return out


def extra_elements():
    # A unit square (two triangles) hidden among elements and properties the loader must skip,
    # including lists in the vertex, face and an unrelated element, and the face element first.
    out = header("binary_little_endian", [
        ("camera", 1, ["float view_x", "double view_y", "short flags"]),
        ("face", 2, ["uchar flags", "list uchar int vertex_indices", "list uchar float texcoord"]),
        ("edge", 2, ["int vertex1", "int vertex2", "list ushort uint8 tags"]),
        ("vertex", 4, ["double x", "float confidence", "double y", "double z",
                       "list uint8 int16 weights", "float nx", "float ny", "float nz",
                       "float s", "float t"]),
    ])
    out += struct.pack("<fdh", 1.5, -2.5, 7)
    for tri in [(0, 1, 2), (0, 2, 3)]:
        out += struct.pack("<BB3i", 9, 3, *tri)
        out += struct.pack("<B6f", 6, *([0.25] * 6))
    out += struct.pack("<iiH", 0, 1, 3) + bytes([1, 2, 3])
    out += struct.pack("<iiH", 1, 2, 0)
    square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    for i, (x, y) in enumerate(square):
        out += struct.pack("<dfdd", x, 0.5, y, 0.0)
        out += struct.pack("<B", i) + struct.pack(f"<{i}h", *range(i))
        out += struct.pack("<3f", 0, 0, 1) + struct.pack("<2f", x * 0.5, y * 0.5)
    return out


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


write("cube.ply", cube("<", "float", "uchar", "int"))
write("cube_big_endian.ply", cube(">", "double", "uint", "uint"))
write("extra_elements_binary.ply", extra_elements())
full = cube("<", "float", "uchar", "int")
write("truncated_binary.ply", full[:len(full) - 40])  # ends inside the face records
# gzip-compressed, as pbrt-v4 scenes ship meshes; mtime 0 keeps the bytes the same at every run.
write("cube.ply.gz", gzip.compress(full, compresslevel=9, mtime=0))
