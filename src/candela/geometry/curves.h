#pragma once
// Curves: hair, fur and grass as pbrt-v4's `curve` shape, traced by Embree's curve primitives.
//
// A CurveSet holds many curves of one kind, each a chain of cubic Bezier segments that share their
// end points (pbrt-v4 turns every basis and degree into cubic Beziers the same way, and so does
// add_curve). Each control point carries its radius, so a width that changes linearly along a
// segment (pbrt's width0 to width1) is exact: a Bezier of evenly spaced linear values is linear.
//
// The three kinds are pbrt-v4's (docs/SCENE_FORMAT.md, "curves"):
//  - flat: a ribbon that always faces the ray (Embree's flat curves), shaded flat;
//  - cylinder: the same ribbon, shaded as if it were a tube: the normal turns from one edge to the
//    other across the width (pbrt-v4 rotates dpdv about dpdu by -90..90 degrees with v);
//  - ribbon: a band oriented by the normals given at the segments' ends (Embree's oriented curves).
// Hits carry pbrt's (u, v): u along the segment in [0, 1], v across it in [0, 1]; v grows along
// dpdv, which for flat and cylinder curves is dpdu turned by +90 degrees about the ray.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

enum class CurveType : uint8_t { kFlat, kCylinder, kRibbon };
enum class CurveBasis : uint8_t { kBezier, kBSpline };

// A control point and the curve's radius there: Embree's RTC_FORMAT_FLOAT4 vertex (x, y, z, r).
struct CurvePoint {
    Vec3f p;
    float r = 0;
};
static_assert(sizeof(CurvePoint) == 16);

struct CurveSet {
    CurveType type = CurveType::kFlat;
    bool reverse_orientation = false;  // flips the normal (pbrt's ReverseOrientation)
    // Control points (x, y, z) and radius (half the width), shared by consecutive segments.
    std::vector<CurvePoint> points;
    // Per segment, the index of its first control point (its 4 are points[first .. first + 3]).
    std::vector<uint32_t> segments;
    // Ribbons only: a normal per control point (only a segment's end points' orient it).
    std::vector<Vec3f> normals;

    size_t segment_count() const { return segments.size(); }
    size_t bytes() const {
        return points.size() * sizeof(CurvePoint) + segments.size() * sizeof(uint32_t) + normals.size() * sizeof(Vec3f);
    }
};

// One curve as pbrt-v4 gives it: control points of `basis` and `degree` (2 or 3), a width from
// width0 at the start to width1 at the end (linear over the segments), and for ribbons the normals
// at the segments' ends (segment count + 1). Returns "" when added, else what is wrong with it
// (too few or too many points for the basis, a non-finite point, a negative width, a ribbon's
// normal count), for the loaders to locate.
std::string add_curve(CurveSet& set, std::span<const Vec3f> control_points, CurveBasis basis, int degree,
                      float width0, float width1, std::span<const Vec3f> end_normals = {});

// What is wrong with such a curve ("" when nothing): add_curve's checks, without adding it, for
// the pbrt importer, which locates the error at the directive. `ribbon`: it needs the normals.
std::string curve_error(std::span<const Vec3f> control_points, CurveBasis basis, int degree, float width0,
                        float width1, bool ribbon, std::span<const Vec3f> end_normals = {});

// The unit vector a fraction t of the way from unit a to unit b along the great circle (slerp),
// as pbrt-v4 interpolates a ribbon's end normals.
Vec3f slerp_unit(const Vec3f& a, const Vec3f& b, float t);

// The number of segments `points` control points make in `basis` and `degree`; 0 when the count
// does not fit (Bezier: degree + 1 + n degree points; B-spline: at least degree + 1).
size_t curve_segment_count(size_t points, CurveBasis basis, int degree);

// The set moved by `to_world`: points as points, radii scaled by the transform's mean scale (the
// cube root of its determinant's magnitude, as a uniform scale scales them), normals as normals.
void transform_curves(CurveSet& set, const Transform& to_world);

// A cubic Bezier segment's point and derivative at u in [0, 1].
Vec3f bezier_point(const CurvePoint cp[4], float u);
Vec3f bezier_derivative(const CurvePoint cp[4], float u);
float bezier_radius(const CurvePoint cp[4], float u);

}  // namespace candela
