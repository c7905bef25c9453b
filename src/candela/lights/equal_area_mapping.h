#pragma once
// Clarberg's equal-area octahedral map between the unit square and the unit sphere ("Fast
// Equal-Area Mapping of the (Hemi)Sphere using SIMD", JGT 13(3), 2008), with pbrt-v4's
// orientation (EqualAreaSquareToSphere / EqualAreaSphereToSquare in util/math.cpp): with
// (u', v') = 2 (u, v) - 1, the inner diamond |u'| + |v'| < 1 is the hemisphere z > 0 (the
// centre is +z), the four corner triangles are z < 0 (every corner is -z), and the signs of
// (u', v') are those of (x, y). Equal areas of the square are equal solid angles: a density p
// over the square is p / (4 pi) per steradian. pbrt-v4's image infinite lights store their
// maps this way.
//
// The square's edges fold onto themselves: (0, v) and (0, 1 - v) are the same direction (and so
// for every edge), which is how a lookup continues across an edge (octahedral_wrap_texel).
#include <algorithm>
#include <cmath>
#include <utility>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// The unit direction of square point p in [0, 1]^2.
CANDELA_HD inline Vec3f equal_area_square_to_sphere(Vec2f p) {
    const float u = 2.0f * p.x - 1.0f, v = 2.0f * p.y - 1.0f;
    const float au = std::abs(u), av = std::abs(v);
    // The signed distance from the diamond's edge: > 0 inside (upper hemisphere).
    const float signed_distance = 1.0f - (au + av);
    const float r = 1.0f - std::abs(signed_distance);  // the radius of the concentric square
    // phi runs 0 -> pi/2 along the square of radius r from the u axis to the v axis.
    const float phi = (r == 0.0f ? 1.0f : (av - au) / r + 1.0f) * kPiOver4;
    const float z = std::copysign(1.0f - r * r, signed_distance);
    // sin(theta) = r sqrt(2 - r^2), since z = +-(1 - r^2).
    const float sin_theta = r * std::sqrt(std::max(0.0f, 2.0f - r * r));
    return {std::copysign(std::cos(phi), u) * sin_theta, std::copysign(std::sin(phi), v) * sin_theta, z};
}

// The square point of unit direction d, in [0, 1]^2: the inverse of the map above. phi comes
// from atan2 (pbrt-v4 uses a polynomial approximation), so a round trip is exact to rounding.
CANDELA_HD inline Vec2f equal_area_sphere_to_square(const Vec3f& d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    const float r = std::sqrt(std::max(0.0f, 1.0f - az));
    const float phi = std::atan2(ay, ax) * (1.0f / kPiOver2);  // in [0, 1]
    float v = phi * r;
    float u = r - v;
    if (d.z < 0.0f) {  // the lower hemisphere: the corner triangles, mirrored across the diamond
        std::swap(u, v);
        u = 1.0f - u;
        v = 1.0f - v;
    }
    u = std::copysign(u, d.x);
    v = std::copysign(v, d.y);
    return {std::clamp(0.5f * (u + 1.0f), 0.0f, 1.0f), std::clamp(0.5f * (v + 1.0f), 0.0f, 1.0f)};
}

// Texel (x, y), at most one texel outside a w x h map, moved to the texel that holds the same
// direction: across a vertical edge the map continues mirrored in u and flipped in v, across a
// horizontal edge mirrored in v and flipped in u (a corner takes both). This is the exact mirror
// of texel centres, so a bilinear lookup is continuous across the edges. (pbrt-v4's
// RemapPixelCoords maps texel -1 to 1 rather than 0 on the low edges, a half-texel shift there;
// its nearest lookup, the one its lights use, never reaches it inside the square.)
CANDELA_HD inline void octahedral_wrap_texel(int& x, int& y, int w, int h) {
    if (x < 0) {
        x = -1 - x;
        y = h - 1 - y;
    } else if (x >= w) {
        x = 2 * w - 1 - x;
        y = h - 1 - y;
    }
    if (y < 0) {
        x = w - 1 - x;
        y = -1 - y;
    } else if (y >= h) {
        x = w - 1 - x;
        y = 2 * h - 1 - y;
    }
}

}  // namespace candela
