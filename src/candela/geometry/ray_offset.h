#pragma once
// Spawning rays from surfaces without self-intersection. A hit point is computed on the surface,
// so it is off by a few ulps at most; we move the origin off the surface along the geometric
// normal by a bound that covers that error, in integer ulps so it scales with the magnitude of
// the coordinates (Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems, ch. 6). No per-call epsilon.
#include <bit>
#include <cmath>
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/geometry/surface_hit.h"
#include "candela/math/ray.h"

namespace candela {

namespace detail {
// Near the origin ulps get too small to cover the error, so there a fixed offset is used.
inline constexpr float kOffsetOrigin = 1.0f / 32.0f;
inline constexpr float kOffsetFloatScale = 1.0f / 65536.0f;
inline constexpr float kOffsetIntScale = 256.0f;

CANDELA_HD inline float offset_coordinate(float p, float n) {
    if (std::abs(p) < kOffsetOrigin) return p + kOffsetFloatScale * n;
    auto ulps = static_cast<int32_t>(kOffsetIntScale * n);
    int32_t bits = std::bit_cast<int32_t>(p);
    // For negative p the bit pattern grows with the magnitude, so the step is mirrored.
    return std::bit_cast<float>(bits + (p < 0.0f ? -ulps : ulps));
}
}  // namespace detail

// p moved off the surface to the side of unit geometric normal n.
CANDELA_HD inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& n) {
    return {detail::offset_coordinate(p.x, n.x), detail::offset_coordinate(p.y, n.y),
            detail::offset_coordinate(p.z, n.z)};
}

// A ray leaving the hit in direction w (either side of the surface).
CANDELA_HD inline Ray spawn_ray(const SurfaceHit& hit, const Vec3f& w) {
    Vec3f n = dot(w, hit.ng) >= 0.0f ? hit.ng : -hit.ng;
    return Ray{offset_ray_origin(hit.p, n), w, 0.0f, kInfinity};
}

// A shadow ray from the hit towards point `target` (itself on a surface with unit geometric
// normal target_n): both ends are offset, and tmax = 1 stops it at the target's offset point.
CANDELA_HD inline Ray spawn_ray_to(const SurfaceHit& hit, const Vec3f& target, const Vec3f& target_n) {
    Vec3f o = offset_ray_origin(hit.p, dot(target - hit.p, hit.ng) >= 0.0f ? hit.ng : -hit.ng);
    Vec3f end = offset_ray_origin(target, dot(o - target, target_n) >= 0.0f ? target_n : -target_n);
    return Ray{o, end - o, 0.0f, 1.0f};
}

}  // namespace candela
