#!/usr/bin/env python3
"""Reference output of pbrt-v4's `loopsubdiv` shape, for tests/geometry/loop_subdivision_test.cpp.

An independent re-implementation of pbrt-v4's LoopSubdivide (src/pbrt/util/loopsubdiv.cpp) as
pbrt structures it: faces holding their vertices and their neighbour across each edge, one-rings
walked face to face (nextFace/prevFace), in double precision. candela's loop_subdivide computes
the same surface from OpenSubdiv's topology instead; the test matches the two vertex by vertex.

Run from the repository root:
    tools/loop_reference/pbrt_loop_reference.py > tests/data/meshes/loop_reference.txt
"""
import math

NEXT = lambda i: (i + 1) % 3
PREV = lambda i: (i + 2) % 3


def add(a, b): return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def mul(s, a): return [s * a[0], s * a[1], s * a[2]]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


class Vertex:
    def __init__(self, p):
        self.p, self.start, self.child, self.boundary = p, None, None, False


class Face:
    def __init__(self):
        self.v, self.f, self.children = [None] * 3, [None] * 3, [None] * 4

    def vnum(self, vert): return self.v.index(vert)
    def next_face(self, vert): return self.f[self.vnum(vert)]
    def prev_face(self, vert): return self.f[PREV(self.vnum(vert))]
    def next_vert(self, vert): return self.v[NEXT(self.vnum(vert))]
    def prev_vert(self, vert): return self.v[PREV(self.vnum(vert))]
    def other_vert(self, a, b): return next(v for v in self.v if v is not a and v is not b)


def valence(v):
    f, n = v.start, 1
    if not v.boundary:
        f = f.next_face(v)
        while f is not v.start:
            n, f = n + 1, f.next_face(v)
        return n
    f = f.next_face(v)
    while f is not None:
        n, f = n + 1, f.next_face(v)
    f = v.start.prev_face(v)
    while f is not None:
        n, f = n + 1, f.prev_face(v)
    return n + 1


def one_ring(v):
    ring = []
    if not v.boundary:
        f = v.start
        while True:
            ring.append(f.next_vert(v).p)
            f = f.next_face(v)
            if f is v.start:
                return ring
    f = v.start
    while f.next_face(v) is not None:
        f = f.next_face(v)
    ring.append(f.next_vert(v).p)
    while f is not None:
        ring.append(f.prev_vert(v).p)
        f = f.prev_face(v)
    return ring


def beta(n): return 3.0 / 16.0 if n == 3 else 3.0 / (8.0 * n)
def gamma(n): return 1.0 / (n + 3.0 / (8.0 * beta(n)))


def weigh_ring(v, w):
    ring = one_ring(v)
    p = mul(1 - len(ring) * w, v.p)
    for q in ring:
        p = add(p, mul(w, q))
    return p


def weigh_boundary(v, w):
    ring = one_ring(v)
    return add(add(mul(1 - 2 * w, v.p), mul(w, ring[0])), mul(w, ring[-1]))


def edge_key(a, b): return (min(id(a), id(b)), max(id(a), id(b)))


