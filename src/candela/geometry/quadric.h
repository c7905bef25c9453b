#pragma once
// pbrt-v4's clipped quadrics: a cylinder, a partial sphere (z range, phi range) and a partial disk
// (inner radius, phi range), each in its own object space and placed by an affine transform. The
// full sphere and full disk have their own, faster shapes (sphere.h, disk.h); these carry pbrt-v4's
// clipping, (u, v) parameterisation and derivatives (pbrt-v4's shapes.h), evaluated in double.
//
// Object space, as pbrt-v4's: the axis is +z; phi = atan2(y, x) in [0, 2pi) is measured from +x
// towards +y and the surface keeps phi <= phi_max. Sphere: |p| = radius, z_min <= z <= z_max.
// Cylinder: x^2 + y^2 = radius^2, z_min <= z <= z_max. Disk: z = height, inner_radius <= r <= radius.
// The front side is the outside (the +z side of a disk), the other side when reverse_orientation.
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

enum class QuadricKind : uint8_t { kSphere, kCylinder, kDisk };

struct Quadric {
    QuadricKind kind = QuadricKind::kCylinder;
    double radius = 1.0;
    double z_min = -1.0, z_max = 1.0;            // sphere and cylinder
    double height = 0.0, inner_radius = 0.0;      // disk
    double phi_max = 0.0;                         // radians, in (0, 2pi]
    double theta_z_min = 0.0, theta_z_max = 0.0;  // sphere: acos(z_min / r), acos(z_max / r)
    Transform to_world, to_object;                // affine, each the other's inverse
    bool reverse_orientation = false;

    // The area in object space (pbrt-v4's Area()).
    CANDELA_HD double object_area() const;
    // Whether the sphere's z range is clipped at all (pbrt-v4 skips the test when it is not).
    CANDELA_HD bool clips_z_min() const { return z_min > -radius; }
    CANDELA_HD bool clips_z_max() const { return z_max < radius; }
};

// The quadrics with pbrt-v4's clamping of their parameters (shapes.h constructors): z_min and
// z_max in either order (a sphere's clamped to [-radius, radius]), phi_max in degrees clamped to
// [0, 360]. The caller checks that the result has area (radius > 0, z range and phi range > 0,
// inner radius below the radius).
Quadric make_sphere_quadric(double radius, double z_min, double z_max, double phi_max_degrees,
                            const Transform& to_world, bool reverse_orientation);
Quadric make_cylinder_quadric(double radius, double z_min, double z_max, double phi_max_degrees,
                              const Transform& to_world, bool reverse_orientation);
Quadric make_disk_quadric(double height, double radius, double inner_radius, double phi_max_degrees,
                          const Transform& to_world, bool reverse_orientation);

// World-space bounds, conservative: the transformed corners of the object-space box.
void quadric_world_bounds(const Quadric& q, Vec3d& lo, Vec3d& hi);

CANDELA_HD inline double Quadric::object_area() const {
    switch (kind) {
        case QuadricKind::kSphere: return phi_max * radius * (z_max - z_min);
        case QuadricKind::kCylinder: return phi_max * radius * (z_max - z_min);
        case QuadricKind::kDisk: return 0.5 * phi_max * (radius * radius - inner_radius * inner_radius);
    }
    return 0.0;
}

}  // namespace candela
