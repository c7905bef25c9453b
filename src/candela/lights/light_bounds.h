#pragma once
// What pbrt-v4's BVH light sampler knows of a light without sampling it (pbrt-v4's LightBounds,
// lights.h; "Physically Based Rendering", 4th ed., section 12.6.3): where it is (a box), how much
// it emits (phi), which way its surfaces face (a cone of normals, axis w and half-angle theta_o)
// and how far past those normals it emits (theta_e: pi/2 for a diffuse surface, the falloff width
// for a spot light). importance() bounds, up to a constant, the light's contribution at a point:
// zero exactly where pbrt-v4's is zero (behind a one-sided emitter, outside a spot's cone), so
// that the sampler never picks a light that cannot contribute there.
#include <algorithm>
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/bounds.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// A cone of directions: unit axis w and the cosine of its half-angle (pbrt-v4's DirectionCone).
// Empty when cos_theta is +infinity; the whole sphere when it is -1.
struct DirectionCone {
    Vec3f w{0.0f, 0.0f, 1.0f};
    float cos_theta = kInfinity;

    CANDELA_HD bool empty() const { return cos_theta == kInfinity; }
    CANDELA_HD static DirectionCone entire_sphere() { return {Vec3f{0.0f, 0.0f, 1.0f}, -1.0f}; }
};

// acos clamped to [-1, 1], so that round-off past 1 gives 0 rather than NaN (safe_sqrt: constants.h).
CANDELA_HD inline float safe_acos(float c) { return std::acos(std::clamp(c, -1.0f, 1.0f)); }

// The smallest cone (of this construction) holding both cones (pbrt-v4's Union, vecmath.cpp):
// the spread is half the sum of both spreads and the angle between the axes, and the axis is a's
// rotated towards b's by what a's spread lacks.
CANDELA_HD inline DirectionCone union_of(const DirectionCone& a, const DirectionCone& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
    const float theta_d = safe_acos(dot(a.w, b.w));
    if (std::min(theta_d + theta_b, kPi) <= theta_a) return a;
    if (std::min(theta_d + theta_a, kPi) <= theta_b) return b;
    const float theta_o = (theta_a + theta_d + theta_b) * 0.5f;
    if (theta_o >= kPi) return DirectionCone::entire_sphere();
    const float theta_r = theta_o - theta_a;
    const Vec3f axis = cross(a.w, b.w);
    if (length_squared(axis) == 0.0f) return DirectionCone::entire_sphere();
    // Rodrigues' rotation of a.w by theta_r about the unit axis k (k is perpendicular to a.w).
    const Vec3f k = normalize(axis);
    const Vec3f w = a.w * std::cos(theta_r) + cross(k, a.w) * std::sin(theta_r);
    return {normalize(w), std::cos(theta_o)};
}

struct LightBounds {
    Bounds3f bounds;
    Vec3f w{0.0f, 0.0f, 1.0f};  // axis of the cone of emitting normals
    float phi = 0.0f;           // emitted power (any fixed measure: only ratios matter)
    float cos_theta_o = 1.0f;   // half-angle of the normals' cone
    float cos_theta_e = 0.0f;   // how far past a normal light leaves: pi/2 for a diffuse emitter
    bool two_sided = false;

    CANDELA_HD Vec3f centroid() const { return bounds.center(); }

    // pbrt-v4's LightBounds::Importance at point p with surface normal n (zero in a medium, where
    // no cosine applies): phi cos(theta') / d^2, theta' the smallest angle between an emitting
    // direction of the bounds and the direction to p, times the bounded |cos| at p.
    CANDELA_HD float importance(const Vec3f& p, const Vec3f& n) const;
};

// The bounds of both (pbrt-v4's Union of LightBounds): one of zero power is ignored.
CANDELA_HD inline LightBounds union_of(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0.0f) return b;
    if (b.phi == 0.0f) return a;
    const DirectionCone cone = union_of(DirectionCone{a.w, a.cos_theta_o}, DirectionCone{b.w, b.cos_theta_o});
    LightBounds u;
    u.bounds = a.bounds;
    u.bounds.extend(b.bounds);
    u.w = cone.w;
    u.phi = a.phi + b.phi;
    u.cos_theta_o = cone.cos_theta;
    u.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
    u.two_sided = a.two_sided || b.two_sided;
    return u;
}

CANDELA_HD inline float LightBounds::importance(const Vec3f& p, const Vec3f& n) const {
    const Vec3f pc = bounds.center();
    const Vec3f diag = bounds.diagonal();
    // The squared distance, clamped to half the box's diagonal so that a point inside a large
    // box does not get an unbounded weight.
    const float d2 = std::max(length_squared(p - pc), length(diag) * 0.5f);

    // cos(a - b) and sin(a - b), clamped to 1 and 0 when a < b (the angle cannot go below 0).
    auto cos_sub_clamped = [](float sin_a, float cos_a, float sin_b, float cos_b) {
        return cos_a > cos_b ? 1.0f : cos_a * cos_b + sin_a * sin_b;
    };
    auto sin_sub_clamped = [](float sin_a, float cos_a, float sin_b, float cos_b) {
        return cos_a > cos_b ? 0.0f : sin_a * cos_b - cos_a * sin_b;
    };

    // theta_w: between the cone's axis and the direction from the box's centre to p.
    const Vec3f wi = normalize(p - pc);
    float cos_theta_w = dot(w, wi);
    if (two_sided) cos_theta_w = std::abs(cos_theta_w);
    const float sin_theta_w = safe_sqrt(1.0f - cos_theta_w * cos_theta_w);

    // theta_b: the half-angle of the box's bounding sphere seen from p (the whole sphere inside).
    const Vec3f center = bounds.center();
    const float radius = length(diag) * 0.5f;
    const float dist2 = length_squared(p - center);
    const float cos_theta_b = dist2 < radius * radius ? -1.0f : safe_sqrt(1.0f - radius * radius / dist2);
    const float sin_theta_b = safe_sqrt(1.0f - cos_theta_b * cos_theta_b);

    // theta' = max(0, theta_w - theta_o - theta_b); nothing leaves beyond theta_e.
    const float sin_theta_o = safe_sqrt(1.0f - cos_theta_o * cos_theta_o);
    const float cos_theta_x = cos_sub_clamped(sin_theta_w, cos_theta_w, sin_theta_o, cos_theta_o);
    const float sin_theta_x = sin_sub_clamped(sin_theta_w, cos_theta_w, sin_theta_o, cos_theta_o);
    const float cos_theta_p = cos_sub_clamped(sin_theta_x, cos_theta_x, sin_theta_b, cos_theta_b);
    if (cos_theta_p <= cos_theta_e) return 0.0f;

    float importance = phi * cos_theta_p / d2;
    // At a surface, the incident cosine, bounded the same way (|cos|: either side may transmit).
    if (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f) {
        const float cos_theta_i = abs_dot(wi, n);
        const float sin_theta_i = safe_sqrt(1.0f - cos_theta_i * cos_theta_i);
        importance *= cos_sub_clamped(sin_theta_i, cos_theta_i, sin_theta_b, cos_theta_b);
    }
    return std::max(importance, 0.0f);
}

}  // namespace candela