def subdivide(positions, indices, levels):
    verts = [Vertex(list(p)) for p in positions]
    faces = [Face() for _ in range(len(indices) // 3)]
    for i, f in enumerate(faces):
        for j in range(3):
            f.v[j] = verts[indices[3 * i + j]]
            f.v[j].start = f
    open_edges = {}
    for f in faces:
        for e in range(3):
            key = edge_key(f.v[e], f.v[NEXT(e)])
            if key in open_edges:
                g, ge = open_edges.pop(key)
                g.f[ge], f.f[e] = f, g
            else:
                open_edges[key] = (f, e)
    for v in verts:
        f = v.start
        while True:
            f = f.next_face(v)
            if f is None or f is v.start:
                break
        v.boundary = f is None

    for _ in range(levels):
        new_verts, new_faces = [], []
        for v in verts:
            v.child = Vertex(None)
            v.child.boundary = v.boundary
            new_verts.append(v.child)
        for f in faces:
            f.children = [Face() for _ in range(4)]
            new_faces.extend(f.children)
        for v in verts:
            v.child.p = weigh_boundary(v, 1 / 8) if v.boundary else weigh_ring(v, beta(valence(v)))
        edge_verts = {}
        for f in faces:
            for k in range(3):
                a, b = f.v[k], f.v[NEXT(k)]
                key = edge_key(a, b)
                if key in edge_verts:
                    continue
                e = Vertex(None)
                new_verts.append(e)
                e.boundary = f.f[k] is None
                e.start = f.children[3]
                if e.boundary:
                    e.p = add(mul(0.5, a.p), mul(0.5, b.p))
                else:
                    e.p = add(mul(3 / 8, add(a.p, b.p)),
                              mul(1 / 8, add(f.other_vert(a, b).p, f.f[k].other_vert(a, b).p)))
                edge_verts[key] = e
        for v in verts:
            v.child.start = v.start.children[v.start.vnum(v)]
        for f in faces:
            for j in range(3):
                f.children[3].f[j] = f.children[NEXT(j)]
                f.children[j].f[NEXT(j)] = f.children[3]
                g = f.f[j]
                f.children[j].f[j] = g.children[g.vnum(f.v[j])] if g else None
                g = f.f[PREV(j)]
                f.children[j].f[PREV(j)] = g.children[g.vnum(f.v[j])] if g else None
        for f in faces:
            for j in range(3):
                f.children[j].v[j] = f.v[j].child
                e = edge_verts[edge_key(f.v[j], f.v[NEXT(j)])]
                f.children[j].v[NEXT(j)] = e
                f.children[NEXT(j)].v[j] = e
                f.children[3].v[j] = e
        verts, faces = new_verts, new_faces

    limit = [weigh_boundary(v, 1 / 5) if v.boundary else weigh_ring(v, gamma(valence(v))) for v in verts]
    for v, p in zip(verts, limit):
        v.p = p
    normals = []
    for v in verts:
        ring, n = one_ring(v), valence(v)
        if not v.boundary:
            s = t = [0.0, 0.0, 0.0]
            for j, q in enumerate(ring):
                s = add(s, mul(math.cos(2 * math.pi * j / n), q))
                t = add(t, mul(math.sin(2 * math.pi * j / n), q))
        else:
            s = sub(ring[-1], ring[0])
            if n == 2:
                t = sub(add(ring[0], ring[1]), mul(2, v.p))
            elif n == 3:
                t = sub(ring[1], v.p)
            elif n == 4:
                t = add(add(mul(-1, ring[0]), mul(2, ring[1])), add(mul(2, ring[2]), add(mul(-1, ring[3]), mul(-2, v.p))))
            else:
                theta = math.pi / (n - 1)
                t = mul(math.sin(theta), add(ring[0], ring[-1]))
                for k in range(1, n - 1):
                    t = add(t, mul((2 * math.cos(theta) - 2) * math.sin(k * theta), ring[k]))
                t = mul(-1, t)
        c = cross(s, t)
        length = math.sqrt(sum(x * x for x in c))
        normals.append([x / length for x in c])
    index = {id(v): i for i, v in enumerate(verts)}
    triangles = [[index[id(f.v[j])] for j in range(3)] for f in faces]
    return limit, normals, triangles


def open_pentagonal_pyramid():
    # An apex of valence 5 and an open base whose five corners are boundary vertices of valence 3.
    p = [[0, 0, 1]] + [[math.cos(2 * math.pi * k / 5), math.sin(2 * math.pi * k / 5), 0] for k in range(5)]
    return p, [i for k in range(5) for i in (0, 1 + k, 1 + (k + 1) % 5)]


def bumpy_grid():
    # A 4 x 3 grid with alternating diagonals and a bump: interior valences 4 and 8, boundary
    # valences 2 to 5.
    n, m = 4, 3
    p = [[x, y, 0.4 * math.sin(x + 0.7 * y)] for y in range(m + 1) for x in range(n + 1)]
    t = []
    for y in range(m):
        for x in range(n):
            a, b, c, d = y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x
            t += [a, b, c, a, c, d] if (x + y) % 2 == 0 else [a, b, d, b, c, d]
    return p, t


def main():
    print("# pbrt-v4's loopsubdiv output, from tools/loop_reference/pbrt_loop_reference.py (do not edit).")
    print("# mesh NAME LEVELS; P: input positions; I: input triangles; V: limit position and unit normal;")
    print("# T: output triangle count.")
    for name, (p, t), levels in (("pyramid", open_pentagonal_pyramid(), 2), ("grid", bumpy_grid(), 1),
                                 ("grid", bumpy_grid(), 2)):
        limit, normals, triangles = subdivide(p, t, levels)
        print(f"mesh {name} {levels}")
        for q in p:
            print("P", *(f"{x:.9g}" for x in q))
        for i in range(0, len(t), 3):
            print("I", *t[i:i + 3])
        for q, n in zip(limit, normals):
            print("V", *(f"{x:.9g}" for x in q + n))
        print("T", len(triangles))


if __name__ == "__main__":
    main()
