#pragma once
// The two values every medium type answers with (pbrt-v4's MediumProperties and
// RayMajorantSegment), at a path's channels.
#include "candela/math/color.h"

namespace candela {

// The medium at one point: absorption and scattering coefficients (per unit length) and the
// radiance it emits (black for most media). Its phase function is the medium's (Medium::g).
struct MediumPoint {
    Color sigma_a, sigma_s, Le;
};

// A stretch [t0, t1] of a ray (t in units of length along the unit direction) over which
// sigma_maj bounds sigma_a + sigma_s in every channel: the majorant of delta and ratio tracking.
struct MajorantSegment {
    float t0 = 0.0f, t1 = 0.0f;
    Color sigma_maj;
};

}  // namespace candela
