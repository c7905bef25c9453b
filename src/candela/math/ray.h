#pragma once
// A ray o + t d for t in [tmin, tmax]. d need not be unit length, but rays from the camera and
// from BSDF sampling are. `time` is where in the shutter the ray is, in [0, 1] (Embree's ray time):
// only moving shapes look at it, and every ray of a path keeps the camera sample's.
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

struct Ray {
    Vec3f o;
    Vec3f d;
    float tmin = 0.0f;
    float tmax = kInfinity;
    float time = 0.0f;
    CANDELA_HD Vec3f at(float t) const { return o + d * t; }
};

}  // namespace candela
