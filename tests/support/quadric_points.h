#pragma once
// Test helpers for the clipped quadrics (geometry/quadric.h): pbrt-v4's (u, v) parameterisation
// written out independently of the library (the intersection and emitter tests check the library
// against it), and a component-wise comparison of double vectors.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/quadric.h"

namespace candela::test {

// The object-space point at (u, v) in [0, 1]^2: phi = u phi_max; v runs along z (cylinder),
// theta (sphere) or inward from the outer radius (disk), as pbrt-v4's shapes have it.
inline Vec3d quadric_point_of_uv(const Quadric& q, double u, double v) {
    const double phi = u * q.phi_max;
    switch (q.kind) {
        case QuadricKind::kCylinder:
            return {q.radius * std::cos(phi), q.radius * std::sin(phi), q.z_min + v * (q.z_max - q.z_min)};
        case QuadricKind::kSphere: {
            const double theta = q.theta_z_min + v * (q.theta_z_max - q.theta_z_min);
            return Vec3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)) * q.radius;
        }
        case QuadricKind::kDisk: {
            const double r = q.radius - v * (q.radius - q.inner_radius);
            return {r * std::cos(phi), r * std::sin(phi), q.height};
        }
    }
    return {};
}

inline void expect_near(const Vec3d& a, const Vec3d& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace candela::test
