#pragma once
// A point sampled on a light, seen from a reference point.
#include "candela/math/color.h"
#include "candela/math/vec.h"

namespace candela {

struct LightSample {
    Vec3f p;           // the point on the light (world), computed on its surface; for the
                       // environment and directional lights, unused (infinitely far along wi)
    Vec3f n;           // unit geometric normal of the light's front side at p
    Vec3f wi;          // unit direction from the reference point towards the light
    bool infinite = false;  // the environment or a directional light: a shadow ray towards it
                            // runs to infinity
    bool is_delta = false;  // a point, spot or directional light (delta_light_type.h): Le is the
                            // irradiance it gives a surface facing it, and no BSDF-sampled ray can
                            // find it, so multiple importance sampling must weight it 1
    Color Le;          // radiance leaving p towards the reference point (0 from behind a one-sided
                       // light); for a delta light, the irradiance it gives (see is_delta)
    float pdf = 0.0f;  // per unit solid angle at the reference point, INCLUDING the probability of
                       // having selected this light; for a delta light, that probability alone
};

}  // namespace candela
