#pragma once
// From Embree's answer on a curve (the segment, u along it, the ray's t) to pbrt-v4's surface
// interaction (Curve::InteractionFromIntersection): the point, the normal, (u, v) and the error
// bound. Embree says where the ray meets the curve; what the surface looks like there is pbrt's:
//  - dpdu is the segment's derivative at u;
//  - dpdv is dpdu turned by +90 degrees about the ray (flat and cylinder curves face the ray),
//    or cross(n_ribbon, dpdu) for ribbons, n_ribbon the end normals slerped at u (a ribbon is
//    traced as pbrt-v4 traces it: a ray-facing ribbon narrowed to |cos(n_ribbon, ray)| of its
//    width, by an Embree filter on a flat curve);
//  - a cylinder's dpdv is then turned about dpdu by -theta, theta from -90 to 90 degrees as v goes
//    from 0 to 1, so that its normal sweeps across the width like a tube's;
//  - the normal is cross(dpdu, dpdv), flipped when reverse_orientation;
//  - v is the signed distance from the curve's centre across the ray-facing ribbon, over the width
//    the ray sees, plus 1/2;
//  - the error bound is the width in every axis (pbrt-v4: the intersection is found to a fraction
//    of the width, and offsetting spawned rays by it keeps them off the curve they leave).
#include <algorithm>
#include <cmath>

#include "candela/geometry/curves.h"
#include "candela/geometry/shading_geometry.h"
#include "candela/math/vec.h"

namespace candela {

struct CurveHit {
    Vec3f p, p_error;
    Vec3f n;  // unit
    Vec2f uv;
};

// `v` turned about unit `axis` by `angle` radians, counter-clockwise seen with the axis towards
// the viewer; v is perpendicular to the axis.
inline Vec3f rotate_perpendicular(const Vec3f& v, const Vec3f& axis, float angle) {
    return v * std::cos(angle) + cross(axis, v) * std::sin(angle);
}

// A ribbon's normal at u: its segment's end normals slerped (pbrt-v4's), unit.
inline Vec3f ribbon_normal(const CurveSet& c, uint32_t segment, float u) {
    return slerp_unit(c.normals[c.segments[segment]], c.normals[c.segments[segment] + 3], u);
}

// The fraction of its width a ribbon shows to a ray along unit `d` at u: pbrt-v4 intersects a
// ribbon as a ray-facing one of width w |cos| of the angle between its normal and the ray.
inline float ribbon_width_scale(const CurveSet& c, uint32_t segment, float u, const Vec3f& d) {
    return std::abs(dot(ribbon_normal(c, segment, u), d));
}

inline CurveHit curve_hit(const CurveSet& c, uint32_t segment, float u, const Vec3f& p, const Vec3f& ray_dir) {
    const CurvePoint* cp = &c.points[c.segments[segment]];
    u = std::clamp(u, 0.0f, 1.0f);
    Vec3f dpdu = bezier_derivative(cp, u);
    if (!(length(dpdu) > 0)) dpdu = cp[3].p - cp[0].p;  // a cusp: the chord's direction
    const Vec3f t = normalize(dpdu);
    const Vec3f d = normalize(ray_dir);
    float width = 2 * bezier_radius(cp, u);
    // v from the distance to the curve's centre across the ray-facing ribbon, over the width it
    // shows the ray, signed along dpdu turned +90 degrees about the ray (pbrt-v4's edge function).
    Vec3f across = cross(d, t);
    const float across_length = length(across);
    across = across_length > 0 ? across / across_length : Vec3f(0, 0, 0);
    Vec3f ribbon_n;
    if (c.type == CurveType::kRibbon) {
        ribbon_n = ribbon_normal(c, segment, u);
        width *= std::abs(dot(ribbon_n, d));
    }
    CurveHit h;
    h.p = p;
    const Vec3f centre = bezier_point(cp, u);
    const float v = width > 0 ? std::clamp(0.5f + dot(p - centre, across) / width, 0.0f, 1.0f) : 0.5f;
    h.uv = Vec2f(u, v);
    if (c.type == CurveType::kRibbon) {
        const Vec3f b = cross(ribbon_n, t);
        across = length(b) > 0 ? normalize(b) : across;
    } else if (c.type == CurveType::kCylinder) {
        across = rotate_perpendicular(across, t, -kPi * (v - 0.5f));
    }
    Vec3f n = cross(t, across);
    const float n_length = length(n);
    // A ray along the curve's tangent has no facing direction: any normal across the tangent.
    if (!(n_length > 0)) {
        Vec3f s, b;
        fallback_tangents(t, s, b);
        n = s;
    } else {
        n = n / n_length;
    }
    h.n = c.reverse_orientation ? -n : n;
    h.p_error = Vec3f(std::max(width, 1e-7f * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f})));
    return h;
}

// The shading geometry at a curve hit: pbrt-v4's dpdu, and dpdv across the curve, `width` long,
// with cross(dpdu, dpdv) along the hit's normal `n`; curves have no normal derivatives.
inline ShadingGeometry curve_shading_geometry(const Vec3f& dpdu, const Vec3f& n, float width, const Vec2f& uv) {
    ShadingGeometry g;
    g.uv = uv;
    g.dpdu = dpdu;
    Vec3f across = cross(n, dpdu);
    const float len = length(across);
    if (len > 0 && length(dpdu) > 0) {
        g.dpdv = across * (std::max(width, 1e-30f) / len);
    } else {
        fallback_tangents(n, g.dpdu, g.dpdv);
    }
    g.dndu = g.dndv = Vec3f(0, 0, 0);
    return g;
}

}  // namespace candela
