#pragma once
// A sphere, kept in double so that smallpt's walls (radius 1e5, centres 1e5 away) intersect
// precisely. Its front side is the outside unless `reverse_orientation`.
#include "candela/math/vec.h"

namespace candela {

struct Sphere {
    Vec3d center;
    double radius = 1.0;
    bool reverse_orientation = false;
};

}  // namespace candela
