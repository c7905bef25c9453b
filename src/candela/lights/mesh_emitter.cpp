#include "candela/lights/mesh_emitter.h"

#include <vector>

namespace candela {

MeshEmitter::MeshEmitter(const TriangleMesh& mesh) : mesh_(&mesh) {
    const bool store_normals = mesh.normals.empty();
    std::vector<float> areas(mesh.triangle_count());
    if (store_normals) face_normals_.resize(areas.size());
    for (size_t t = 0; t < areas.size(); ++t) {
        const Vec3f& p0 = mesh.positions[mesh.indices[3 * t]];
        const Vec3f& p1 = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3f& p2 = mesh.positions[mesh.indices[3 * t + 2]];
        areas[t] = 0.5f * length(cross(p1 - p0, p2 - p0));
        // A zero-area triangle is never sampled, so its normal is never read.
        if (store_normals && areas[t] > 0.0f) face_normals_[t] = winding_normal(p0, p1, p2);
    }
    triangles_ = Distribution1D(areas);
    // The distribution's double sum: a float sum over millions of triangles would drift.
    double total = triangles_.total();
    area_ = static_cast<float>(total);
    inv_area_ = total > 0.0 ? 1.0 / total : 0.0;
}

}  // namespace candela
