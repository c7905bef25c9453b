#!/usr/bin/env python3
"""Writes a pbrt-v4 scene of N hairs (cubic Bezier curves, width 0.004 to 0.001) on a ball of
radius 0.5, for measuring how candela loads, holds and traces many curves (bench/RESULTS.md):

    bench/hair/make_hair.py 1000000 /tmp/hair1m.pbrt       # 170 MB of text
    /usr/bin/time -v build/candela render /tmp/hair1m.pbrt --spp 4 --resolution 256x256 -o /tmp/h.png
    /usr/bin/time -v pbrt --nthreads 2 --outfile /tmp/h.exr /tmp/hair1m.pbrt

The hairs are random (seed 1), so the file is the same on every run."""
import math
import random
import sys

count, path = int(sys.argv[1]), sys.argv[2]
random.seed(1)
with open(path, "w") as out:
    out.write('LookAt 0 0.5 -3  0 0.5 0  0 1 0\nCamera "perspective" "float fov" 40\n'
              'Film "rgb" "integer xresolution" 256 "integer yresolution" 256\n'
              'Sampler "independent" "integer pixelsamples" 4\nWorldBegin\n'
              'LightSource "infinite" "rgb L" [1 1 1]\nMaterial "diffuse" "rgb reflectance" [0.4 0.3 0.2]\n')
    for _ in range(count):
        theta, phi = random.random() * 2 * math.pi, math.acos(2 * random.random() - 1)
        x, y, z = math.sin(phi) * math.cos(theta), math.cos(phi), math.sin(phi) * math.sin(theta)
        root = (0.5 * x, 0.5 * y + 0.5, 0.5 * z)
        length = 0.25
        points = [(root[0] + x * length * k / 3 + 0.02 * k * k * random.random(),
                   root[1] + y * length * k / 3 - 0.03 * k * k, root[2] + z * length * k / 3) for k in range(4)]
        out.write('Shape "curve" "point3 P" [%s] "float width0" 0.004 "float width1" 0.001\n' %
                  " ".join("%.5f %.5f %.5f" % p for p in points))
