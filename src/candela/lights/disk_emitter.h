#pragma once
// A disk (or ellipse, geometry/disk.h) as an emitter: a point uniform by area, from Shirley and
// Chiu's concentric map of the unit square onto the unit disk carried onto the disk by its axes
// (an affine map, so uniform stays uniform: area density 1 / area, pbrt-v4's Disk::Sample),
// converted to solid angle at the reference point. The point is computed in double, as hits on
// the disk are, and its front normal is the disk's, exactly as hits report it.
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/disk.h"
#include "candela/lights/emitter.h"
#include "candela/sampling/warps.h"

namespace candela {

class DiskEmitter {
  public:
    explicit DiskEmitter(const Disk& disk)
        : disk_(disk),
          area_(static_cast<float>(disk.area())),
          inv_area_(disk.area() > 0.0 ? static_cast<float>(1.0 / disk.area()) : 0.0f) {}

    // pi |axis_u x axis_v| (pi r^2 when round).
    CANDELA_HD float area() const { return area_; }
    CANDELA_HD std::optional<EmitterSample> sample(const Vec3f& ref, Vec2f u) const {
        std::optional<EmitterSample> result;  // the one object returned, built in place
        Vec2f q = sample_concentric_disk(u);
        EmitterSample& s = result.emplace();
        s.p = Vec3f(disk_.point(static_cast<double>(q.x), static_cast<double>(q.y)));
        s.n = Vec3f(disk_.normal);
        SolidAngleDensity seen = solid_angle_density(inv_area_, ref, s.p, s.n);  // as pdf() computes it
        s.pdf = seen.pdf;
        s.wi = seen.wi;
        if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) result.reset();
        return result;
    }
    // (1 / area) dist^2 / |cos theta_light| for any point p of the disk with normal n.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const {
        return solid_angle_pdf(inv_area_, ref, p, n);
    }

  private:
    Disk disk_;
    float area_ = 0.0f;
    float inv_area_ = 0.0f;  // 1 / area, from the area in double
};
static_assert(EmitterType<DiskEmitter>);

}  // namespace candela
