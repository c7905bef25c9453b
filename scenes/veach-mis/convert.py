#!/usr/bin/env python3
"""Writes scene.json and meshes/*.obj from Bitterli's pbrt-v4 export of Veach's MIS scene.

Usage: python3 convert.py PATH/TO/veach-mis/scene-v4.pbrt

A converter for this one file (its directives only), not a pbrt reader: candela's own pbrt-v4
import is issue 15. pbrt's camera shows camera-space +x on the image's right, +y up, looking along +z;
candela's image right is forward x up. Where the camera transform makes the two disagree, the
whole scene is mirrored in world x (scale -1) so that the image shows what pbrt-v4 shows, not its
mirror image (candela keeps front faces under a mirror itself: DESIGN.md). This file's camera
transform has determinant -1 (Bitterli's exports carry the flip), so it needs no mirror.
"""
import json, math, re, sys
from pathlib import Path

text = Path(sys.argv[1]).read_text()
here = Path(__file__).resolve().parent
tokens = re.findall(r'"[^"]*"|\[|\]|[^\s\[\]"]+', re.sub(r'#[^\n]*', '', text))

def mat_inverse(m):  # 4x4 row-major, general inverse by Gauss-Jordan
    a = [row[:] + [1.0 if i == j else 0.0 for j in range(4)] for i, row in enumerate(m)]
    for c in range(4):
        p = max(range(c, 4), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        piv = a[c][c]
        a[c] = [x / piv for x in a[c]]
        for r in range(4):
            if r != c:
                f = a[r][c]
                a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return [row[4:] for row in a]

def apply(m, v, w):
    return [sum(m[i][j] * (v[j] if j < 3 else w) for j in range(4)) for i in range(3)]

i = 0
def values():
    """The bracketed list (or single value) at tokens[i]."""
    global i
    if tokens[i] == '[':
        j = tokens.index(']', i)
        out = tokens[i + 1:j]
        i = j + 1
    else:
        out = [tokens[i]]
        i += 1
    return [x.strip('"') for x in out]

def params():
    global i
    out = {}
    while i < len(tokens) and tokens[i].startswith('"') and ' ' in tokens[i]:
        ty, name = tokens[i].strip('"').split()
        i += 1
        out[name] = (ty, values())
    return out

camera = None
materials, shapes, current, area, xform = {}, [], None, None, None
stack = []
mesh_count = 0
while i < len(tokens):
    t = tokens[i]; i += 1
    if t == 'Transform':
        v = [float(x) for x in values()]
        xform = [[v[c * 4 + r] for c in range(4)] for r in range(4)]  # pbrt lists columns
        if camera is None and not materials: camera_from_world = xform
    elif t == 'Camera':
        i += 1; p = params(); fov = float(p['fov'][1][0])
        camera = True
    elif t in ('Integrator', 'Sampler', 'PixelFilter', 'Film'):
        i += 1; params()
    elif t == 'MakeNamedMaterial':
        name = values()[0]; p = params()
        materials[name] = p
    elif t == 'NamedMaterial':
        current = values()[0]
    elif t == 'AttributeBegin':
        stack.append((current, area, xform))
    elif t == 'AttributeEnd':
        current, area, xform = stack.pop()
    elif t == 'AreaLightSource':
        i += 1; p = params(); area = [float(x) for x in p['L'][1]]
    elif t == 'Shape':
        kind = values()[0]; p = params()
        if kind == 'sphere':
            c = [xform[0][3], xform[1][3], xform[2][3]]
            shapes.append({"type": "sphere", "center": c,
                           "radius": float(p['radius'][1][0]), "material": current,
                           **({"emission": area} if area else {})})
        else:
            P = [float(x) for x in p['P'][1]]; N = [float(x) for x in p['N'][1]]
            uv = [float(x) for x in p['uv'][1]]; idx = [int(x) for x in p['indices'][1]]
            mesh_count += 1
            name = f"meshes/{current.lower()}_{mesh_count}.obj"
            with open(here / name, 'w') as f:
                f.write(f"# from {Path(sys.argv[1]).name} (Bitterli, CC0), shape {mesh_count}\n")
                for k in range(0, len(P), 3): f.write(f"v {P[k]} {P[k+1]} {P[k+2]}\n")
                for k in range(0, len(uv), 2): f.write(f"vt {uv[k]} {uv[k+1]}\n")
                for k in range(0, len(N), 3): f.write(f"vn {N[k]} {N[k+1]} {N[k+2]}\n")
                for k in range(0, len(idx), 3):
                    a, b, c = (x + 1 for x in idx[k:k + 3])
                    f.write(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}\n")
            shapes.append({"type": "mesh", "file": name, "material": current})

world_from_camera = mat_inverse(camera_from_world)
pos = apply(world_from_camera, [0, 0, 0], 1)
fwd = apply(world_from_camera, [0, 0, 1], 0)
up = apply(world_from_camera, [0, 1, 0], 0)
mirror = lambda v: [-v[0], v[1], v[2]]
r6 = lambda v: [round(x, 6) + 0.0 for x in v]
right = apply(world_from_camera, [1, 0, 0], 0)
cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
mirrored = sum(x * y for x, y in zip(cross(fwd, up), right)) < 0
if mirrored:
    pos, fwd, up = mirror(pos), mirror(fwd), mirror(up)
    for s in shapes:
        if s["type"] == "sphere": s["center"] = mirror(s["center"])
        else: s["transform"] = [{"scale": [-1, 1, 1]}]

def material(p):
    if p['type'][1][0] == 'diffuse':
        return {"type": "diffuse", "albedo": [float(x) for x in p['reflectance'][1]]}
    return {"type": "conductor", "eta": [float(x) for x in p['eta'][1]],
            "k": [float(x) for x in p['k'][1]], "roughness": float(p['uroughness'][1][0])}

scene = {
    "integrator": {"type": "path", "max_depth": 3},
    "sampler": {"spp": 256, "seed": 0},
    "camera": {"position": r6(pos), "look_at": r6([p + f for p, f in zip(pos, fwd)]),
               "up": r6(up), "fov": fov, "resolution": [640, 360]},
    "film": {"filter": "tent"},
    "materials": {k: material(v) for k, v in materials.items()},
    "shapes": shapes,
}
text = json.dumps(scene, indent=2)
# Short arrays of numbers on one line, as the other example scenes write them.
text = re.sub(r'\[\s+([-0-9.e,\s]+?)\s+\]', lambda m: '[' + ', '.join(m.group(1).split()).replace(',,', ',') + ']', text)
(here / "scene.json").write_text(text + "\n")
print(f"wrote scene.json with {len(shapes)} shapes")
