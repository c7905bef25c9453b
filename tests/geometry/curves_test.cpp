// Curves (geometry/curves.h, curve_hit.h): pbrt-v4's bases and degrees as cubic Bezier segments,
// its width from width0 to width1, its checks; and Embree's hits turned into pbrt's (u, v), normal
// and error bound, for flat, cylinder and ribbon curves, alone and instanced.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/curve_hit.h"
#include "candela/geometry/curves.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A quadratic Bezier at t.
Vec3f quadratic(const Vec3f& a, const Vec3f& b, const Vec3f& c, float t) {
    return a * ((1 - t) * (1 - t)) + b * (2 * t * (1 - t)) + c * (t * t);
}

// A uniform cubic B-spline segment at t (its basis functions).
Vec3f cubic_bspline(const Vec3f* c, float t) {
    const float s = 1 - t;
    return (c[0] * (s * s * s) + c[1] * (3 * t * t * t - 6 * t * t + 4) + c[2] * (-3 * t * t * t + 3 * t * t + 3 * t + 1) +
            c[3] * (t * t * t)) /
           6.0f;
}

void expect_near(const Vec3f& a, const Vec3f& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Curves, BezierChainsShareTheirEndPointsAndWidthRunsLinearly) {
    CurveSet set;
    const std::vector<Vec3f> cp = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}, {4, -1, 0}, {5, -1, 0}, {6, 0, 0}};
    ASSERT_EQ(add_curve(set, cp, CurveBasis::kBezier, 3, 0.2f, 0.8f), "");
    ASSERT_EQ(set.segment_count(), 2u);
    EXPECT_EQ(set.points.size(), 7u);  // 3 n + 1
    EXPECT_EQ(set.segments[0], 0u);
    EXPECT_EQ(set.segments[1], 3u);
    // The radius is half the width, linear over the whole curve (segment 2 runs from 0.5 to 1).
    for (float u : {0.0f, 0.3f, 1.0f}) {
        EXPECT_NEAR(bezier_radius(&set.points[0], u), 0.5f * (0.2f + 0.6f * 0.5f * u), 1e-6f);
        EXPECT_NEAR(bezier_radius(&set.points[3], u), 0.5f * (0.2f + 0.6f * (0.5f + 0.5f * u)), 1e-6f);
    }
    expect_near(bezier_point(&set.points[3], 1.0f), cp[6], 1e-6f);
}

TEST(Curves, QuadraticsAndBSplinesBecomeTheSameCurveInBezierForm) {
    const std::vector<Vec3f> q = {{0, 0, 0}, {1, 2, 0}, {2, 0, 1}};
    CurveSet quad;
    ASSERT_EQ(add_curve(quad, q, CurveBasis::kBezier, 2, 1, 1), "");
    for (float t : {0.0f, 0.25f, 0.5f, 0.9f}) expect_near(bezier_point(quad.points.data(), t), quadratic(q[0], q[1], q[2], t), 1e-5f);

    const std::vector<Vec3f> b = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 1, 0}, {4, 0, 2}};
    CurveSet spline;
    ASSERT_EQ(add_curve(spline, b, CurveBasis::kBSpline, 3, 1, 1), "");
    ASSERT_EQ(spline.segment_count(), 2u);
    for (size_t s = 0; s < 2; ++s)
        for (float t : {0.0f, 0.4f, 1.0f})
            expect_near(bezier_point(&spline.points[spline.segments[s]], t), cubic_bspline(&b[s], t), 1e-5f);

    // A quadratic B-spline: the segments run between the midpoints of the control polygon.
    CurveSet q_spline;
    ASSERT_EQ(add_curve(q_spline, b, CurveBasis::kBSpline, 2, 1, 1), "");
    ASSERT_EQ(q_spline.segment_count(), 3u);
    for (size_t s = 0; s < 3; ++s)
        expect_near(bezier_point(&q_spline.points[q_spline.segments[s]], 0.5f),
                    quadratic((b[s] + b[s + 1]) * 0.5f, b[s + 1], (b[s + 1] + b[s + 2]) * 0.5f, 0.5f), 1e-5f);
}

