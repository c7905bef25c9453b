#pragma once
// The irradiance a uniform polygonal light puts on a point, by Lambert's formula for polygons
// (Arvo 1995, "Applications of Irradiance Tensors to the Simulation of Non-Lambertian Phenomena",
// section 3): E(p) = (L / 2) sum_i theta_i (n . gamma_i), theta_i the angle the polygon's edge i
// subtends at p and gamma_i the unit normal of the plane through p and that edge.
#include <cmath>
#include <vector>

#include "candela/math/vec.h"

namespace candela::test {

using Polygon = std::vector<Vec3d>;

// Irradiance at p (unit normal n) from a polygon of uniform radiance L lying wholly on the side of
// p's tangent plane that n points to (then every edge term has the same sign).
inline double polygon_irradiance(const Vec3d& p, const Vec3d& n, const Polygon& polygon, double L) {
    double sum = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec3d a = normalize(polygon[i] - p), b = normalize(polygon[(i + 1) % polygon.size()] - p);
        Vec3d g = cross(a, b);
        double sin_theta = length(g);
        if (sin_theta == 0.0) continue;
        sum += std::atan2(sin_theta, dot(a, b)) * dot(n, g / sin_theta);
    }
    return 0.5 * L * std::abs(sum);
}

}  // namespace candela::test
