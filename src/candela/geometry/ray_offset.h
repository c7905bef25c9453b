#pragma once
// Spawning rays from surfaces without self-intersection, by error bounds rather than epsilons
// (pbrt-v4's approach; Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., 6.8).
// A hit point is computed on the surface with a conservative per-axis bound on its rounding
// error (SurfaceHit::p_error). Moving the origin along the geometric normal by the projection of
// that error box onto the normal, then one float further away, puts it strictly on the chosen
// side of the true surface, so the new ray cannot hit the surface where it starts.
#include <cmath>
#include <limits>

#include "candela/core/platform.h"
#include "candela/geometry/surface_hit.h"
#include "candela/math/next_float.h"
#include "candela/math/ray.h"

namespace candela {

// gamma(n) = n u / (1 - n u), u = 2^-24: the relative bound of n successive float roundings
// (Higham, "Accuracy and Stability of Numerical Algorithms", 3.1).
CANDELA_HD constexpr float rounding_gamma(int n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    return (float(n) * u) / (1.0f - float(n) * u);
}

// p moved off the surface to the side of unit geometric normal n, out of its error box.
CANDELA_HD inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& p_error, const Vec3f& n) {
    float d = dot(abs(n), p_error);
    Vec3f offset = n * d;
    Vec3f po = p + offset;
    // The addition above rounds, possibly back towards the surface: step one float further out
    // along n. The step follows n, not the offset, so that an exact point (zero error, e.g. on a
    // plane through the origin) still leaves the surface: Embree counts hits at t = tmin = 0.
    for (int i = 0; i < 3; ++i) {
        if (n[i] > 0.0f)
            po[i] = next_float_up(po[i]);
        else if (n[i] < 0.0f)
            po[i] = next_float_down(po[i]);
    }
    return po;
}

// A ray leaving the hit in direction w (either side of the surface).
CANDELA_HD inline Ray spawn_ray(const SurfaceHit& hit, const Vec3f& w) {
    Vec3f n = dot(w, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    return Ray{offset_ray_origin(hit.p, hit.p_error, n), w, 0.0f, kInfinity};
}

// Fraction of a shadow ray's length left out at its far end, so that it does not hit the surface
// of the point it aims at (that point's own error box is not known here).
inline constexpr float kShadowEpsilon = 1e-4f;

// A shadow ray from the hit towards point `target`; tmax stops it just before the target.
CANDELA_HD inline Ray spawn_ray_to(const SurfaceHit& hit, const Vec3f& target) {
    Vec3f n = dot(target - hit.p, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    Vec3f o = offset_ray_origin(hit.p, hit.p_error, n);
    return Ray{o, target - o, 0.0f, 1.0f - kShadowEpsilon};
}

}  // namespace candela
