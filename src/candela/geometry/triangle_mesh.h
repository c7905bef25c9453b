#pragma once
// A triangle mesh in world space, with its orientation already resolved: the front face of each
// triangle is the counter-clockwise one (geometric normal = cross(p1 - p0, p2 - p0)), and vertex
// normals, where present, point to the front. Quads are meshes of two triangles.
#include <cstdint>
#include <vector>

#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

struct TriangleMesh {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;     // unit, one per vertex, or empty
    std::vector<Vec2f> uvs;         // one per vertex, or empty
    std::vector<uint32_t> indices;  // three per triangle

    size_t triangle_count() const { return indices.size() / 3; }
};

// The unit normal of triangle p0 p1 p2's counter-clockwise side, the front: what hits report as
// the geometric normal and what light samples on an emitting mesh use, so the two always agree.
inline Vec3f winding_normal(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}
// winding_normal of every triangle, in triangle order (NaN for a zero-area one): the table that
// hits and mesh-light samples read instead of normalizing a cross product each time.
std::vector<Vec3f> winding_normals(const TriangleMesh& mesh);

// Moves an object-space mesh to world space and resolves its front side, as DESIGN.md's scene
// format says (pbrt's rule): positions by `to_world`; vertex normals by its inverse transpose; the
// winding reversed when exactly one of `reverse_orientation` and to_world.swaps_handedness()
// holds (so the front stays where it was under a mirror, and flips on request); vertex normals
// negated when `reverse_orientation`.
void transform_mesh(TriangleMesh& mesh, const Transform& to_world, bool reverse_orientation);

// A parallelogram corner + s edge1 + t edge2, (s, t) in [0,1]^2, front side cross(edge1, edge2),
// as two triangles with uv = (s, t).
TriangleMesh make_quad(const Vec3f& corner, const Vec3f& edge1, const Vec3f& edge2);

}  // namespace candela
