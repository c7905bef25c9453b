#pragma once
// Warps: maps from uniform samples u in [0, 1)^2 (or [0, 1)) to other domains, each next to its
// density (Nori's warp.h layout, yocto's sample_X / X_pdf pairs). The comment on each pdf names
// its measure. A pdf takes the warped value and returns 0 outside the warp's support, so it can
// be checked against the samples (tests/sampling/warps_stat_test.cpp).
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/select.h"
#include "candela/math/vec.h"

namespace candela {

// ---- unit disk -------------------------------------------------------------------------------

// cos and sin of (pi/4) t for t in [-1, 1], by the minimax polynomials of Cephes' cosf and sinf
// (Moshier, "Methods and Programs for Mathematical Functions", 1989) on |angle| <= pi/4: within
// 1.1e-7 of std::cos/std::sin, without libm's range reduction (which was 2% of a render's time)
// and two Horner steps shorter than the Taylor series of the same accuracy.
CANDELA_HD inline Vec2f cos_sin_quarter_pi(float t) {
    float x = kPiOver4 * t, z = x * x;
    float c = 1.0f - 0.5f * z + z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
    float s = x + x * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    return {c, s};
}

// Uniform point on the unit disk by Shirley and Chiu's concentric map (1997, "A Low Distortion
// Map Between Disk and Square"): it keeps strata compact, unlike the polar r = sqrt(u) map.
// Also returns the point's radius r (its length up to the rounding of cos and sin), known
// before the angle's polynomials are evaluated.
struct ConcentricDiskSample {
    Vec2f p;
    float r = 0.0f;  // in [0, 1]
};
CANDELA_HD inline ConcentricDiskSample sample_concentric_disk_and_radius(Vec2f u) {
    float a = 2.0f * u.x - 1.0f;
    float b = 2.0f * u.y - 1.0f;
    // Concentric squares map to concentric circles; the larger coordinate picks the wedge. The
    // angle is (pi/4) (b/a) in the first, pi/2 - (pi/4) (a/b) in the second: cos and sin swap.
    // Selects instead of branches: the wedge is random (math/select.h).
    SelectMask wide = greater(std::abs(a), std::abs(b));
    float r = select(wide, a, b);
    float t = r != 0.0f ? select(wide, b, a) / r : 0.0f;  // r = 0 only for a = b = 0: the centre
    Vec2f cs = cos_sin_quarter_pi(t);
    return {{r * select(wide, cs.x, cs.y), r * select(wide, cs.y, cs.x)}, std::abs(r)};
}
CANDELA_HD inline Vec2f sample_concentric_disk(Vec2f u) { return sample_concentric_disk_and_radius(u).p; }
// Per unit area of the plane: 1/pi inside the unit disk.
CANDELA_HD inline float concentric_disk_pdf(Vec2f p) {
    return p.x * p.x + p.y * p.y <= 1.0f ? kInvPi : 0.0f;
}

// ---- sphere and hemispheres ------------------------------------------------------------------

// Uniform direction on the unit sphere: z = cos(theta) is uniform on [-1, 1] (Archimedes).
CANDELA_HD inline Vec3f sample_uniform_sphere(Vec2f u) {
    float z = 1.0f - 2.0f * u.x;
    float r = safe_sqrt(1.0f - z * z);
    float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
// Per unit solid angle: 1/(4 pi) everywhere.
CANDELA_HD inline float uniform_sphere_pdf([[maybe_unused]] Vec3f w) { return kInv4Pi; }

// Uniform direction on the hemisphere z >= 0: z uniform on [0, 1].
CANDELA_HD inline Vec3f sample_uniform_hemisphere(Vec2f u) {
    float z = u.x;
    float r = safe_sqrt(1.0f - z * z);
    float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
// Per unit solid angle: 1/(2 pi) for z >= 0, else 0.
CANDELA_HD inline float uniform_hemisphere_pdf(Vec3f w) { return w.z >= 0.0f ? kInv2Pi : 0.0f; }

// Cosine-weighted direction on the hemisphere z >= 0 (Malley's method: a uniform disk point
// lifted onto the hemisphere has density cos(theta)/pi).
CANDELA_HD inline Vec3f sample_cosine_hemisphere(Vec2f u) {
    ConcentricDiskSample d = sample_concentric_disk_and_radius(u);
    // z from the radius rather than from the point: the square root then runs beside the angle's
    // polynomials instead of after them (it is on the path's critical chain, bench/RESULTS.md).
    float z = safe_sqrt(1.0f - d.r * d.r);
    return {d.p.x, d.p.y, z};
}
// Per unit solid angle: cos(theta)/pi for z >= 0, else 0.
CANDELA_HD inline float cosine_hemisphere_pdf(Vec3f w) { return w.z >= 0.0f ? w.z * kInvPi : 0.0f; }

// Uniform direction in the cone of half-angle theta_max around +z. Works with 1 - cos(theta)
// rather than cos(theta), so narrow cones (distant sphere lights) keep their precision.
CANDELA_HD inline Vec3f sample_uniform_cone(Vec2f u, float cos_theta_max) {
    float one_minus_cos = u.x * (1.0f - cos_theta_max);
    float z = 1.0f - one_minus_cos;
    float r = safe_sqrt(one_minus_cos * (2.0f - one_minus_cos));  // sin(theta), cancellation-free
    float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}
// Per unit solid angle: 1 / (2 pi (1 - cos_theta_max)) inside the cone, else 0.
CANDELA_HD inline float uniform_cone_pdf(Vec3f w, float cos_theta_max) {
    return w.z >= cos_theta_max ? 1.0f / (2.0f * kPi * (1.0f - cos_theta_max)) : 0.0f;
}

// ---- triangle --------------------------------------------------------------------------------

// Uniform barycentrics (b0, b1, b2) of a triangle p0 p1 p2 (the point is b0 p0 + b1 p1 + b2 p2),
// by Heitz's low-distortion square-to-triangle map (2019, "A Low-Distortion Map Between Triangle
// and Square"): no square root, and strata stay compact.
CANDELA_HD inline Vec3f sample_uniform_triangle(Vec2f u) {
    // Halve the smaller coordinate and subtract it from the larger (selects, not a branch: which
    // one is smaller is random; math/select.h).
    SelectMask x_smaller = greater(u.y, u.x);
    float half = 0.5f * select(x_smaller, u.x, u.y);
    float rest = select(x_smaller, u.y, u.x) - half;
    float b0 = select(x_smaller, half, rest);
    float b1 = select(x_smaller, rest, half);
    return {b0, b1, 1.0f - b0 - b1};
}
// Per unit area of a triangle of area `area`: 1/area (the map is uniform in area).
CANDELA_HD inline float uniform_triangle_pdf(float area) { return 1.0f / area; }

// ---- 1D tent ---------------------------------------------------------------------------------

// A value in [-radius, radius] with the tent density (radius - |x|) / radius^2: each half
// inverts its quadratic CDF (smallpt's dx = r1 < 1 ? sqrt(r1) - 1 : 1 - sqrt(2 - r1)).
CANDELA_HD inline float sample_tent(float u, float radius) {
    float t = u < 0.5f ? std::sqrt(2.0f * u) - 1.0f : 1.0f - std::sqrt(2.0f - 2.0f * u);
    return t * radius;
}
// Per unit length: max(0, radius - |x|) / radius^2.
CANDELA_HD inline float tent_pdf(float x, float radius) {
    float d = radius - std::abs(x);
    return d > 0.0f ? d / (radius * radius) : 0.0f;
}

}  // namespace candela