TEST(Curves, BadCurvesAreRefusedWithWhatIsWrong) {
    CurveSet set;
    const std::vector<Vec3f> five = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    EXPECT_NE(add_curve(set, five, CurveBasis::kBezier, 3, 1, 1).find("5 control points do not make"), std::string::npos);
    EXPECT_NE(add_curve(set, std::span(five).first(2), CurveBasis::kBSpline, 2, 1, 1).find("too few"),
              std::string::npos);
    EXPECT_NE(add_curve(set, std::span(five).first(4), CurveBasis::kBezier, 4, 1, 1).find("degree 4"),
              std::string::npos);
    std::vector<Vec3f> nan = {{0, 0, 0}, {1, 0, 0}, {2, NAN, 0}, {3, 0, 0}};
    EXPECT_NE(add_curve(set, nan, CurveBasis::kBezier, 3, 1, 1).find("control point 2 is not finite"),
              std::string::npos);
    EXPECT_NE(add_curve(set, std::span(five).first(4), CurveBasis::kBezier, 3, -1, 1).find("width"),
              std::string::npos);
    EXPECT_NE(add_curve(set, std::span(five).first(4), CurveBasis::kBezier, 3, 0, 0).find("width"),
              std::string::npos);
    CurveSet ribbon;
    ribbon.type = CurveType::kRibbon;
    const std::vector<Vec3f> one_normal = {{0, 0, 1}};
    EXPECT_NE(add_curve(ribbon, std::span(five).first(4), CurveBasis::kBezier, 3, 1, 1, one_normal).find("needs 2 normals"),
              std::string::npos);
    EXPECT_TRUE(set.points.empty() && ribbon.points.empty());
}

// A straight curve along x from -2 to 2 in the plane z = 0, width w, of `type`; ribbons face +z.
CurveSet straight_curve(CurveType type, float w) {
    CurveSet set;
    set.type = type;
    const std::vector<Vec3f> cp = {{-2, 0, 0}, {-0.5f, 0, 0}, {0.5f, 0, 0}, {2, 0, 0}};
    const std::vector<Vec3f> n = {{0, 0, 1}, {0, 0, 1}};
    EXPECT_EQ(add_curve(set, cp, CurveBasis::kBezier, 3, w, w, type == CurveType::kRibbon ? std::span(n) : std::span<const Vec3f>{}), "");
    return set;
}

struct OneCurve {
    std::vector<CurveSet> curves;
    std::vector<Shape> shapes;
    std::unique_ptr<Accelerator> accel;
    explicit OneCurve(CurveSet set) {
        curves.push_back(std::move(set));
        Shape s;
        s.kind = ShapeKind::kCurves;
        shapes.push_back(s);
        accel = std::make_unique<Accelerator>(std::span<const TriangleMesh>{}, std::span<const Sphere>{},
                                              std::span<const Disk>{}, shapes, AlphaCutouts{}, Instancing{}, curves);
    }
};

Ray down_at(float x, float y) { return Ray{Vec3f(x, y, 5), Vec3f(0, 0, -1), 0.0f, 100.0f}; }

TEST(CurveHits, AFlatCurveFacesTheRayWithPbrtsUVAndNormal) {
    const OneCurve c(straight_curve(CurveType::kFlat, 0.4f));
    // Across the width, v runs from 0 to 1 along dpdv = dpdu turned +90 degrees about the ray:
    // for dpdu = +x and the ray -z, that is -y. The normal is cross(dpdu, dpdv): along the ray.
    for (float y : {-0.15f, 0.0f, 0.1f}) {
        auto hit = c.accel->intersect(down_at(0.3f, y));
        ASSERT_TRUE(hit) << y;
        EXPECT_NEAR(hit->t, 5.0f, 1e-3f);
        EXPECT_NEAR(hit->b.y, 0.5f - y / 0.4f, 1e-3f) << y;
        expect_near(hit->ng, Vec3f(0, 0, -1), 1e-5f);
        EXPECT_EQ(hit->ns, hit->ng);
        EXPECT_NEAR(hit->p_error.x, 0.4f, 1e-6f);  // pbrt-v4's bound: the width
        EXPECT_EQ(c.accel->uv(*hit), hit->b);
        const ShadingGeometry g = c.accel->shading(*hit);
        EXPECT_GT(g.dpdu.x, 0.0f);
        expect_near(normalize(cross(g.dpdu, g.dpdv)), hit->ng, 1e-5f);
        EXPECT_NEAR(length(g.dpdv), 0.4f, 1e-4f);
    }
    // u along the segment: x = 0 is the middle of the symmetric segment.
    EXPECT_NEAR(c.accel->intersect(down_at(0.0f, 0.0f))->b.x, 0.5f, 1e-3f);
    EXPECT_FALSE(c.accel->intersect(down_at(0.0f, 0.25f)));   // beyond the half width
    EXPECT_FALSE(c.accel->intersect(down_at(2.3f, 0.0f)));    // beyond the end
    EXPECT_TRUE(c.accel->occluded(down_at(1.0f, 0.05f)));
    EXPECT_FALSE(c.accel->occluded(down_at(1.0f, 0.3f)));
}

