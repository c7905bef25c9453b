#include "candela/geometry/curves.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace candela {
namespace {

using Cubic = std::array<Vec3f, 4>;

// A quadratic Bezier's cubic form: the same curve (degree elevation, exact).
Cubic elevate_quadratic(const Vec3f& p0, const Vec3f& p1, const Vec3f& p2) {
    return {p0, p0 + (p1 - p0) * (2.0f / 3.0f), p2 + (p1 - p2) * (2.0f / 3.0f), p2};
}

// The Bezier form of a uniform B-spline segment: quadratic (3 points, elevated) or cubic (4).
Cubic bspline_segment(std::span<const Vec3f> c, int degree) {
    if (degree == 2) {
        // The quadratic B-spline segment runs between the midpoints of its control polygon.
        return elevate_quadratic((c[0] + c[1]) * 0.5f, c[1], (c[1] + c[2]) * 0.5f);
    }
    const Vec3f p1 = c[1] * (2.0f / 3.0f) + c[2] * (1.0f / 3.0f);
    const Vec3f p2 = c[1] * (1.0f / 3.0f) + c[2] * (2.0f / 3.0f);
    const Vec3f p0 = (c[0] * (1.0f / 3.0f) + c[1] * (2.0f / 3.0f)) * 0.5f + p1 * 0.5f;
    const Vec3f p3 = p2 * 0.5f + (c[2] * (2.0f / 3.0f) + c[3] * (1.0f / 3.0f)) * 0.5f;
    return {p0, p1, p2, p3};
}

bool finite(const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Vec3f slerp_unit(const Vec3f& a, const Vec3f& b, float t) {
    const float angle = std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
    if (angle < 1e-4f) return normalize(a * (1 - t) + b * t);
    const float s = std::sin(angle);
    return normalize(a * (std::sin((1 - t) * angle) / s) + b * (std::sin(t * angle) / s));
}

size_t curve_segment_count(size_t points, CurveBasis basis, int degree) {
    if (degree != 2 && degree != 3) return 0;
    const size_t d = size_t(degree);
    if (basis == CurveBasis::kBezier) return points >= d + 1 && (points - 1) % d == 0 ? (points - 1) / d : 0;
    return points >= d + 1 ? points - d : 0;
}

std::string curve_error(std::span<const Vec3f> cp, CurveBasis basis, int degree, float width0, float width1,
                        bool ribbon, std::span<const Vec3f> end_normals) {
    if (degree != 2 && degree != 3) return fmt::format("degree {} is not 2 or 3", degree);
    const size_t n = curve_segment_count(cp.size(), basis, degree);
    if (n == 0) {
        return basis == CurveBasis::kBezier
                   ? fmt::format("{} control points do not make a degree {} Bezier curve ({} + n * {} are needed, "
                                 "n >= 0)",
                                 cp.size(), degree, degree + 1, degree)
                   : fmt::format("{} control points are too few for a degree {} B-spline (at least {})", cp.size(),
                                 degree, degree + 1);
    }
    for (size_t i = 0; i < cp.size(); ++i)
        if (!finite(cp[i])) return fmt::format("control point {} is not finite", i);
    if (!(width0 >= 0 && width1 >= 0 && std::isfinite(width0) && std::isfinite(width1)) || (width0 == 0 && width1 == 0))
        return fmt::format("the width must be finite and >= 0, and not 0 at both ends (width0 {}, width1 {})", width0,
                           width1);
    if (ribbon) {
        if (end_normals.size() != n + 1)
            return fmt::format("a ribbon of {} segments needs {} normals, one at each segment's end; {} given", n,
                               n + 1, end_normals.size());
        for (const Vec3f& v : end_normals)
            if (!finite(v) || !(length(v) > 0)) return "a ribbon's normals must be finite and nonzero";
    }
    return "";
}

std::string add_curve(CurveSet& set, std::span<const Vec3f> cp, CurveBasis basis, int degree, float width0,
                      float width1, std::span<const Vec3f> end_normals) {
    const bool ribbon = set.type == CurveType::kRibbon;
    if (std::string error = curve_error(cp, basis, degree, width0, width1, ribbon, end_normals); !error.empty())
        return error;
    const size_t n = curve_segment_count(cp.size(), basis, degree);
    const auto radius = [&](float t) { return 0.5f * (width0 + (width1 - width0) * t); };
    for (size_t s = 0; s < n; ++s) {
        Cubic c;
        if (basis == CurveBasis::kBezier) {
            const size_t o = s * size_t(degree);
            c = degree == 3 ? Cubic{cp[o], cp[o + 1], cp[o + 2], cp[o + 3]}
                            : elevate_quadratic(cp[o], cp[o + 1], cp[o + 2]);
        } else {
            c = bspline_segment(cp.subspan(s, size_t(degree) + 1), degree);
        }
        set.segments.push_back(uint32_t(set.points.size() - (s == 0 ? 0 : 1)));
        for (int k = s == 0 ? 0 : 1; k < 4; ++k) {
            // Radii at u = k/3 of the segment: pbrt's width runs linearly over the segments.
            const float t = (float(s) + float(k) / 3.0f) / float(n);
            set.points.push_back({c[size_t(k)], radius(t)});
            if (ribbon) {
                const Vec3f a = normalize(end_normals[s]), b = normalize(end_normals[s + 1]);
                set.normals.push_back(slerp_unit(a, b, float(k) / 3.0f));
            }
        }
        // A Bezier chain shares its segments' end points by definition, and a B-spline's Bezier
        // segments meet (to rounding), so the next segment starts at this one's last point.
    }
    return "";
}

void transform_curves(CurveSet& set, const Transform& to_world) {
    const float scale = float(std::cbrt(std::fabs(to_world.determinant())));
    for (CurvePoint& c : set.points) {
        c.p = to_world.apply_point(c.p);
        c.r *= scale;
    }
    for (Vec3f& n : set.normals) n = normalize(to_world.apply_normal(n));
}

Vec3f bezier_point(const CurvePoint cp[4], float u) {
    const float t = 1 - u;
    return cp[0].p * (t * t * t) + cp[1].p * (3 * t * t * u) + cp[2].p * (3 * t * u * u) + cp[3].p * (u * u * u);
}

Vec3f bezier_derivative(const CurvePoint cp[4], float u) {
    const float t = 1 - u;
    return (cp[1].p - cp[0].p) * (3 * t * t) + (cp[2].p - cp[1].p) * (6 * t * u) + (cp[3].p - cp[2].p) * (3 * u * u);
}

float bezier_radius(const CurvePoint cp[4], float u) {
    const float t = 1 - u;
    return cp[0].r * (t * t * t) + cp[1].r * (3 * t * t * u) + cp[2].r * (3 * t * u * u) + cp[3].r * (u * u * u);
}

}  // namespace candela
