#!/usr/bin/env python3
"""The census of pbrt-v4's scene collection (github.com/mmp/pbrt-v4-scenes) in candela.

Run on demand, not in CI. It works on a folder that holds the collection's scene texts in their
original layout (this folder, or a checkout of pbrt-v4-scenes whose binary assets may be absent):

  census.py stand-ins DIR [--compress-grids]
      writes a small generated stand-in for every asset the .pbrt files under DIR name and DIR
      lacks: a one-triangle PLY per mesh, a 4x4 PNG or EXR per image, a NanoVDB grid per .nvdb
      (tests/data/vdb/two_grids.nvdb: "density" and "temperature"), a flat spectrum per .spd, an
      empty file per measured .bsdf. With --compress-grids a grid is written as NAME.nvdb.gz (how
      this folder keeps them small; the test inflates them into the build tree).
  census.py run DIR --candela BUILD/candela [--manifest]
      makes the stand-ins, runs `candela convert` on every main file, and prints what candela
      makes of each: its warnings and errors, how many load without a warning, and which warning
      blocks how many files. --manifest prints instead the manifest the collection test reads
      (expected_warnings.txt: regenerate it with `census.py run . --candela ... --manifest`).
  census.py triples DIR
      prints every (directive, type, parameter) that the .pbrt files under DIR use, with the
      number of files each appears in: the list docs/PBRT.md's collection table is written from.

A main file is a .pbrt file with a WorldBegin directive: the scene files one renders. The files
they Include (materials, geometry, instances) have none.
"""
import argparse
import collections
import gzip
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
GRID_FIXTURE = os.path.join(HERE, "..", "vdb", "two_grids.nvdb.gz")

# --- pbrt-v4 tokens -------------------------------------------------------------------------

TOKEN = re.compile(r'"[^"]*"|\[|\]|#[^\n]*|[^\s\[\]"#]+')


def tokens(text):
    """pbrt-v4's tokens, comments dropped."""
    for m in TOKEN.finditer(text):
        t = m.group(0)
        if not t.startswith("#"):
            yield t


DIRECTIVES = set("""Accelerator ActiveTransform AreaLightSource Attribute AttributeBegin AttributeEnd Camera
    ColorSpace ConcatTransform CoordinateSystem CoordSysTransform Film Identity Import Include Integrator
    LightSource LookAt MakeNamedMaterial MakeNamedMedium Material MediumInterface NamedMaterial ObjectBegin
    ObjectEnd ObjectInstance Option PixelFilter ReverseOrientation Rotate Sampler Scale Shape Texture
    Transform TransformBegin TransformEnd TransformTimes Translate WorldBegin WorldEnd""".split())
PARAMETER_TYPES = set("""integer float point2 vector2 point3 vector3 normal normal3 point vector color rgb
    spectrum blackbody bool string texture""".split())


def is_directive(t):
    return t in DIRECTIVES


def directives(text):
    """(name, [arguments]) per directive, arguments as tokens (brackets dropped)."""
    name, args = None, []
    for t in tokens(text):
        if is_directive(t):
            if name:
                yield name, args
            name, args = t, []
        elif t not in "[]":
            args.append(t)
    if name:
        yield name, args


def unquote(t):
    return t[1:-1] if t.startswith('"') else t


def parameters(args):
    """The "type name" parameters of a directive and their values."""
    params, key = {}, None
    for a in args:
        if a.startswith('"') and len(unquote(a).split()) == 2 and unquote(a).split()[0] in PARAMETER_TYPES:
            key = " ".join(unquote(a).split())
            params[key] = []
        elif key:
            params[key].append(unquote(a))
    return params


def pbrt_files(root):
    for folder, _, files in os.walk(root):
        for f in sorted(files):
            if f.endswith(".pbrt"):
                yield os.path.join(folder, f)


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def is_main(path):
    return any(name == "WorldBegin" for name, _ in directives(read(path)))


# --- stand-ins --------------------------------------------------------------------------------


