// Chi-square goodness of fit of QuadricEmitter::sample (lights/quadric_emitter.h) against its
// area density: the sampled points, mapped to pbrt-v4's (u, v) of the surface, are histogrammed
// on [0, 1]^2 and compared with the density that area_pdf claims, carried to (u, v) by the
// surface's own area element |dpdu x dpdv| (quadric_shading_geometry, checked against finite
// differences in geometry/quadric_test.cpp). The transforms scale unevenly, so uniform in
// object space is not uniform in the world: the density must include the Jacobian. A control
// sampler, uniform in (u, v) (not by area on a sphere), must fail.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/quadric_intersection.h"
#include "candela/lights/quadric_emitter.h"
#include "support/chi2.h"
#include "support/quadric_points.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 4;  // in this file, for the Sidak correction

// The claimed density per unit (u, v): area density times the world area element.
double uv_pdf(const Quadric& q, const QuadricEmitter& e, Vec2f uv) {
    const Vec3d p = quadric_point_of_uv(q, double(uv.x), double(uv.y));
    const Vec3f n(quadric_normal(q, p));
    const ShadingGeometry g = quadric_shading_geometry(q, p, n);
    return double(e.area_pdf(n)) * length(cross(Vec3d(g.dpdu), Vec3d(g.dpdv)));
}

Chi2Result fit(const Quadric& q, bool control = false) {
    const QuadricEmitter e(q);
    Chi2Options opt;
    opt.res_x = 40;
    opt.res_y = 40;
    opt.test_count = kChi2Tests;
    const Vec3f ref(0.3f, -4.0f, 2.5f);  // any point: the area density does not depend on it
    auto sample = [&](Sampler& rng) -> std::optional<Vec2f> {
        const Vec2f u = rng.next_vec2f();
        if (control) return u;
        const std::optional<EmitterSample> s = e.sample(ref, u);
        if (!s) return std::nullopt;
        const Vec3d p_object = q.to_object.apply_point(Vec3d(s->p));
        return quadric_uv(q, p_object, quadric_phi(p_object));
    };
    return chi2_test(PlanarDomain{}, sample, [&](Vec2f uv) { return uv_pdf(q, e, uv); }, opt);
}

const Transform kUneven = Transform::translate({1, 2, -3}) * Transform::rotate(normalize(Vec3d(1, -2, 0.5)), 0.8) *
                          Transform::scale({2.0, 0.6, 1.3});

TEST(QuadricEmitter, CylinderSampleMatchesPdfChiSquare) {
    const Chi2Result r = fit(make_cylinder_quadric(0.7, -0.5, 1.5, 270.0, kUneven, false));
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(QuadricEmitter, PartialSphereSampleMatchesPdfChiSquare) {
    const Chi2Result r = fit(make_sphere_quadric(1.1, -0.8, 0.6, 230.0, kUneven, false));
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(QuadricEmitter, PartialDiskSampleMatchesPdfChiSquare) {
    const Chi2Result r = fit(make_disk_quadric(0.2, 1.0, 0.35, 300.0, kUneven, true));
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(QuadricEmitter, ChiSquareRejectsSamplesUniformInUvOnASphere) {
    const Chi2Result r = fit(make_sphere_quadric(1.1, -1.1, 1.1, 360.0, Transform(), false), true);
    EXPECT_FALSE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
