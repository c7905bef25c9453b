#pragma once
// A clipped quadric (geometry/quadric.h: cylinder, partial sphere, partial disk) as an emitter:
// a point uniform by area in object space over the clipped surface only, then moved to the
// world. pbrt-v4 samples its cylinder this way; for partial spheres and partial disks it samples
// the full shape instead (docs/PBRT.md), which puts light where there is no surface.
//
// Uniform in object space is uniform in the world only under a similarity transform. In general
// the world's area element is J dA_object with J = |det M| |M^-T n_object| = |det M| / |M^T n|
// (M the transform's linear part, n the unit world normal), so the world area density at a point
// is 1 / (object area * J): exact under any affine transform (pbrt-v4 divides by the object area
// alone). pdf() computes it from the normal it is given, as sample() does, so the two agree bit
// for bit.
#include <algorithm>
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/quadric_intersection.h"
#include "candela/lights/emitter.h"

namespace candela {

class QuadricEmitter {
  public:
    // `q` must outlive the emitter (the scene's, as the light set's spans); held by pointer so
    // that the Emitter variant stays as small as the other emitters need.
    explicit QuadricEmitter(const Quadric& q)
        : quadric_(&q), inv_object_area_(1.0 / q.object_area()), abs_det_(std::fabs(q.to_world.determinant())) {
        // The world area (the light's power): J averaged over a grid of points uniform by object
        // area; exact for similarity transforms, where J is constant.
        constexpr int kGrid = 32;
        double sum = 0.0;
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                const Vec3d p = object_point(Vec2f((float(i) + 0.5f) / kGrid, (float(j) + 0.5f) / kGrid));
                sum += area_scale(quadric_normal(*quadric_, p));
            }
        area_ = static_cast<float>(q.object_area() * sum / (kGrid * kGrid));
    }

    CANDELA_HD float area() const { return area_; }
    CANDELA_HD std::optional<EmitterSample> sample(const Vec3f& ref, Vec2f u) const {
        std::optional<EmitterSample> result;
        const Vec3d p = object_point(u);
        EmitterSample& s = result.emplace();
        s.p = Vec3f(quadric_->to_world.apply_point(p));
        s.n = Vec3f(quadric_normal(*quadric_, p));
        const SolidAngleDensity seen = solid_angle_density(area_pdf(s.n), ref, s.p, s.n);
        s.pdf = seen.pdf;
        s.wi = seen.wi;
        if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) result.reset();
        return result;
    }
    // The world area density at the point with unit normal n, converted to solid angle at ref.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const {
        return solid_angle_pdf(area_pdf(n), ref, p, n);
    }

    // The object-space point of u, uniform by object area over the clipped surface: phi = u.y
    // phi_max; z uniform on the sphere (Archimedes) and the cylinder, r^2 uniform on the disk.
    CANDELA_HD Vec3d object_point(Vec2f u) const {
        const Quadric& q = *quadric_;
        const double phi = double(u.y) * q.phi_max;
        const double c = std::cos(phi), s = std::sin(phi);
        if (q.kind == QuadricKind::kDisk) {
            const double ri2 = q.inner_radius * q.inner_radius;
            const double r = std::sqrt(ri2 + double(u.x) * (q.radius * q.radius - ri2));
            return Vec3d(r * c, r * s, q.height);
        }
        const double z = q.z_min + double(u.x) * (q.z_max - q.z_min);
        const double rho = q.kind == QuadricKind::kSphere ? std::sqrt(std::max(0.0, q.radius * q.radius - z * z))
                                                          : q.radius;
        return Vec3d(rho * c, rho * s, z);
    }

    // The world area density of sample() at a point with unit world normal n.
    CANDELA_HD float area_pdf(const Vec3f& n) const {
        return static_cast<float>(inv_object_area_ / area_scale(Vec3d(n)));
    }

  private:
    // J = |det M| / |M^T n| (above); to_object's normal map is M^T.
    CANDELA_HD double area_scale(const Vec3d& n) const {
        return abs_det_ / length(quadric_->to_object.apply_normal(n));
    }

    const Quadric* quadric_ = nullptr;
    double inv_object_area_ = 0.0;
    double abs_det_ = 1.0;
    float area_ = 0.0f;
};
static_assert(EmitterType<QuadricEmitter>);

}  // namespace candela
