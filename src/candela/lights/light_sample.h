#pragma once
// A point sampled on a light, seen from a reference point.
#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

struct LightSample {
    Vec3f p;           // the point on the light (world), computed on its surface; for the
                       // environment, unused (it is infinitely far along wi)
    Vec3f n;           // unit geometric normal of the light's front side at p
    Vec3f wi;          // unit direction from the reference point towards the light
    bool infinite = false;  // the environment: a shadow ray towards it runs to infinity
    Rgb Le;            // radiance leaving p towards the reference point (0 from behind a one-sided light)
    float pdf = 0.0f;  // per unit solid angle at the reference point, INCLUDING the probability of
                       // having selected this light
};

}  // namespace candela
