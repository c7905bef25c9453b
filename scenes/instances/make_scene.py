#!/usr/bin/env python3
"""Writes scene.json: a forest of 400 instanced trees on a meadow (docs/SCENE_FORMAT.md, "Objects
and instances"). Each tree is one object (a trunk of four quads, a crown of three spheres) placed
by an instance with its own turn, height and position, jittered from a grid by a fixed seed."""
import json
import math
import random
from pathlib import Path

GRID = 20        # trees per side
SPACING = 4.0    # metres between grid points


def trunk(half_width, height):
    """Four quads around the y axis, their fronts outwards."""
    w, h = half_width, height
    sides = [([-w, 0, w], [2 * w, 0, 0]), ([w, 0, w], [0, 0, -2 * w]),
             ([w, 0, -w], [-2 * w, 0, 0]), ([-w, 0, -w], [0, 0, 2 * w])]
    return [{"type": "quad", "corner": c, "edge1": e, "edge2": [0, h, 0], "material": "bark"} for c, e in sides]


def main():
    rng = random.Random(15)
    tree = trunk(0.15, 2.0) + [
        {"type": "sphere", "center": [0, 2.6, 0], "radius": 1.0, "material": "leaves"},
        {"type": "sphere", "center": [0.5, 2.1, 0.2], "radius": 0.7, "material": "leaves"},
        {"type": "sphere", "center": [-0.4, 2.2, -0.3], "radius": 0.75, "material": "leaves"},
    ]
    shapes = [{"type": "quad", "corner": [-60, 0, 60], "edge1": [120, 0, 0], "edge2": [0, 0, -120],
               "material": "meadow"}]
    for j in range(GRID):
        for i in range(GRID):
            x = (i - GRID / 2 + 0.5) * SPACING + rng.uniform(-1, 1)
            z = (j - GRID / 2 + 0.5) * SPACING + rng.uniform(-1, 1)
            transform = [{"scale": round(rng.uniform(0.7, 1.3), 3)},
                         {"rotate": {"axis": [0, 1, 0], "angle": round(rng.uniform(0, 360), 1)}},
                         {"translate": [round(x, 3), 0, round(z, 3)]}]
            shapes.append({"type": "instance", "object": "tree", "transform": transform})
    scene = {
        "integrator": {"type": "path", "max_depth": 8},
        "sampler": {"spp": 64},
        "camera": {"type": "perspective", "position": [0, 14, -48], "look_at": [0, 0, 4], "up": [0, 1, 0],
                   "fov": 40, "resolution": [640, 360]},
        "film": {"filter": "gaussian", "tonemap": "exposure", "exposure": 0.6, "transfer": "srgb"},
        "materials": {
            "meadow": {"type": "diffuse", "albedo": [0.25, 0.4, 0.12]},
            "bark": {"type": "diffuse", "albedo": [0.3, 0.2, 0.12]},
            "leaves": {"type": "diffuse", "albedo": [0.12, 0.35, 0.08]},
        },
        "objects": {"tree": {"shapes": tree}},
        "shapes": shapes,
        "lights": [
            {"type": "environment", "color": [0.5, 0.65, 0.9]},
            {"type": "directional", "direction": [-0.5, -1, 0.6], "irradiance": [3, 2.8, 2.5]},
        ],
    }
    # One line per section entry, so that the file reads as a list of trees.
    def entries(items, indent):
        return (",\n" + indent).join(json.dumps(item) for item in items)

    lines = ["{"]
    for key in ("integrator", "sampler", "camera", "film"):
        lines.append(f'  "{key}": {json.dumps(scene[key])},')
    lines.append('  "materials": {\n    ' + entries([], "") +
                 ",\n    ".join(f'"{k}": {json.dumps(v)}' for k, v in scene["materials"].items()) + "\n  },")
    lines.append('  "objects": {"tree": {"shapes": [\n    ' + entries(tree, "    ") + "\n  ]}},")
    lines.append('  "shapes": [\n    ' + entries(shapes, "    ") + "\n  ],")
    lines.append('  "lights": [\n    ' + entries(scene["lights"], "    ") + "\n  ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)
    Path(__file__).with_name("scene.json").write_text(text)


if __name__ == "__main__":
    main()
