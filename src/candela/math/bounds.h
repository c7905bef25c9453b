#pragma once
// Axis-aligned bounding boxes.
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

struct Bounds3f {
    Vec3f lo{kInfinity, kInfinity, kInfinity};
    Vec3f hi{-kInfinity, -kInfinity, -kInfinity};

    CANDELA_HD bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    CANDELA_HD void extend(const Vec3f& p) { lo = min(lo, p); hi = max(hi, p); }
    CANDELA_HD void extend(const Bounds3f& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    CANDELA_HD Vec3f center() const { return (lo + hi) * 0.5f; }
    CANDELA_HD Vec3f diagonal() const { return hi - lo; }
};

}  // namespace candela
