#pragma once
// pbrt-v4's `loopsubdiv` shape: Loop subdivision surfaces (Loop 1987), refined `levels` times and
// pushed to their limit positions with limit normals, exactly by pbrt-v4's rules.
#include <span>

#include "candela/geometry/triangle_mesh.h"
#include "candela/math/vec.h"

namespace candela {

// The most levels loop_subdivide refines (OpenSubdiv's limit); each level makes 4x the triangles.
inline constexpr int kMaxLoopLevels = 15;

// Subdivides the triangles `indices` (three per triangle, into `positions`) `levels` times and
// returns the mesh of the last level at its limit positions, with per-vertex limit normals. The
// rules are pbrt-v4's (src/pbrt/util/loopsubdiv.cpp): interior even vertices by Warren's weights
// (beta = 3/16 at valence 3, 3/(8n) otherwise), edge vertices 3/8 3/8 1/8 1/8, boundary edges as
// creases (even 1/8 3/4 1/8, odd 1/2 1/2; corners are not kept sharp), limit positions by pbrt's
// masks (gamma = 1/(n + 3/(8 beta)) inside, 1/5 3/5 1/5 on boundaries) and normals as pbrt's
// cross(S, T) of its tangent masks. OpenSubdiv's TopologyRefiner (Loop scheme, uniform) does the
// topology; the positions are computed here, since OpenSubdiv's Loop masks use Loop's original
// weights and the true boundary limit (1/6 2/3 1/6), which differ from pbrt-v4's.
// Orientation as pbrt-v4 renders it: pbrt's limit normals point away from the side the input
// triangles wind counter-clockwise (its one-ring runs clockwise), and pbrt lets vertex normals
// decide a triangle's side, so the returned triangles are wound the other way round from the
// input's, keeping candela's rule that the winding and the normals agree on the front.
// Throws SceneError (without a location: the caller adds it) for an index count that is not a
// multiple of 3, an index out of range, a position no triangle uses, a non-manifold or
// inconsistently wound mesh, `levels` outside [0, kMaxLoopLevels], or a result beyond 2^31 - 1
// triangles (OpenSubdiv's int indices).
TriangleMesh loop_subdivide(std::span<const Vec3f> positions, std::span<const int> indices, int levels);

}  // namespace candela
