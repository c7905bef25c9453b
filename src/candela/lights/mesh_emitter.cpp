#include "candela/lights/mesh_emitter.h"

#include <algorithm>
#include <vector>

namespace candela {

MeshEmitter::MeshEmitter(const TriangleMesh& mesh) : mesh_(&mesh) {
    // A zero-area triangle is never sampled, so its (NaN) normal is never read.
    const bool store_normals = mesh.normals.empty();
    if (store_normals) face_normals_ = winding_normals(mesh);
    std::vector<float> areas(mesh.triangle_count());
    for (size_t t = 0; t < areas.size(); ++t) {
        const Vec3f& p0 = mesh.positions[mesh.indices[3 * t]];
        const Vec3f& p1 = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3f& p2 = mesh.positions[mesh.indices[3 * t + 2]];
        areas[t] = 0.5f * length(cross(p1 - p0, p2 - p0));
    }
    triangles_ = Distribution1D(areas);
    // The distribution's double sum: a float sum over millions of triangles would drift.
    double total = triangles_.total();
    area_ = static_cast<float>(total);
    inv_area_ = total > 0.0 ? static_cast<float>(1.0 / total) : 0.0f;

    // The parallelogram form needs both triangles sampleable, their normals stored, and the
    // shared diagonal a-c: (a, b, c), (a, c, d) with b - a = c - d up to rounding (make_quad
    // computes c as (a + e1) + e2; a transform rounds each corner): 1e-6 of the quad's size plus
    // about four float steps of its coordinates. Within that, the two forms differ by rounding.
    if (store_normals && areas.size() == 2 && areas[0] > 0.0f && areas[1] > 0.0f) {
        const uint32_t* v = mesh.indices.data();
        if (v[3] == v[0] && v[4] == v[2]) {
            const Vec3f &a = mesh.positions[v[0]], &b = mesh.positions[v[1]], &c = mesh.positions[v[2]],
                        &d = mesh.positions[v[5]];
            Vec3f e1 = b - a, e2 = d - a;
            float size = std::max(max_component(abs(e1)), max_component(abs(e2)));
            float magnitude = std::max(max_component(abs(a)), max_component(abs(c)));
            if (max_component(abs((c - d) - e1)) <= 1e-6f * size + 5e-7f * magnitude) {
                parallelogram_ = true;
                corner_ = a;
                edge1_ = e1;
                edge2_ = e2;
            }
        }
    }
}

}  // namespace candela
