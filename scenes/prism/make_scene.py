#!/usr/bin/env python3
"""Writes scenes/prism/scene.json: a 60-degree SF11 prism (pbrt-v4's "glass-F11") lit through a
slit at minimum deviation for the d line, throwing its spectrum on a white wall in a dark room.

The geometry is worked out in the prism's cross-section (u, v), apex up (+v), light entering the
left face at theta_1 from its normal; the plane is then turned about the vertical (y, the prism's
axis) so that the d line leaves towards the wall (-z). Run from anywhere:
    python3 scenes/prism/make_scene.py
"""
import json
import math
import os

APEX = math.radians(60.0)
N_D = 1.78472                                  # SF11's catalogue index at 587.6 nm
THETA_1 = math.asin(N_D * math.sin(APEX / 2))  # minimum deviation: the ray crosses parallel to the base
DEVIATION = 2 * THETA_1 - APEX
SIDE = 1.2           # prism's triangle side
HALF_HEIGHT = 0.6    # prism's half length along y (it stands on the floor at y = -0.6)
LIGHT_DISTANCE = 0.6  # slit centre to the entry point
SLIT_WIDTH = 0.06     # across the beam: the spectrum's blur is SLIT_WIDTH / LIGHT_DISTANCE radians
SLIT_HEIGHT = 1.0
RADIANCE = 400.0
WALL_Z = -1.4

# The exit direction of the d line in (u, v) is at angle THETA_1 - APEX/2 - DEVIATION; turn (u, v)
# so that it becomes -z in (x, z).
exit_angle = THETA_1 - APEX / 2 - DEVIATION
psi = -math.pi / 2 - exit_angle


def world(u, v, y):
    return [round(u * math.cos(psi) - v * math.sin(psi), 6), round(y, 6),
            round(u * math.sin(psi) + v * math.cos(psi), 6)]


def direction(angle):
    return math.cos(angle), math.sin(angle)


# The triangle, centred on its centroid, apex up.
h = SIDE * math.sqrt(3) / 2
apex = (0.0, 2 * h / 3)
left = (-SIDE / 2, -h / 3)
right = (SIDE / 2, -h / 3)
y0 = -0.6
y1 = y0 + 2 * HALF_HEIGHT


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def quad(p0, p1, p3, material, **extra):
    """The quad p0, p1, p0 + (p3 - p0) + (p1 - p0), p3; its normal is cross(p1 - p0, p3 - p0)."""
    shape = {"type": "quad", "corner": p0, "edge1": [round(x, 6) for x in sub(p1, p0)],
             "edge2": [round(x, 6) for x in sub(p3, p0)], "material": material}
    shape.update(extra)
    return shape


# Prism: three side quads and two triangular caps as an OBJ (faces outwards).
verts = [world(*apex, y0), world(*left, y0), world(*right, y0),
         world(*apex, y1), world(*left, y1), world(*right, y1)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


centroid = [sum(v[i] for v in verts) / 6 for i in range(3)]
faces = [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)]
obj = ["# scenes/prism/make_scene.py: a 60-degree prism, side %.2f, length %.2f, faces outwards" %
       (SIDE, 2 * HALF_HEIGHT)]
obj += ["v %.6f %.6f %.6f" % tuple(v) for v in verts]
for f in faces:
    a, b, c = (verts[i] for i in f[:3])
    n = cross(sub(b, a), sub(c, a))
    mid = [sum(verts[i][k] for i in f) / len(f) for k in range(3)]
    if sum(n[k] * (mid[k] - centroid[k]) for k in range(3)) < 0:
        f = tuple(reversed(f))
    obj.append("f " + " ".join(str(i + 1) for i in f))

# The slit: an emitter facing the entry point (the left face's midpoint) along the incoming ray,
# inside a black tube that keeps its light off the wall except through the prism.
entry = ((apex[0] + left[0]) / 2, (apex[1] + left[1]) / 2)
d_in = direction(THETA_1 - APEX / 2)
across = (-d_in[1], d_in[0])
c = (entry[0] - LIGHT_DISTANCE * d_in[0], entry[1] - LIGHT_DISTANCE * d_in[1])
yc = 0.0


def at(t, s, y):
    """The point t along the beam from the slit, s across it, at height y."""
    return world(c[0] + t * d_in[0] + s * across[0], c[1] + t * d_in[1] + s * across[1], y)


hw, hs = SLIT_WIDTH / 2, SLIT_HEIGHT / 2
# Emits towards +t: edge1 x edge2 must point along d_in.
light = quad(at(0, -hw, yc - hs), at(0, -hw, yc + hs), at(0, hw, yc - hs), "black",
             emission=RADIANCE)
tube_length = LIGHT_DISTANCE - 0.25
tw, th = 0.12, hs + 0.02
tube = [
    quad(at(-0.01, -tw, yc - th), at(tube_length, -tw, yc - th), at(-0.01, -tw, yc + th), "black"),
    quad(at(-0.01, tw, yc - th), at(-0.01, tw, yc + th), at(tube_length, tw, yc - th), "black"),
    quad(at(-0.01, -tw, yc + th), at(tube_length, -tw, yc + th), at(-0.01, tw, yc + th), "black"),
    quad(at(-0.01, -tw, yc - th), at(-0.01, tw, yc - th), at(tube_length, -tw, yc - th), "black"),
    quad(at(-0.02, -tw, yc - th), at(-0.02, -tw, yc + th), at(-0.02, tw, yc - th), "black"),
]

scene = {
    "integrator": {"type": "path", "max_depth": 16, "rr_depth": 5, "spectral": True},
    "sampler": {"spp": 1024, "seed": 0},
    "camera": {"type": "perspective", "position": [1.2, 1.0, 2.2], "look_at": [0.0, -0.1, -0.8],
               "up": [0, 1, 0], "fov": 45, "resolution": [320, 240]},
    "film": {"filter": "tent", "tonemap": "clamp", "transfer": "srgb"},
    "materials": {
        "wall": {"type": "diffuse", "albedo": 0.8},
        "floor": {"type": "diffuse", "albedo": 0.25},
        "black": {"type": "diffuse", "albedo": 0.0},
        "sf11": {"type": "dielectric", "ior": {"spectrum": "glass-F11"}},
    },
    "shapes": [
        {"type": "mesh", "file": "prism.obj", "material": "sf11"},
        quad([-6, -0.6, 4], [6, -0.6, 4], [-6, -0.6, WALL_Z], "floor"),
        quad([-6, -0.6, WALL_Z], [6, -0.6, WALL_Z], [-6, 4, WALL_Z], "wall"),
        light,
    ] + tube,
}

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "prism.obj"), "w") as f:
    f.write("\n".join(obj) + "\n")
with open(os.path.join(here, "scene.json"), "w") as f:
    f.write(json.dumps(scene, indent=1) + "\n")
print("theta_1 %.2f deg, deviation %.2f deg" % (math.degrees(THETA_1), math.degrees(DEVIATION)))
