#!/usr/bin/env python3
"""Writes the files of this corpus that are binary, large, or hold bytes an editor would change
(NUL, invalid UTF-8, a raw tab in a string). Run once from here; the outputs are committed.
The scenes that reference them, and every other file here, are plain text kept by hand."""
import gzip
import struct

DEPTH = 100000  # deep enough to overflow any recursive reader's stack


def write(name, data):
    with open(name, "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


# --- JSON: nesting, encodings, control characters
write("deep_nesting_arrays.json", '{"camera": {"position": ' + "[" * DEPTH + "]" * DEPTH + "}}\n")
write("deep_nesting_unclosed.json", "[" * DEPTH)
# The error locator must walk through the deep array to find the repeated key after it.
write("deep_nesting_then_duplicate_key.json",
      '{"film": {"filter": "box"},\n "extra": ' + "[" * DEPTH + "]" * DEPTH + ',\n "film": {}}\n')
write("non_utf8_name.json", b'{\n  "materials": {"r\xe9d": {"type": "diffuse"}}\n}\n')  # Latin-1
write("utf16_file.json", '{"sampler": {"spp": 4}}\n'.encode("utf-16"))  # with a byte order mark
write("control_character_in_string.json", '{\n  "materials": {"a\tb": {"type": "diffuse"}}\n}\n')


# --- PLY
def ply_header(fmt, elements):
    lines = ["ply", f"format {fmt} 1.0"]
    for name, count, props in elements:
        lines.append(f"element {name} {count}")
        lines += [f"property {p}" for p in props]
    lines.append("end_header")
    return ("\n".join(lines) + "\n").encode("ascii")


XYZ = ["float x", "float y", "float z"]
FACE = ["list uchar int vertex_indices"]
TRIANGLE = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)


def triangle_ply(vertex_count=3, face_count=1, vertices=TRIANGLE, faces=struct.pack("<B3i", 3, 0, 1, 2),
                 face_props=FACE):
    return ply_header("binary_little_endian", [("vertex", vertex_count, XYZ),
                                               ("face", face_count, face_props)]) + vertices + faces


full = triangle_ply()
write("ply_truncated_binary.ply", full[:len(full) - 6])  # ends inside the face record
write("ply_index_out_of_range.ply", triangle_ply(faces=struct.pack("<B3i", 3, 0, 1, 7)))
write("ply_negative_index.ply", triangle_ply(faces=struct.pack("<B3i", 3, 0, -1, 2)))
write("ply_nan_position.ply", triangle_ply(vertices=struct.pack("<9f", 0, 0, 0, float("nan"), 0, 0, 0, 1, 0)))
# Counts no 200-byte file can hold: refused from the file's size before anything is allocated.
write("ply_absurd_vertex_count.ply", triangle_ply(vertex_count=4000000000))
write("ply_absurd_face_count.ply", triangle_ply(face_count=10**10))
write("ply_vertex_count_beyond_index.ply", triangle_ply(vertex_count=10**12))
write("ply_absurd_list_length.ply", triangle_ply(faces=struct.pack("<I3i", 4000000000, 0, 1, 2),
                                                 face_props=["list uint int vertex_indices"]))
write("ply_two_corner_face.ply", triangle_ply(faces=struct.pack("<B2i", 2, 0, 1)))
# A gzip-compressed PLY cut off inside its compressed data (mtime 0: the same bytes every run).
write("ply_gz_truncated.ply.gz", gzip.compress(triangle_ply(), mtime=0)[:30])
write("mesh_binary_garbage.obj", bytes(range(256)) * 2)
write("mesh_empty.obj", b"")
write("mesh_empty.ply", b"")

# --- Radiance HDR
HDR_HEAD = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n"
write("hdr_empty.hdr", b"")
write("hdr_bad_magic.hdr", b"P6\n2 1\n255\n" + bytes(6))
write("hdr_truncated_header.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")
write("hdr_bad_resolution_line.hdr", HDR_HEAD + b"+X 2 -Y 1\n" + bytes(8))
write("hdr_zero_size.hdr", HDR_HEAD + b"-Y 0 +X 2\n")
write("hdr_truncated_data.hdr", HDR_HEAD + b"-Y 2 +X 4\n" + b"\x10\x10\x10\x80" * 5)
# 65536x4096 (2^28 pixels, the most read_image accepts: 3 GiB as floats) in 60 bytes.
write("hdr_absurd_size.hdr", HDR_HEAD + b"-Y 4096 +X 65536\n" + bytes(8))
write("hdr_black.hdr", HDR_HEAD + b"-Y 1 +X 2\n" + bytes(8))


# --- OpenEXR: a scanline file of one float channel Y, written attribute by attribute.
def exr(width, height, compression, table, chunks):
    def attr(name, kind, data):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data
    channels = b"Y\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1) + b"\0"  # 2: FLOAT
    window = struct.pack("<4i", 0, 0, width - 1, height - 1)
    header = b"\x76\x2f\x31\x01" + struct.pack("<I", 2)
    header += attr("channels", "chlist", channels)
    header += attr("compression", "compression", bytes([compression]))
    header += attr("dataWindow", "box2i", window) + attr("displayWindow", "box2i", window)
    header += attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1))
    header += attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
    header += attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0"
    return header, table, chunks


def scanlines(width, height, written):
    """Uncompressed rows (one per chunk); only the first `written` rows' data is present."""
    head, _, _ = exr(width, height, 0, b"", b"")
    first = len(head) + 8 * height
    table = b"".join(struct.pack("<Q", first + y * (8 + 4 * width)) for y in range(height))
    rows = b"".join(struct.pack("<ii", y, 4 * width) + struct.pack(f"<{width}f", *([0.5] * width))
                    for y in range(written))
    return head + table + rows


write("exr_empty.exr", b"")
write("exr_bad_magic.exr", b"\x89PNG\r\n\x1a\n" + bytes(40))
write("exr_truncated_header.exr", scanlines(4, 2, 2)[:60])
write("exr_truncated_data.exr", scanlines(4, 2, 1))
# 16384x16384 (2^28 pixels) with a complete table of ZIP chunks (16 rows each) but no pixel data:
# 8 KiB that would have had us allocate 3 GiB before finding the data missing.
head, _, _ = exr(16384, 16384, 3, b"", b"")
write("exr_absurd_size.exr", head + b"".join(struct.pack("<Q", len(head) + 8 * 1024 + 8 * i) for i in range(1024)))

# --- pbrt-v4: a binary file given as the scene; a gzip-compressed include with an error on line 3
write("pbrt_binary_scene.pbrt", b"\x89PNG\r\n\x1a\n" + bytes(range(64)))
write("pbrt_gzip_include_error_geometry.pbrt.gz",
      gzip.compress(b'# gzip-compressed: a sphere with a misspelt type on line 3.\nAttributeBegin\n'
                    b'Shape "sphere" "flaot radius" 1\nAttributeEnd\n', mtime=0))
