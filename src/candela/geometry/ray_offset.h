#pragma once
// Spawning rays from surfaces without self-intersection, by error bounds rather than epsilons
// (pbrt-v4's approach; Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., 6.8).
// A hit point is computed on the surface with a conservative per-axis bound on its rounding
// error (SurfaceHit::p_error). Moving the origin along the geometric normal by the projection of
// that error box onto the normal, plus the rounding of that move, puts it strictly on the chosen
// side of the true surface, so the new ray cannot hit the surface where it starts.
#include <cmath>
#include <limits>

#include "candela/core/platform.h"
#include "candela/geometry/surface_hit.h"
#include "candela/math/ray.h"

namespace candela {

// gamma(n) = n u / (1 - n u), u = 2^-24: the relative bound of n successive float roundings
// (Higham, "Accuracy and Stability of Numerical Algorithms", 3.1).
CANDELA_HD constexpr float rounding_gamma(int n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    return (float(n) * u) / (1.0f - float(n) * u);
}

// p moved off the surface to the side of unit geometric normal n, out of its error box.
// pbrt-v4 adds n d (d: the error box projected onto n) and then steps each coordinate one float
// further along n, because the addition rounds, possibly back towards the surface. Here the
// rounding is paid for in d instead, which needs no per-coordinate branches: with u = 2^-24,
// the product n_i d' and the sum p_i + n_i d' round by at most u of their size, which moves the
// point along n by at most u (d' + |p|_1) plus u d' from n's own rounding; so
// d' = (d + 2u |p|_1) (1 + 8u) leaves it at least d + u |p|_1 out: beyond the box whenever p
// or its error is nonzero (for every hit but one exactly at the origin with no error).
CANDELA_HD inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& p_error, const Vec3f& n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    const Vec3f abs_p = abs(p);
    const float d = (dot(abs(n), p_error) + 2.0f * u * (abs_p.x + abs_p.y + abs_p.z)) * (1.0f + 8.0f * u);
    return p + n * d;
}

// A ray leaving the hit in direction w (either side of the surface).
CANDELA_HD inline Ray spawn_ray(const SurfaceHit& hit, const Vec3f& w) {
    Vec3f n = dot(w, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    return Ray{offset_ray_origin(hit.p, hit.p_error, n), w, 0.0f, kInfinity, hit.time};
}

// Fraction of a shadow ray's length left out at its far end, so that it does not hit the surface
// of the point it aims at (that point's own error box is not known here).
inline constexpr float kShadowEpsilon = 1e-4f;

// A shadow ray from the hit towards point `target`; tmax stops it just before the target.
CANDELA_HD inline Ray spawn_ray_to(const SurfaceHit& hit, const Vec3f& target) {
    Vec3f n = dot(target - hit.p, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    Vec3f o = offset_ray_origin(hit.p, hit.p_error, n);
    return Ray{o, target - o, 0.0f, 1.0f - kShadowEpsilon, hit.time};
}

}  // namespace candela
