#include "candela/geometry/quadric.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "candela/math/constants.h"

namespace candela {

namespace {

double clamped_phi_max(double degrees) { return std::clamp(degrees, 0.0, 360.0) * (kPiD / 180.0); }

Quadric placed(QuadricKind kind, const Transform& to_world, bool reverse_orientation) {
    Quadric q;
    q.kind = kind;
    q.to_world = to_world;
    q.to_object = to_world.inverse();
    q.reverse_orientation = reverse_orientation;
    return q;
}

}  // namespace

Quadric make_sphere_quadric(double radius, double z_min, double z_max, double phi_max_degrees,
                            const Transform& to_world, bool reverse_orientation) {
    Quadric q = placed(QuadricKind::kSphere, to_world, reverse_orientation);
    q.radius = radius;
    const double lo = std::min(z_min, z_max), hi = std::max(z_min, z_max);
    q.z_min = std::clamp(lo, -radius, radius);
    q.z_max = std::clamp(hi, -radius, radius);
    q.theta_z_min = std::acos(std::clamp(lo / radius, -1.0, 1.0));
    q.theta_z_max = std::acos(std::clamp(hi / radius, -1.0, 1.0));
    q.phi_max = clamped_phi_max(phi_max_degrees);
    return q;
}

Quadric make_cylinder_quadric(double radius, double z_min, double z_max, double phi_max_degrees,
                              const Transform& to_world, bool reverse_orientation) {
    Quadric q = placed(QuadricKind::kCylinder, to_world, reverse_orientation);
    q.radius = radius;
    q.z_min = std::min(z_min, z_max);
    q.z_max = std::max(z_min, z_max);
    q.phi_max = clamped_phi_max(phi_max_degrees);
    return q;
}

Quadric make_disk_quadric(double height, double radius, double inner_radius, double phi_max_degrees,
                          const Transform& to_world, bool reverse_orientation) {
    Quadric q = placed(QuadricKind::kDisk, to_world, reverse_orientation);
    q.height = height;
    q.radius = radius;
    q.inner_radius = inner_radius;
    q.phi_max = clamped_phi_max(phi_max_degrees);
    return q;
}

void quadric_world_bounds(const Quadric& q, Vec3d& lo, Vec3d& hi) {
    const double r = q.radius;
    const double z0 = q.kind == QuadricKind::kDisk ? q.height : q.kind == QuadricKind::kSphere ? -r : q.z_min;
    const double z1 = q.kind == QuadricKind::kDisk ? q.height : q.kind == QuadricKind::kSphere ? r : q.z_max;
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = Vec3d(-std::numeric_limits<double>::infinity());
    for (int k = 0; k < 8; ++k) {
        const Vec3d p = q.to_world.apply_point(Vec3d(k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? z1 : z0));
        lo = min(lo, p);
        hi = max(hi, p);
    }
}

}  // namespace candela
