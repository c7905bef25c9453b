#pragma once
// Ray-sphere intersection that stays precise for huge spheres (smallpt's walls: radius 1e5,
// centre 1e5 away), after Haines et al., "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems, ch. 7, and evaluated in double.
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/sphere.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// The smallest root t of |o + t d - c| = r with tmin < t < tmax, if any. d need not be unit.
CANDELA_HD inline std::optional<double> intersect_sphere(const Sphere& s, const Vec3d& o, const Vec3d& d,
                                                         double tmin, double tmax) {
    // Roots of a t^2 + 2 b t + c = 0 with f = o - centre: a = d.d, b = f.d, c = f.f - r^2.
    Vec3d f = o - s.center;
    double a = dot(d, d);
    double b = dot(f, d);
    double c = dot(f, f) - s.radius * s.radius;
    // b^2 - a c loses all precision when |f| >> r; the equivalent form a (r^2 - |f - (b/a) d|^2)
    // subtracts nearly equal numbers only after the large component along d is removed (RTG 7.2).
    Vec3d l = f - d * (b / a);
    double disc = a * (s.radius * s.radius - dot(l, l));
    if (disc < 0.0) return std::nullopt;
    // The root of larger magnitude first, then the other from the product of roots c / a
    // (avoids cancellation in -b +- sqrt(disc), RTG 7.3).
    double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = c / q;
    double t1 = q / a;
    if (q == 0.0) t0 = t1 = 0.0;  // only when the origin lies on the sphere and d is tangent
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tmin && t0 < tmax) return t0;
    if (t1 > tmin && t1 < tmax) return t1;
    return std::nullopt;
}

// The point of the sphere nearest to p (p reprojected onto the surface, in double).
CANDELA_HD inline Vec3d project_to_sphere(const Sphere& s, const Vec3d& p) {
    Vec3d v = p - s.center;
    return s.center + v * (s.radius / length(v));
}

}  // namespace candela
