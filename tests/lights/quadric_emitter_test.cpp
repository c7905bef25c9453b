// QuadricEmitter (lights/quadric_emitter.h): its points lie on the clipped surface with the
// normal hits report, pdf() gives back sample()'s pdf bit for bit, and its area is the world's:
// exact under a similarity transform, and under an uneven scale the integral of the area
// element, against a Monte Carlo estimate from the emitter's own samples (E[1 / pdf_area] = area).
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/quadric_intersection.h"
#include "candela/lights/quadric_emitter.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(QuadricEmitter, SamplesLieOnTheClippedSurfaceAndPdfAgreesBitForBit) {
    const Transform m = Transform::translate({1, 2, 3}) * Transform::rotate(normalize(Vec3d(0, 1, 1)), 0.5) *
                        Transform::scale({1.5, 0.5, 2.0});
    const Quadric quadrics[] = {make_cylinder_quadric(0.7, -0.5, 1.5, 270.0, m, false),
                                make_sphere_quadric(1.1, -0.8, 0.6, 230.0, m, true),
                                make_disk_quadric(0.2, 1.0, 0.35, 300.0, m, false)};
    const Vec3f ref(-3.0f, 0.5f, 8.0f);
    for (const Quadric& q : quadrics) {
        const QuadricEmitter e(q);
        Rng rng(1, 1);
        for (int i = 0; i < 2000; ++i) {
            const std::optional<EmitterSample> s = e.sample(ref, rng.next_vec2f());
            ASSERT_TRUE(s);
            EXPECT_EQ(e.pdf(ref, s->p, s->n), s->pdf);
            // On the surface, within the clipped ranges.
            const Vec3d p = q.to_object.apply_point(Vec3d(s->p));
            const double phi = quadric_phi(p);
            EXPECT_LE(phi, q.phi_max + 1e-6);
            if (q.kind == QuadricKind::kDisk) {
                EXPECT_NEAR(p.z, q.height, 1e-5);
                EXPECT_GE(std::hypot(p.x, p.y), q.inner_radius - 1e-5);
                EXPECT_LE(std::hypot(p.x, p.y), q.radius + 1e-5);
            } else {
                EXPECT_GE(p.z, q.z_min - 1e-5);
                EXPECT_LE(p.z, q.z_max + 1e-5);
            }
            const Vec3f n(quadric_normal(q, p));
            EXPECT_NEAR(dot(n, s->n), 1.0f, 1e-5f);
            if (q.kind == QuadricKind::kSphere) {
                EXPECT_NEAR(length(p), q.radius, 1e-5);
            } else if (q.kind == QuadricKind::kCylinder) {
                EXPECT_NEAR(std::hypot(p.x, p.y), q.radius, 1e-5);
            }
            EXPECT_NEAR(dot(s->wi, normalize(s->p - ref)), 1.0f, 1e-6f);
        }
    }
}

TEST(QuadricEmitter, AreaIsExactUnderASimilarity) {
    const Transform m = Transform::translate({4, -1, 2}) * Transform::rotate(normalize(Vec3d(1, 1, 1)), 1.2) *
                        Transform::scale({2.5, 2.5, 2.5});
    const Quadric c = make_cylinder_quadric(0.7, -0.5, 1.5, 270.0, m, false);
    EXPECT_NEAR(QuadricEmitter(c).area(), c.object_area() * 6.25, 1e-5 * c.object_area() * 6.25);
    const Quadric s = make_sphere_quadric(1.1, -0.8, 0.6, 230.0, m, false);
    EXPECT_NEAR(QuadricEmitter(s).area(), s.object_area() * 6.25, 1e-5 * s.object_area() * 6.25);
    const Quadric d = make_disk_quadric(0.2, 1.0, 0.35, 300.0, m, false);
    EXPECT_NEAR(QuadricEmitter(d).area(), d.object_area() * 6.25, 1e-5 * d.object_area() * 6.25);
}

TEST(QuadricEmitter, AreaUnderAnUnevenScaleIsTheIntegralOfTheAreaElement) {
    // E[1 / pdf_area] over the emitter's samples is the world area; 200k samples give it to a
    // standard error well under 0.2%, and the bound is 5 standard errors plus the quadrature's 0.1%.
    const Transform m = Transform::rotate(normalize(Vec3d(1, -2, 0.5)), 0.8) * Transform::scale({2.0, 0.6, 1.3});
    const Quadric quadrics[] = {make_cylinder_quadric(0.7, -0.5, 1.5, 270.0, m, false),
                                make_sphere_quadric(1.1, -0.8, 0.6, 230.0, m, false),
                                make_disk_quadric(0.2, 1.0, 0.35, 300.0, m, false)};
    for (const Quadric& q : quadrics) {
        const QuadricEmitter e(q);
        Rng rng(4, 2);
        const int n = 200000;
        double sum = 0.0, sum_sq = 0.0;
        for (int i = 0; i < n; ++i) {
            const std::optional<EmitterSample> s = e.sample(Vec3f(0.0f, 0.0f, 9.0f), rng.next_vec2f());
            ASSERT_TRUE(s);
            const double x = 1.0 / double(e.area_pdf(s->n));
            sum += x;
            sum_sq += x * x;
        }
        const double mean = sum / n, se = std::sqrt(std::max(0.0, sum_sq / n - mean * mean) / n);
        EXPECT_NEAR(e.area(), mean, 5 * se + 1e-3 * mean);
    }
}

}  // namespace
}  // namespace candela
