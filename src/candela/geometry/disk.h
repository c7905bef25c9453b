#pragma once
// A disk: the points center + x axis_u + y axis_v with x^2 + y^2 <= 1. It is pbrt-v4's Disk
// (inner radius 0, phimax 360 degrees) placed by its centre and axes rather than by an object
// transform; a transform that scales unevenly makes it an ellipse, which this form still holds
// exactly (an affine map takes the unit disk to center + x axis_u' + y axis_v'). Kept in double,
// as spheres are, so that intersections stay precise far from the origin.
//
// Surface parameterisation (pbrt-v4's Disk::InteractionFromIntersection): with (x, y) the local
// coordinates of a point, phi = atan2(y, x) in [0, 2pi), u = phi / 2pi and v = 1 - sqrt(x^2 + y^2):
// v = 1 at the centre, 0 on the rim.
#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

struct Disk {
    Vec3d center;
    Vec3d axis_u, axis_v;  // images of the local x and y radii (orthogonal and radius long when round)
    Vec3d normal;          // unit, on the front side
    // The dual basis of (axis_u, axis_v) in the disk's plane: a point p of the plane has local
    // coordinates x = dot(p - center, dual_u), y = dot(p - center, dual_v).
    Vec3d dual_u, dual_v;

    CANDELA_HD double area() const { return kPiD * length(cross(axis_u, axis_v)); }
    // The local (x, y) of a point p of the disk's plane.
    CANDELA_HD Vec2<double> local(const Vec3d& p) const {
        Vec3d q = p - center;
        return {dot(q, dual_u), dot(q, dual_v)};
    }
    // The point of local coordinates (x, y).
    CANDELA_HD Vec3d point(double x, double y) const { return center + axis_u * x + axis_v * y; }
};

// A disk from its axes and front normal (unit, perpendicular to both axes; either side of
// cross(axis_u, axis_v)); computes the dual basis. The axes must not be parallel.
Disk make_disk(const Vec3d& center, const Vec3d& axis_u, const Vec3d& axis_v, const Vec3d& normal);

// The round disk of the scene file: centre, front normal (any nonzero length) and radius. Its
// local x and y axes are those of the orthonormal frame around the normal (Duff et al. 2017, as
// Frame::from_normal): for the normal +z they are +x and +y, pbrt-v4's object space, so that
// u = 0 lies along +x there.
Disk make_round_disk(const Vec3d& center, const Vec3d& normal, double radius);

// The disk moved by `to_world`: centre as a point, axes as vectors, the normal by the inverse
// transpose, so that the front side stays where it was under a mirror (pbrt's rule, as
// transform_mesh); then flipped when reverse_orientation.
Disk transform_disk(const Disk& disk, const Transform& to_world, bool reverse_orientation);

}  // namespace candela
