#pragma once
// A chi-square domain (support/chi2.h) for narrow lobes: the directions within theta_max of an
// axis, parametrised by (phi, v) in [-pi, pi] x [0, 1] with the angle to the axis theta =
// theta_max v^2. Rows near the axis are narrow (the first spans theta_max / 2500), so a lobe of
// width 0.01 around the axis still covers several rows and all the columns.
#include <cmath>

#include "candela/math/frame.h"
#include "support/chi2.h"

namespace candela::test {

struct AxisDomain {
    using Point = Vec3f;
    Vec3d s, t, n;  // the axis n and two tangents, orthonormal
    double theta_max = kPiD;

    AxisDomain(Vec3f axis, double theta_max_) : theta_max(theta_max_) {
        n = normalize(Vec3d(axis));
        Frame f = Frame::from_normal(Vec3f(n));
        s = normalize(Vec3d(f.s));
        t = cross(n, s);
    }
    Vec2d param_min() const { return {-kPiD, 0.0}; }
    Vec2d param_max() const { return {kPiD, 1.0}; }
    Vec2d to_param(Vec3f w) const {
        Vec3d v(w);
        double x = dot(v, s), y = dot(v, t), z = dot(v, n);
        double theta = std::atan2(std::sqrt(x * x + y * y), z);
        return {std::atan2(y, x), std::sqrt(theta / theta_max)};
    }
    Vec3f from_param(Vec2d q) const {
        double theta = theta_max * q.y * q.y, st = std::sin(theta);
        return Vec3f(s * (st * std::cos(q.x)) + t * (st * std::sin(q.x)) + n * std::cos(theta));
    }
    // d omega = sin(theta) d theta d phi, d theta = 2 theta_max v dv.
    double jacobian(Vec2d q) const {
        return std::sin(theta_max * q.y * q.y) * 2.0 * theta_max * q.y;
    }
};

}  // namespace candela::test
