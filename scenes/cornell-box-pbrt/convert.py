#!/usr/bin/env python3
"""Writes scene.json and meshes/*.obj from Bitterli's pbrt-v4 export of the Cornell box.

Usage: python3 convert.py PATH/TO/pbrt-v4/cornell-box/scene-v4.pbrt

A converter for this one file (its directives only), not a pbrt reader: candela's own pbrt-v4
import is issue 15. Every number comes from the file, and the mesh files repeat its numbers
character for character (positions, normals, uvs), so that candela and pbrt-v4 round the same
decimals to the same floats. What is not in the file, or is changed, is said here and in
README.md:
- resolution 256x256 instead of the file's 1024x1024: the size of pbrt-v4's reference render
  (refs/pbrt-v4 in the shared folder), at 256 spp as its scenes.txt says (the file says 64; the
  reference was made with --spp 2048);
- Russian roulette from the second bounce on (`rr_depth` 1), which is pbrt-v4's rule
  (PathIntegrator::Li cuts only when depth > 1), with the survival probability pbrt-v4 uses (the
  throughput's largest component, refraction's scaling taken out), candela's default;
- pbrt's `fov` spans the shorter image axis: `fov_axis` "smaller".
pbrt's camera shows camera-space +x on the image's right; candela's image right is forward x up.
Bitterli's camera transform has determinant -1, which makes the two agree, so nothing is mirrored
(the converter stops if they disagree rather than render a mirror image).
"""
import json, re, sys
from pathlib import Path

here = Path(__file__).resolve().parent
source = Path(sys.argv[1])
tokens = re.findall(r'"[^"]*"|\[|\]|[^\s\[\]"]+', re.sub(r'#[^\n]*', '', source.read_text()))
RESOLUTION, SPP, RR_DEPTH = [256, 256], 256, 1

i = 0
def values():
    """The bracketed list (or single value) at tokens[i], as the file spells it."""
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
    """The `"type name" [values]` pairs that follow a directive."""
    global i
    out = {}
    while i < len(tokens) and tokens[i].startswith('"') and ' ' in tokens[i]:
        name = tokens[i].strip('"').split()[1]
        i += 1
        out[name] = values()
    return out

def number(text):
    x = float(text)
    return int(x) if x.is_integer() else x

camera_from_world = None
settings, materials, shapes, stack = {}, {}, [], []
current = area = None
while i < len(tokens):
    t = tokens[i]; i += 1
    if t == 'Transform':
        v = [float(x) for x in values()]
        assert camera_from_world is None, "only the camera's Transform is expected"
        camera_from_world = [[v[c * 4 + r] for c in range(4)] for r in range(4)]  # pbrt lists columns
    elif t in ('Integrator', 'Sampler', 'PixelFilter', 'Film', 'Camera'):
        settings[t] = (values()[0], params())
    elif t == 'WorldBegin':
        pass
    elif t == 'MakeNamedMaterial':
        name = values()[0]
        materials[name] = params()
    elif t == 'NamedMaterial':
        current = values()[0]
    elif t == 'AttributeBegin':
        stack.append((current, area))
    elif t == 'AttributeEnd':
        current, area = stack.pop()
    elif t == 'AreaLightSource':
        kind = values()[0]; p = params()
        assert kind == 'diffuse' and 'filename' not in p and 'power' not in p
        scale = float(p.get('scale', ['1'])[0])
        area = {"emission": [number(x) if scale == 1 else float(x) * scale for x in p['L']],
                "two_sided": p.get('twosided', ['false'])[0] == 'true'}
    elif t == 'Shape':
        kind = values()[0]; p = params()
        assert kind == 'trianglemesh', kind
        name = f"meshes/{current.lower()}.obj"
        P, N, uv, idx = p['P'], p['N'], p['uv'], [int(x) for x in p['indices']]
        with open(here / name, 'w') as f:
            f.write(f"# from {source.name} (Bitterli, CC0): the trianglemesh of {current}, numbers as written there\n")
            for k in range(0, len(P), 3): f.write(f"v {P[k]} {P[k+1]} {P[k+2]}\n")
            for k in range(0, len(uv), 2): f.write(f"vt {uv[k]} {uv[k+1]}\n")
            for k in range(0, len(N), 3): f.write(f"vn {N[k]} {N[k+1]} {N[k+2]}\n")
            for k in range(0, len(idx), 3):
                a, b, c = (x + 1 for x in idx[k:k + 3])
                f.write(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}\n")
        shapes.append({"type": "mesh", "file": name, "material": current, **(area or {})})
    else:
        sys.exit(f"convert.py: directive {t} is not handled")

def solve(m, rhs):
    """x with m x = rhs for the upper-left 3x3 of m (Cramer's rule)."""
    det = lambda a: (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                     + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    a = [row[:3] for row in m[:3]]
    d = det(a)
    return [det([[rhs[r] if c == k else a[r][c] for c in range(3)] for r in range(3)]) / d for k in range(3)]

m = camera_from_world
pos = solve(m, [-m[0][3], -m[1][3], -m[2][3]])  # the point camera_from_world maps to the origin
fwd, up, right = solve(m, [0, 0, 1]), solve(m, [0, 1, 0]), solve(m, [1, 0, 0])
cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
if sum(x * y for x, y in zip(cross(fwd, up), right)) < 0:
    sys.exit("convert.py: this camera would show a mirror image in candela; mirror the scene in x first")
r6 = lambda v: [number(f"{x:.6g}") + 0 for x in v]

integrator, ip = settings['Integrator']
sampler, sp = settings['Sampler']
pixel_filter, fp = settings['PixelFilter']
camera, cp = settings['Camera']
assert integrator == 'path' and sampler == 'sobol' and camera == 'perspective'
assert pixel_filter == 'triangle' and fp['xradius'] == ['1'] and fp['yradius'] == ['1'], "candela's tent has radius 1"

def material(p):
    assert p['type'] == ['diffuse'] and set(p) == {'type', 'reflectance'}
    return {"type": "diffuse", "albedo": [number(x) for x in p['reflectance']]}

scene = {
    "integrator": {"type": "path", "max_depth": int(ip['maxdepth'][0]), "rr_depth": RR_DEPTH},
    "sampler": {"type": "sobol", "spp": SPP, "seed": 0},
    "camera": {"type": "perspective", "position": r6(pos), "look_at": r6([p + f for p, f in zip(pos, fwd)]),
               "up": r6(up), "fov": number(cp['fov'][0]), "fov_axis": "smaller", "resolution": RESOLUTION},
    "film": {"filter": "tent"},
    "materials": {k: material(v) for k, v in materials.items()},
    "shapes": shapes,
}
text = json.dumps(scene, indent=2)
# Short arrays of numbers on one line, as the other example scenes write them.
text = re.sub(r'\[\s+([-0-9.e,\s]+?)\s+\]', lambda g: '[' + ', '.join(g.group(1).split()).replace(',,', ',') + ']', text)
(here / "scene.json").write_text(text + "\n")
print(f"wrote scene.json with {len(shapes)} shapes")
