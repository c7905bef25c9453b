#!/usr/bin/env python3
"""Writes hair-curves.pbrt.gz, the curves of scenes/hair/hair.pbrt (run from this folder):
a tuft of dark hair (cylinder curves, eumelanin), a tuft of blond hair (cylinder curves, the
`reflectance` parameterisation), both cubic Bezier, and a row of grass blades (ribbon curves with
normals), 3,200 curves in all. Random with seed 3 and gzip's mtime 0, so the file is the same on
every run."""
import gzip
import math
import random

random.seed(3)
lines = ["# Written by make_hair.py: 3,200 curves. Included by hair.pbrt."]


def tuft(cx, material, count, lean):
    lines.append('NamedMaterial "%s"' % material)
    for _ in range(count):
        a = random.random() * 2 * math.pi
        r = 0.35 * math.sqrt(random.random())
        x, z = cx + r * math.cos(a), r * math.sin(a)
        h = 1.6 + 0.3 * random.random()
        bend = lean + 0.25 * (random.random() - 0.5)
        pts = [(x + bend * (k / 3) ** 2 + 0.05 * r * math.cos(a) * k, -0.5 + h * k / 3,
                z + 0.05 * r * math.sin(a) * k + 0.1 * (random.random() - 0.5) * k / 3) for k in range(4)]
        lines.append('Shape "curve" "string type" "cylinder" "point3 P" [%s] "float width0" 0.012 "float width1" 0.004'
                     % " ".join("%.4f %.4f %.4f" % p for p in pts))


tuft(-0.55, "dark", 1500, -0.3)
tuft(0.55, "blond", 1500, 0.3)
lines.append('NamedMaterial "grass"')
for i in range(200):
    x = -1.5 + 3.0 * i / 199 + 0.01 * random.random()
    z = -0.7 + 0.1 * random.random()
    h = 0.4 + 0.3 * random.random()
    tilt = 0.2 * (random.random() - 0.5)
    pts = [(x + tilt * k / 3, -0.5 + h * k / 3, z + 0.05 * (k / 3) ** 2) for k in range(4)]
    twist = random.random() * 0.8
    lines.append('Shape "curve" "string type" "ribbon" "point3 P" [%s] "normal N" [0 0 -1 %.3f 0 -1] '
                 '"float width0" 0.04 "float width1" 0.005' % (" ".join("%.4f %.4f %.4f" % p for p in pts), twist))
with gzip.GzipFile("hair-curves.pbrt.gz", "wb", mtime=0) as out:
    out.write(("\n".join(lines) + "\n").encode())
