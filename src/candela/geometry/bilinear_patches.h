#pragma once
// pbrt-v4's bilinear patch meshes (its `bilinearmesh` shape, and the quads of its PLY files) as
// triangle meshes: candela renders every patch as two triangles.
#include <span>

#include "candela/geometry/triangle_mesh.h"
#include "candela/math/vec.h"

namespace candela {

// Patches given as pbrt-v4 gives them: `indices` holds four positions per patch, in pbrt's order
// v00 v10 v01 v11, the patch being p(u, v) = lerp over (v00, v10, v01, v11) bilinearly in (u, v);
// an empty `indices` with exactly four positions is one patch (pbrt's default). `normals` and
// `uvs` are per position, or empty. Each patch becomes the triangles (v00, v10, v11) and
// (v00, v11, v01): their winding normal is the patch's cross(dp/du, dp/dv), so the front side is
// pbrt's, and the diagonal v00-v11 is the one pbrt-v4 and candela's PLY reader cut a quad
// (v0 v1 v2 v3 = v00 v10 v11 v01) along. Planar patches come out exactly; curved ones as two
// flat halves. Without `uvs`, a patch's corners get pbrt's default uv (0,0), (1,0), (0,1), (1,1),
// so positions shared by patches are repeated per patch; with `uvs`, positions stay shared.
// Normals are copied as given (not normalized).
// Throws SceneError (without a location: the caller adds it) when the index count is not a
// multiple of 4, an index is out of range, or `normals`/`uvs` are neither empty nor one per position.
TriangleMesh bilinear_patches_to_triangles(std::span<const Vec3f> positions, std::span<const int> indices,
                                           std::span<const Vec3f> normals = {},
                                           std::span<const Vec2f> uvs = {});

}  // namespace candela
