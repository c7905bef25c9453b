#!/usr/bin/env python3
"""Writes scenes/prism/scene.json and prism.obj: a 60-degree SF11 prism (pbrt-v4's "glass-F11")
in a dark room, lit by a tall white strip far behind a black screen with a slit, at minimum
deviation for the d line (587.6 nm). The camera stands in the dispersed beam and looks back
through the prism: it sees the strip spread into its spectrum (the view through a
spectroscope), and the floor in front of the prism catches the beam's caustic.

Why this composition: a camera path that reaches the strip through the prism is fixed by its
wavelength (two refractions, no random choice), so only the wavelength varies per sample and the
spectrum converges in a few hundred samples. A caustic on a diffuse surface needs the surface's
BSDF sample to pass both refractions and hit a strip of small angular size, which unidirectional
path tracing finds rarely: the floor's rainbow stays grainy (see README.md).

The geometry is worked out in the prism's cross-section (u, v), apex up (+v), light entering the
left face at theta_1 from its normal; the plane is then turned about the vertical (y, the prism's
axis) so that the d line leaves towards -z. Run from anywhere:
    python3 scenes/prism/make_scene.py
"""
import json
import math
import os

APEX = math.radians(60.0)
N_D = 1.78472                                  # SF11's catalogue index at 587.6 nm
THETA_1 = math.asin(N_D * math.sin(APEX / 2))  # minimum deviation: the ray crosses parallel to the base
DEVIATION = 2 * THETA_1 - APEX
SIDE = 1.0            # prism's triangle side
Y0, Y1 = -0.5, 0.7    # the prism stands on the floor at y = Y0
LIGHT_DISTANCE = 4.0  # strip to the entry point, along the beam
STRIP_WIDTH = 0.08    # its angular size from the prism, 0.02 rad, against SF11's ~0.1 rad spread
STRIP_HEIGHT = 2.4
RADIANCE = 60.0
SCREEN_DISTANCE = 0.7  # the black screen's slit, before the entry point
SLIT_WIDTH = 0.16
CAMERA_DISTANCE = 3.0  # camera to the exit point, along the d line's exit direction

exit_angle = THETA_1 - APEX / 2 - DEVIATION
psi = -math.pi / 2 - exit_angle


def world(u, v, y):
    return [round(u * math.cos(psi) - v * math.sin(psi), 6), round(y, 6),
            round(u * math.sin(psi) + v * math.cos(psi), 6)]


def direction(angle):
    return math.cos(angle), math.sin(angle)


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quad(p0, p1, p3, material, **extra):
    """The quad p0, p1, p1 + p3 - p0, p3; its normal is cross(p1 - p0, p3 - p0)."""
    shape = {"type": "quad", "corner": p0, "edge1": [round(x, 6) for x in sub(p1, p0)],
             "edge2": [round(x, 6) for x in sub(p3, p0)], "material": material}
    shape.update(extra)
    return shape


# The triangle, centred on its centroid, apex up.
h = SIDE * math.sqrt(3) / 2
apex = (0.0, 2 * h / 3)
left = (-SIDE / 2, -h / 3)
right = (SIDE / 2, -h / 3)

verts = [world(*apex, Y0), world(*left, Y0), world(*right, Y0),
         world(*apex, Y1), world(*left, Y1), world(*right, Y1)]
centroid = [sum(v[i] for v in verts) / 6 for i in range(3)]
faces = [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)]
obj = ["# scenes/prism/make_scene.py: a 60-degree prism, side %.2f, length %.2f, faces outwards" %
       (SIDE, Y1 - Y0)]
obj += ["v %.6f %.6f %.6f" % tuple(v) for v in verts]
for f in faces:
    a, b, c = (verts[i] for i in f[:3])
    n = cross(sub(b, a), sub(c, a))
    mid = [sum(verts[i][k] for i in f) / len(f) for k in range(3)]
    if sum(n[k] * (mid[k] - centroid[k]) for k in range(3)) < 0:
        f = tuple(reversed(f))
    obj.append("f " + " ".join(str(i + 1) for i in f))

# The d line enters the left face's midpoint and, at minimum deviation, leaves the right face's.
entry = ((apex[0] + left[0]) / 2, (apex[1] + left[1]) / 2)
exit_point = ((apex[0] + right[0]) / 2, (apex[1] + right[1]) / 2)
d_in = direction(THETA_1 - APEX / 2)
across = (-d_in[1], d_in[0])
yc = 0.5 * (Y0 + Y1)


def at(t, s, y):
    """The point t along the incoming beam from the entry point, s across it, at height y."""
    return world(entry[0] + t * d_in[0] + s * across[0], entry[1] + t * d_in[1] + s * across[1], y)


# The strip faces the prism: edge1 x edge2 must point along d_in.
hw, hs = STRIP_WIDTH / 2, STRIP_HEIGHT / 2
strip = quad(at(-LIGHT_DISTANCE, -hw, yc - hs), at(-LIGHT_DISTANCE, -hw, yc + hs),
             at(-LIGHT_DISTANCE, hw, yc - hs), "black", emission=RADIANCE)
# The screen: two black quads either side of the slit, wide and tall enough that the strip
# lights nothing but through the slit.
t, big, sw = -SCREEN_DISTANCE, 6.0, SLIT_WIDTH / 2
screen = [quad(at(t, -big, Y0), at(t, -big, 4.0), at(t, -sw, Y0), "black"),
          quad(at(t, sw, Y0), at(t, sw, 4.0), at(t, big, Y0), "black")]

exit_world = world(*exit_point, yc)
camera_pos = [exit_world[0], yc + 0.45, round(exit_world[2] - CAMERA_DISTANCE, 6)]
look = [exit_world[0], yc - 0.1, exit_world[2]]

scene = {
    "integrator": {"type": "path", "max_depth": 12, "rr_depth": 5, "spectral": True},
    "sampler": {"spp": 1024, "seed": 0},
    "camera": {"type": "perspective", "position": camera_pos, "look_at": look,
               "up": [0, 1, 0], "fov": 30, "resolution": [320, 240]},
    "film": {"filter": "tent", "tonemap": "clamp", "transfer": "srgb"},
    "materials": {
        "floor": {"type": "diffuse", "albedo": 0.6},
        "black": {"type": "diffuse", "albedo": 0.0},
        "sf11": {"type": "dielectric", "ior": {"spectrum": "glass-F11"}},
    },
    "shapes": [
        {"type": "mesh", "file": "prism.obj", "material": "sf11"},
        quad([-8, Y0, 8], [8, Y0, 8], [-8, Y0, -8], "floor"),
        strip,
        # A dim ceiling so that the floor, the screen and the prism's edges can be made out.
        quad([-4, 3.0, -4], [4, 3.0, -4], [-4, 3.0, 4], "black", emission=0.04),
    ] + screen,
}

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "prism.obj"), "w") as f:
    f.write("\n".join(obj) + "\n")
with open(os.path.join(here, "scene.json"), "w") as f:
    f.write(json.dumps(scene, indent=1) + "\n")
print("theta_1 %.2f deg, deviation %.2f deg" % (math.degrees(THETA_1), math.degrees(DEVIATION)))