def ply_bytes():
    """One triangle with uv and normals, ascii: every plymesh option has something to read."""
    return (b"ply\nformat ascii 1.0\ncomment candela census stand-in\nelement vertex 3\n"
            b"property float x\nproperty float y\nproperty float z\n"
            b"property float nx\nproperty float ny\nproperty float nz\n"
            b"property float u\nproperty float v\n"
            b"element face 1\nproperty list uchar int vertex_indices\nend_header\n"
            b"0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n0 1 0 0 0 1 0 1\n3 0 1 2\n")


def png_bytes(size=4):
    """An 8-bit RGB PNG of a mid grey."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    rows = b"".join(b"\0" + b"\x80\x80\x80" * size for _ in range(size))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def exr_bytes(size=4, value=0.5):
    """An uncompressed float RGB OpenEXR file, square (pbrt-v4's equal-area maps must be)."""
    def attr(name, kind, data):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(data)) + data
    channels = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    box = struct.pack("<iiii", 0, 0, size - 1, size - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", channels) +
              attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", box) +
              attr("displayWindow", "box2i", box) + attr("lineOrder", "lineOrder", b"\0") +
              attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    line = struct.pack("<%df" % (3 * size), *([value] * (3 * size)))
    chunk_size = 8 + len(line)
    first = len(header) + 8 * size
    offsets = b"".join(struct.pack("<Q", first + y * chunk_size) for y in range(size))
    chunks = b"".join(struct.pack("<ii", y, len(line)) + line for y in range(size))
    return header + offsets + chunks


def grid_bytes():
    with gzip.open(GRID_FIXTURE, "rb") as f:
        return f.read()


def referenced_files(path):
    """(file name, parameter) of every string parameter naming a file in one .pbrt file."""
    for name, args in directives(read(path)):
        if name == "Film":  # its filename is the output
            continue
        for key, values in parameters(args).items():
            ptype, pname = key.split()
            if ptype == "string" and pname in ("filename", "mapname") and values:
                yield values[0], name
            if ptype == "spectrum" and values and values[0].lower().endswith(".spd"):
                yield values[0], name  # a spectrum from a file
        if name in ("Include", "Import") and args:
            yield unquote(args[0]), name


def stand_in(name):
    """The bytes of a stand-in for the asset `name`, or None where there is none to make."""
    lower = name.lower()
    if lower.endswith(".ply"):
        return ply_bytes()
    if lower.endswith(".ply.gz"):
        return gzip.compress(ply_bytes(), mtime=0)
    if lower.endswith((".png", ".jpg", ".jpeg", ".tga", ".bmp")):
        return png_bytes()
    if lower.endswith(".exr"):
        return exr_bytes()
    if lower.endswith(".pfm"):
        return b"PF\n4 4\n-1.0\n" + struct.pack("<48f", *([0.5] * 48))
    if lower.endswith(".spd"):
        return b"400 1\n700 1\n"
    if lower.endswith(".bsdf"):
        return b""
    return None


def make_stand_ins(root, compress_grids=False, log=print):
    """Writes the missing assets; returns the missing .pbrt includes (which need a stand-in
    written by hand from what one can read of the original)."""
    missing_includes = set()
    for path in list(pbrt_files(root)):
        base = os.path.dirname(path)
        for name, directive in referenced_files(path):
            # pbrt-v4 looks beside the including file, then beside the main file; the stand-in
            # goes beside the including file unless it already exists at either place.
            target = os.path.normpath(os.path.join(base, name))
            scene_dir = os.path.join(root, os.path.relpath(path, root).split(os.sep)[0])
            alt = os.path.normpath(os.path.join(scene_dir, name))
            if os.path.exists(target) or os.path.exists(alt) or os.path.exists(target + ".gz"):
                continue
            if directive in ("Include", "Import"):
                missing_includes.add(os.path.relpath(target, root))
                continue
            if name.lower().endswith(".nvdb"):
                data, target = (gzip.compress(grid_bytes(), 9, mtime=0), target + ".gz") if compress_grids \
                    else (grid_bytes(), target)
            else:
                data = stand_in(name)
            if data is None:
                log(f"census: no stand-in for {os.path.relpath(target, root)}")
                continue
            # An asset named relative to the main file's folder (pbrt-v4's fallback) goes there.
            if not os.path.isdir(os.path.dirname(target)) and os.path.isdir(os.path.dirname(alt)):
                target = alt
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with open(target, "wb") as f:
                f.write(data)
    return sorted(missing_includes)


# --- running candela --------------------------------------------------------------------------

# "file:line:col: message", the location perhaps followed by " (included from file:line:col)".
LOCATION = re.compile(r"^\S+:\d+:\d+(?: \(included from [^)]*\))?: (?P<message>.*)$")
FILE_ONLY = re.compile(r"^\S+\.pbrt: (?P<message>.*)$")  # a warning about the whole scene
REPEATS = re.compile(r" \(and \d+ more like (it|them)\)$")


def relative_line(line, root):
    """A warning with its file named relative to the collection's folder."""
    prefix = os.path.abspath(root) + os.sep
    return line.replace(prefix, "")


def kind(warning):
    """A warning without its location and repeat count: what the census table counts."""
    m = LOCATION.match(warning) or FILE_ONLY.match(warning)
    message = m.group("message") if m else warning
    return REPEATS.sub("", message)


def convert(candela, main, out_dir):
    proc = subprocess.run([candela, "convert", main, "-o", os.path.join(out_dir, "scene.json")],
                          capture_output=True, text=True)
    warnings = [l[len("candela: warning: "):] for l in proc.stderr.splitlines()
                if l.startswith("candela: warning: ")]
    errors = [l[len("candela: error: "):] for l in proc.stderr.splitlines() if l.startswith("candela: error: ")]
    if proc.returncode != 0 and not errors:
        errors = [f"exit {proc.returncode}: {proc.stderr.strip()}"]
    return warnings, errors


def stand_in_includes(root, main):
    """The included .pbrt files, followed recursively, that are hand-written stand-ins (their
    first line starts "# STAND-IN"): what candela says of such a main file is partial."""
    found, todo, seen = [], [os.path.join(root, main)], set()
    while todo:
        path = todo.pop()
        if path in seen or not os.path.exists(path):
            continue
        seen.add(path)
        if path.endswith(".gz"):
            with gzip.open(path, "rt", errors="replace") as f:
                text = f.read()
        else:
            text = read(path)
        if path != os.path.join(root, main) and text.startswith("# STAND-IN"):
            found.append(os.path.relpath(path, root))
        for name, args in directives(text):
            if name in ("Include", "Import") and args:
                near = os.path.join(os.path.dirname(path), unquote(args[0]))
                todo.append(near if os.path.exists(near) else os.path.join(root, os.path.dirname(main), unquote(args[0])))
    return sorted(found)


def copy_collection(source, dest):
    """The collection's texts and stand-ins in `dest`, gzip-compressed grids inflated."""
    shutil.copytree(source, dest, ignore=shutil.ignore_patterns("*.py", "*.md", "*.txt"))
    for folder, _, files in os.walk(dest):
        for f in files:
            if f.endswith(".nvdb.gz"):
                with gzip.open(os.path.join(folder, f), "rb") as src, open(os.path.join(folder, f[:-3]), "wb") as dst:
                    shutil.copyfileobj(src, dst)


def run(source, candela, manifest):
    work = tempfile.TemporaryDirectory()
    root = os.path.join(work.name, "scenes")
    copy_collection(os.path.abspath(source), root)
    missing = make_stand_ins(root, log=lambda m: print(m, file=sys.stderr))
    for m in missing:
        print(f"census: missing include {m} (write a stand-in for it)", file=sys.stderr)
    mains = sorted(os.path.relpath(p, root) for p in pbrt_files(root) if is_main(p))
    results = {}
    with tempfile.TemporaryDirectory() as out:
        for rel in mains:
            w, e = convert(candela, os.path.join(root, rel), out)
            results[rel] = ([relative_line(x, root) for x in w], [relative_line(x, root) for x in e])
    if manifest:
        print("# The warnings candela gives on each main file of this folder: the collection test\n"
              "# (tests/formats/pbrt/pbrt_v4_scenes_test.cpp) fails on any other warning and on any\n"
              "# listed here that no longer appears. Regenerate with\n"
              "#   tests/data/pbrt-v4-scenes/census.py run tests/data/pbrt-v4-scenes --candela build/candela --manifest\n"
              "# Each warning must match a row of docs/PBRT.md's \"Remaining in pbrt-v4-scenes\".")
        for rel in mains:
            w, e = results[rel]
            print(f"\n[{rel}]")
            for x in e:
                print(f"error: {x}")
            for x in w:
                print(x)
        return 0
    clean = [rel for rel in mains if not results[rel][0] and not results[rel][1]]
    failed = [rel for rel in mains if results[rel][1]]
    partial = {rel: stand_in_includes(root, rel) for rel in mains}
    for rel in mains:
        w, e = results[rel]
        note = f" (partial: includes stand-ins {', '.join(partial[rel])})" if partial[rel] else ""
        print(f"{rel}: {len(w)} warning(s), {len(e)} error(s){note}")
        for x in e:
            print(f"  error: {x}")
        for x in w:
            print(f"  {x}")
    print(f"\n{len(clean)} of {len(mains)} main files load without a warning; {len(failed)} fail to load; "
          f"{sum(1 for r in mains if partial[r])} include hand-written stand-ins, "
          f"{sum(1 for r in clean if not partial[r])} of the clean ones none.")
    blocking = collections.Counter()
    for rel in mains:
        for k in {kind(x) for x in results[rel][0] + results[rel][1]}:
            blocking[k] += 1
    print("\n| files | warning (or error) |\n| ---: | --- |")
    for k, n in blocking.most_common():
        print(f"| {n} | {k.replace('|', '/')} |")
    return 0


def triples(root):
    seen = collections.defaultdict(set)
    for path in pbrt_files(root):
        rel = os.path.relpath(path, root)
        for name, args in directives(read(path)):
            params = parameters(args)
            kind_ = ""
            if name in ("Shape", "Material", "LightSource", "AreaLightSource", "Film", "Camera", "Sampler",
                        "Integrator", "PixelFilter", "Accelerator", "ColorSpace") and args:
                kind_ = unquote(args[0])
            elif name == "Texture" and len(args) >= 3:
                kind_ = f"{unquote(args[1])} {unquote(args[2])}"
            elif name in ("MakeNamedMaterial", "MakeNamedMedium"):
                kind_ = (params.get("string type") or [""])[0]
            seen[(name, kind_, "")].add(rel)
            for key in params:
                if not (name in ("MakeNamedMaterial", "MakeNamedMedium") and key == "string type"):
                    seen[(name, kind_, key)].add(rel)
    for (d, k, p), files in sorted(seen.items()):
        print(f"{d}\t{k}\t{p}\t{len(files)}")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    s = sub.add_parser("stand-ins")
    s.add_argument("dir")
    s.add_argument("--compress-grids", action="store_true")
    r = sub.add_parser("run")
    r.add_argument("dir")
    r.add_argument("--candela", required=True)
    r.add_argument("--manifest", action="store_true")
    t = sub.add_parser("triples")
    t.add_argument("dir")
    a = ap.parse_args()
    if a.command == "stand-ins":
        for m in make_stand_ins(a.dir, a.compress_grids):
            print(f"census: missing include {m} (write a stand-in for it)")
        return 0
    if a.command == "run":
        return run(a.dir, os.path.abspath(a.candela), a.manifest)
    return triples(a.dir)


if __name__ == "__main__":
    sys.exit(main())
