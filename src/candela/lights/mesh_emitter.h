#pragma once
// A triangle mesh (or quad) as an emitter: a triangle chosen with probability proportional to its
// area, then a uniform point in it, so the area density is 1 / (total area) everywhere.
//
// The front normal at a point is the one hits report (geometry/accelerator.cpp): the winding's
// normalize(cross(p1 - p0, p2 - p0)), flipped to agree with the interpolated vertex normal where
// the mesh has vertex normals (pbrt's rule, DESIGN.md). Emission sidedness must follow the same
// normal for light sampling and for rays that hit the light, or the two estimators would disagree.
#include <cstdint>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/triangle_mesh.h"
#include "candela/lights/emitter.h"
#include "candela/sampling/distribution_1d.h"
#include "candela/sampling/warps.h"

namespace candela {

class MeshEmitter {
  public:
    // The mesh must outlive the emitter. Zero-area triangles are never sampled.
    explicit MeshEmitter(const TriangleMesh& mesh);

    // Total area of the mesh's triangles.
    CANDELA_HD float area() const { return area_; }
    // A uniform point by area: uc picks the triangle, u the point in it.
    CANDELA_HD std::optional<EmitterSample> sample(const Vec3f& ref, float uc, Vec2f u) const;
    // (1 / area) * dist^2 / |cos theta_light|, for any point p of the mesh with normal n.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const {
        return solid_angle_pdf(inv_area_, ref, p, n);
    }

  private:
    const TriangleMesh* mesh_ = nullptr;
    Distribution1D triangles_;  // by area
    float area_ = 0.0f;
    double inv_area_ = 0.0;     // 1 / area, from the double sum of triangle areas
};
static_assert(EmitterType<MeshEmitter>);

CANDELA_HD inline std::optional<EmitterSample> MeshEmitter::sample(const Vec3f& ref, float uc, Vec2f u) const {
    if (triangles_.empty()) return std::nullopt;
    const TriangleMesh& m = *mesh_;
    uint32_t tri = triangles_.sample_discrete(uc).index;
    uint32_t i0 = m.indices[3 * tri], i1 = m.indices[3 * tri + 1], i2 = m.indices[3 * tri + 2];
    const Vec3f &p0 = m.positions[i0], &p1 = m.positions[i1], &p2 = m.positions[i2];
    Vec3f b = sample_uniform_triangle(u);
    EmitterSample s;
    // The same convex combination and normal as a hit at these barycentrics (accelerator.cpp).
    s.p = p0 * b.x + p1 * b.y + p2 * b.z;
    s.n = normalize(cross(p1 - p0, p2 - p0));  // nonzero: the triangle has positive area
    if (!m.normals.empty()) {
        Vec3f ns = m.normals[i0] * b.x + m.normals[i1] * b.y + m.normals[i2] * b.z;
        if (length(ns) > 0.0f) s.n = face_forward(s.n, ns);
    }
    s.pdf = pdf(ref, s.p, s.n);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    return s;
}

}  // namespace candela
