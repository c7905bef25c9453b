#include "candela/geometry/triangle_mesh.h"

#include <utility>

namespace candela {

void transform_mesh(TriangleMesh& mesh, const Transform& to_world, bool reverse_orientation) {
    for (Vec3f& p : mesh.positions) p = to_world.apply_point(p);
    for (Vec3f& n : mesh.normals) {
        Vec3f nw = normalize(to_world.apply_normal(n));
        n = reverse_orientation ? -nw : nw;
    }
    // A mirroring transform reverses the winding, and so would move the front face; reverse it
    // back. reverse_orientation asks for the opposite front. Both at once cancel (pbrt-v4's
    // reverseOrientation ^ transformSwapsHandedness).
    if (reverse_orientation != to_world.swaps_handedness()) {
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
}

std::vector<Vec3f> winding_normals(const TriangleMesh& mesh) {
    std::vector<Vec3f> normals;
    normals.reserve(mesh.triangle_count());
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const uint32_t* v = &mesh.indices[3 * t];
        normals.push_back(winding_normal(mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]));
    }
    return normals;
}

TriangleMesh make_quad(const Vec3f& corner, const Vec3f& edge1, const Vec3f& edge2) {
    TriangleMesh m;
    m.positions = {corner, corner + edge1, corner + edge1 + edge2, corner + edge2};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    // Both triangles wind like (edge1, edge2), so their normal is cross(edge1, edge2).
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

}  // namespace candela