TEST(CurveHits, ACylinderCurveIsShadedLikeATube) {
    const OneCurve c(straight_curve(CurveType::kCylinder, 0.4f));
    // At the centre the normal is the flat one; towards the edges it turns out to the side of the
    // edge (v = 1 is at -y here), by 180 (v - 1/2) degrees.
    for (float y : {0.0f, -0.1f, 0.1f, -0.19f}) {
        auto hit = c.accel->intersect(down_at(0.5f, y));
        ASSERT_TRUE(hit);
        const float v = hit->b.y;
        const float angle = float(M_PI) * (v - 0.5f);
        expect_near(hit->ng, Vec3f(0, -std::sin(angle), -std::cos(angle)), 1e-4f);
    }
}

TEST(CurveHits, ARibbonFollowsItsNormalsAndIsThinSeenEdgeOn) {
    const OneCurve c(straight_curve(CurveType::kRibbon, 0.4f));
    auto hit = c.accel->intersect(down_at(0.2f, 0.1f));
    ASSERT_TRUE(hit);
    expect_near(hit->ng, Vec3f(0, 0, 1), 1e-4f);  // the given normal: cross(dpdu, dpdv) with dpdv = n x dpdu
    // Seen along its plane, a ribbon is no wider than nothing: a ray along y at z = 0.05 misses it.
    EXPECT_FALSE(c.accel->intersect(Ray{Vec3f(0, -5, 0.05f), Vec3f(0, 1, 0), 0.0f, 100.0f}));
    CurveSet reversed = straight_curve(CurveType::kRibbon, 0.4f);
    reversed.reverse_orientation = true;
    const OneCurve r(std::move(reversed));
    expect_near(r.accel->intersect(down_at(0.2f, 0.1f))->ng, Vec3f(0, 0, -1), 1e-4f);
}

TEST(CurveHits, AnInstancedCurveHitsAsTheSameCurvePlacedInTheWorld) {
    std::vector<CurveSet> curves = {straight_curve(CurveType::kFlat, 0.4f)};
    std::vector<Shape> shapes(1);
    shapes[0].kind = ShapeKind::kCurves;
    Transform to_world = Transform::translate(Vec3d(0, 0, 1)) * Transform::scale(Vec3d(2, 2, 2));
    std::vector<ObjectShapes> objects = {{0, 1}};
    std::vector<Instance> instances = {make_instance(0, to_world)};
    const Accelerator accel(std::span<const TriangleMesh>{}, std::span<const Sphere>{}, std::span<const Disk>{}, shapes,
                            AlphaCutouts{}, Instancing{objects, instances}, curves);
    auto hit = accel.intersect(down_at(1.0f, 0.3f));  // the width doubles to 0.8
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0f, 1e-3f);
    EXPECT_NEAR(hit->b.y, 0.5f - 0.3f / 0.8f, 1e-3f);
    expect_near(hit->ng, Vec3f(0, 0, -1), 1e-5f);
    const ShadingGeometry g = accel.shading(*hit);
    EXPECT_NEAR(length(g.dpdv), 0.8f, 1e-3f);
    EXPECT_FALSE(accel.intersect(down_at(1.0f, 0.45f)));
}

// Embree's curves ignore hits nearer the ray's origin than twice their radius (its
// self-intersection avoidance); the accelerator moves every ray's origin back in a scene with
// curves, so that a hair right beside the origin still blocks it, as in pbrt-v4.
TEST(CurveHits, ACurveRightBesideTheOriginIsHit) {
    const OneCurve c(straight_curve(CurveType::kCylinder, 0.02f));  // radius 0.01
    for (float d : {0.5f, 0.02f, 0.011f}) {
        auto hit = c.accel->intersect(Ray{Vec3f(0.3f, 0, d), Vec3f(0, 0, -1), 0.0f, 100.0f});
        ASSERT_TRUE(hit) << d;
        EXPECT_NEAR(hit->t, d, 1e-5f);
        EXPECT_TRUE(c.accel->occluded(Ray{Vec3f(0.3f, 0, d), normalize(Vec3f(0.2f, 0, -1)), 0.0f, 100.0f})) << d;
        // A ray that stops short of it is not blocked, nor one that starts past it.
        EXPECT_FALSE(c.accel->occluded(Ray{Vec3f(0.3f, 0, d), Vec3f(0, 0, -1), 0.0f, 0.5f * d})) << d;
        EXPECT_FALSE(c.accel->intersect(Ray{Vec3f(0.3f, 0, -d), Vec3f(0, 0, -1), 0.0f, 100.0f})) << d;
    }
}

}  // namespace
}  // namespace candela
