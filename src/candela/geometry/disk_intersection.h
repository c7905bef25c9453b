#pragma once
// Ray-disk intersection and the disk's surface parameterisation (uv and its derivatives), in
// double as for spheres (sphere_intersection.h): a disk far from the origin or a ray from far
// away keeps float-level precision at the hit.
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/disk.h"
#include "candela/geometry/shading_geometry.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// The ray parameter t where o + t d crosses the disk, with tmin < t < tmax, if it does. d need
// not be unit. A ray in the disk's plane misses it (pbrt-v4's Disk::BasicIntersect): it would
// touch the disk along a line of zero area.
CANDELA_HD inline std::optional<double> intersect_disk(const Disk& disk, const Vec3d& o, const Vec3d& d, double tmin,
                                                       double tmax) {
    double along_normal = dot(d, disk.normal);
    if (along_normal == 0.0) return std::nullopt;
    double t = dot(disk.center - o, disk.normal) / along_normal;
    if (!(t > tmin && t < tmax)) return std::nullopt;
    Vec2<double> q = disk.local(o + d * t);
    if (q.x * q.x + q.y * q.y > 1.0) return std::nullopt;
    return t;
}

// The point of the disk's plane nearest to p (a hit moved onto the plane, in double).
CANDELA_HD inline Vec3d project_to_disk_plane(const Disk& disk, const Vec3d& p) {
    return p - disk.normal * dot(p - disk.center, disk.normal);
}

// (u, v) of a point of the disk (disk.h): u = phi / 2pi in [0, 1), v = 1 - r in [0, 1].
CANDELA_HD inline Vec2f disk_uv(const Disk& disk, const Vec3d& p) {
    Vec2<double> q = disk.local(p);
    double phi = std::atan2(q.y, q.x);
    auto u = static_cast<float>((phi < 0.0 ? phi + 2.0 * kPiD : phi) / (2.0 * kPiD));
    if (!(u < 1.0f)) u = 0.0f;  // just below 2pi rounds to 1, which is u = 0 on the circle
    double v = 1.0 - std::sqrt(q.x * q.x + q.y * q.y);
    return Vec2f(u, static_cast<float>(v > 0.0 ? v : 0.0));
}

// The shading geometry at a point p of the disk. With (x, y) its local coordinates and
// r = sqrt(x^2 + y^2), the point of (u, v) is center + (1 - v) (cos 2pi u axis_u + sin 2pi u axis_v),
// so dpdu = 2pi (-y axis_u + x axis_v) and dpdv = -(x axis_u + y axis_v) / r (pbrt-v4's Disk, in
// world space), and cross(dpdu, dpdv) = 2pi r cross(axis_u, axis_v). A disk is flat: dndu =
// dndv = 0. At the centre (r = 0) u is undefined, and the fallback frame stands in.
CANDELA_HD inline ShadingGeometry disk_shading_geometry(const Disk& disk, const Vec3d& p) {
    ShadingGeometry g;
    g.uv = disk_uv(disk, p);
    const Vec2<double> q = disk.local(p);
    const double r = std::sqrt(q.x * q.x + q.y * q.y);
    if (r > 0.0) {
        g.dpdu = Vec3f((disk.axis_v * q.x - disk.axis_u * q.y) * (2.0 * kPiD));
        g.dpdv = Vec3f((disk.axis_u * q.x + disk.axis_v * q.y) * (-1.0 / r));
    }
    if (!(r > 0.0) || length_squared(cross(g.dpdu, g.dpdv)) == 0.0f)
        fallback_tangents(Vec3f(disk.normal), g.dpdu, g.dpdv);
    g.dndu = g.dndv = Vec3f(0.0f);
    return g;
}

}  // namespace candela
