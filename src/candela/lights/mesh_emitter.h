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
#include <vector>

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
    // A uniform point by area. On a parallelogram (a quad: two triangles (a, b, c), (a, c, d)
    // with b - a = c - d) it is a + u.x (b - a) + u.y (d - a), which keeps a stratified u
    // stratified over the whole quad and costs a few multiplies. Otherwise u.x picks the
    // triangle and, stretched back over [0, 1) within the triangle's share (pbrt-v3's sample
    // reuse), places the point with u.y. A stratified 2D set stays stratified over the whole mesh
    // (for a 2D net, each triangle's share is a net again), and no separate number is drawn for
    // the choice.
    CANDELA_HD std::optional<EmitterSample> sample(const Vec3f& ref, Vec2f u) const;
    // (1 / area) * dist^2 / |cos theta_light|, for any point p of the mesh with normal n.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const {
        return solid_angle_pdf(inv_area_, ref, p, n);
    }
    // Whether sample() uses the parallelogram form (for tests).
    bool is_parallelogram() const { return parallelogram_; }

  private:
    // The point and front normal for u by the triangle-then-point route.
    CANDELA_HD void sample_by_triangle(Vec2f u, EmitterSample& s) const;

    const TriangleMesh* mesh_ = nullptr;
    Distribution1D triangles_;  // by area
    // Per triangle, the unit normal of its winding, when the mesh has no vertex normals (with
    // them, the front normal depends on the point): a square root and three divisions per light
    // sample saved, 12 bytes per emitting triangle.
    std::vector<Vec3f> face_normals_;
    float area_ = 0.0f;
    float inv_area_ = 0.0f;  // 1 / area, from the double sum of triangle areas
    // The parallelogram form: corner a and edges b - a, d - a (see sample()).
    bool parallelogram_ = false;
    Vec3f corner_, edge1_, edge2_;
};
static_assert(EmitterType<MeshEmitter>);

CANDELA_HD inline void MeshEmitter::sample_by_triangle(Vec2f u, EmitterSample& s) const {
    const TriangleMesh& m = *mesh_;
    uint32_t tri = 0;
    if (triangles_.size() > 1) {
        DiscreteSample chosen = triangles_.sample_discrete(u.x);
        tri = chosen.index;
        u.x = chosen.u_remapped;
    }
    uint32_t i0 = m.indices[3 * tri], i1 = m.indices[3 * tri + 1], i2 = m.indices[3 * tri + 2];
    const Vec3f &p0 = m.positions[i0], &p1 = m.positions[i1], &p2 = m.positions[i2];
    Vec3f b = sample_uniform_triangle(u);
    // The same convex combination and normal as a hit at these barycentrics (accelerator.cpp).
    s.p = p0 * b.x + p1 * b.y + p2 * b.z;
    if (m.normals.empty()) {
        s.n = face_normals_[tri];
    } else {
        s.n = winding_normal(p0, p1, p2);  // nonzero: the triangle has positive area
        Vec3f ns = m.normals[i0] * b.x + m.normals[i1] * b.y + m.normals[i2] * b.z;
        if (length(ns) > 0.0f) s.n = face_forward(s.n, ns);
    }
}

[[gnu::always_inline]] CANDELA_HD inline std::optional<EmitterSample> MeshEmitter::sample(const Vec3f& ref, Vec2f u) const {
    std::optional<EmitterSample> result;  // the one object returned, built in place
    if (triangles_.empty()) return result;
    EmitterSample& s = result.emplace();
    if (parallelogram_) {
        s.p = corner_ + edge1_ * u.x + edge2_ * u.y;
        // Triangle (a, b, c) is the half u.y <= u.x; its normal is the one a hit there reports.
        s.n = face_normals_[u.y > u.x ? 1 : 0];
    } else {
        sample_by_triangle(u, s);
    }
    SolidAngleDensity seen = solid_angle_density(inv_area_, ref, s.p, s.n);  // as pdf() computes it
    s.pdf = seen.pdf;
    s.wi = seen.wi;
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) result.reset();
    return result;
}

}  // namespace candela
