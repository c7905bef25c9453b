#!/usr/bin/env python3
"""Writes the checkerboard floor of scene.json: 1 x 1 squares on y = 0 over x in [-8, 16] and
z in [-28, 8], as two OBJ meshes (light and dark squares, a material each). Run it here."""

X0, X1, Z0, Z1 = -8, 16, -28, 8


def write(name, parity):
    lines = [f"# {name} squares of the depth-of-field floor (written by make_floor.py)"]
    faces = []
    for i, x in enumerate(range(X0, X1)):
        for j, z in enumerate(range(Z0, Z1)):
            if (i + j) % 2 != parity:
                continue
            n = len(faces) * 4
            # Counter-clockwise seen from above (+y): the front side faces up.
            lines += [f"v {x} 0 {z}", f"v {x} 0 {z + 1}", f"v {x + 1} 0 {z + 1}", f"v {x + 1} 0 {z}"]
            faces.append(f"f {n + 1} {n + 2} {n + 3} {n + 4}")
    with open(f"meshes/floor_{name}.obj", "w", encoding="ascii") as out:
        out.write("\n".join(lines + faces) + "\n")


write("light", 0)
write("dark", 1)
