#include "candela/geometry/disk.h"

#include <cmath>

namespace candela {

Disk make_disk(const Vec3d& center, const Vec3d& axis_u, const Vec3d& axis_v, const Vec3d& normal) {
    Disk d;
    d.center = center;
    d.axis_u = axis_u;
    d.axis_v = axis_v;
    d.normal = normal;
    // dual_u is perpendicular to axis_v and the normal, scaled so that dot(axis_u, dual_u) = 1;
    // likewise dual_v. The sign of the normal cancels in each quotient.
    Vec3d cu = cross(axis_v, normal), cv = cross(normal, axis_u);
    d.dual_u = cu / dot(axis_u, cu);
    d.dual_v = cv / dot(axis_v, cv);
    return d;
}

Disk make_round_disk(const Vec3d& center, const Vec3d& normal, double radius) {
    Vec3d n = normalize(normal);
    // Duff et al. 2017 ("Building an Orthonormal Basis, Revisited"), in double: (s, t, n) is
    // right-handed, and (x, y, z) for n = +z.
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    Vec3d s(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    Vec3d t(b, sign + n.y * n.y * a, -n.y);
    return make_disk(center, s * radius, t * radius, n);
}

Disk transform_disk(const Disk& disk, const Transform& to_world, bool reverse_orientation) {
    Vec3d n = normalize(to_world.apply_normal(disk.normal));
    return make_disk(to_world.apply_point(disk.center), to_world.apply_vector(disk.axis_u),
                     to_world.apply_vector(disk.axis_v), reverse_orientation ? -n : n);
}

}  // namespace candela
