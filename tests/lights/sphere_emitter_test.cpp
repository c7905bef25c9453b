// Sphere emitters: sampled points lie on the sphere and are visible from the reference point, the
// cone density is 1 / (2 pi (1 - cos theta_max)) also for very narrow cones, the density from
// inside is the converted area density, and smallpt-sized spheres keep their precision.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/sphere_intersection.h"
#include "candela/lights/sphere_emitter.h"
#include "candela/sampling/rng.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Checks samples from ref: on the sphere to 1e-6 relative (or to the float rounding of p, for a
// small sphere far from the origin), normal = the (possibly reversed) outward normal there,
// visible from ref when ref is outside, and pdf == pdf() of the point.
void expect_samples_on_sphere(const Sphere& sphere, const Vec3f& ref) {
    SphereEmitter e{sphere};
    // A float coordinate c is within 2^-24 |c| of its exact value.
    double far = std::max(std::abs(sphere.center.x), std::max(std::abs(sphere.center.y), std::abs(sphere.center.z)));
    double tolerance = 1e-6 + 2.0 * std::sqrt(3.0) * 0x1p-24 * (far + sphere.radius) / sphere.radius;
    Vec3d to_ref = Vec3d(ref) - sphere.center;
    bool outside = dot(to_ref, to_ref) > sphere.radius * sphere.radius;
    Rng rng(3, 4);
    for (int i = 0; i < 2000; ++i) {
        Vec2f u = rng.next_vec2f();
        std::optional<EmitterSample> s = e.sample(ref, u);
        ASSERT_TRUE(s) << "u = " << u.x << ", " << u.y;
        Vec3d offset = Vec3d(s->p) - sphere.center;
        EXPECT_NEAR(length(offset) / sphere.radius, 1.0, tolerance);
        Vec3d n_out = normalize(offset);
        Vec3d n_front = sphere.reverse_orientation ? -n_out : n_out;
        EXPECT_GT(dot(Vec3d(s->n), n_front), 1.0 - 1e-6);
        EXPECT_NEAR(length(s->n), 1.0f, 1e-6f);
        // From outside only the near cap is drawn (up to the float rounding of p).
        if (outside) {
            EXPECT_GE(dot(n_out, Vec3d(ref) - Vec3d(s->p)), -1e-6 * sphere.radius);
        }
        EXPECT_EQ(s->pdf, e.pdf(ref, s->p, s->n));
    }
}

TEST(SphereEmitter, SamplesFromOutsideLieOnTheVisibleCap) {
    expect_samples_on_sphere({Vec3d(0.5, -1.0, 3.0), 1.25, false}, {0.0f, 0.0f, 0.0f});
    expect_samples_on_sphere({Vec3d(0.0, 0.0, 1.001), 1.0, false}, {0.0f, 0.0f, 0.0f});  // grazing
    expect_samples_on_sphere({Vec3d(0.0, 0.0, 1000.0), 1.0, true}, {0.0f, 0.0f, 0.0f});  // far
}

TEST(SphereEmitter, SamplesFromInsideLieOnTheSphere) {
    expect_samples_on_sphere({Vec3d(0.3, -0.2, 0.5), 2.0, true}, {0.0f, 0.0f, 0.0f});
    expect_samples_on_sphere({Vec3d(0.3, -0.2, 0.5), 2.0, false}, {0.1f, 0.0f, 0.0f});
}

TEST(SphereEmitter, SmallptSizedSpheresKeepPrecision) {
    // smallpt's left wall (radius 1e5, surface at x = 1; the box lies inside the sphere) from the
    // box, from just in front of the wall, and from just outside it; and its light from the floor.
    const Sphere wall{Vec3d(1e5 + 1.0, 40.8, 81.6), 1e5, false};
    expect_samples_on_sphere(wall, {50.0f, 40.0f, 80.0f});
    expect_samples_on_sphere(wall, {1.5f, 40.0f, 80.0f});
    expect_samples_on_sphere(wall, {0.5f, 40.0f, 80.0f});
    expect_samples_on_sphere({Vec3d(1e5 + 1.0, 40.8, 81.6), 1e5, true}, {50.0f, 40.0f, 80.0f});
    expect_samples_on_sphere({Vec3d(50.0, 681.33, 81.6), 600.0, false}, {50.0f, 40.0f, 81.6f});
}

TEST(SphereEmitter, PointsOnTheSphereSampleByArea) {
    // Float points on the sphere lie on either side of it; within rounding they sample by area
    // (the cone from just outside would show only the outside). Clearly outside, the cone.
    const Sphere spheres[] = {{Vec3d(0.0, 0.0, 0.0), 1.0, true},
                              {Vec3d(50.0, 681.33, 81.6), 600.0, false},
                              {Vec3d(1000.0, -20.0, 3.0), 1.0, true},
                              {Vec3d(1e5 + 1.0, 40.8, 81.6), 1e5, false}};
    for (const Sphere& sphere : spheres) {
        SphereEmitter e{sphere};
        Rng rng(8, 8);
        int outside = 0;
        for (int i = 0; i < 1000; ++i) {
            Vec3d dir(sample_uniform_sphere(rng.next_vec2f()));
            Vec3f on(project_to_sphere(sphere, sphere.center + dir));
            outside += length_squared(Vec3d(on) - sphere.center) > sphere.radius * sphere.radius;
            EXPECT_EQ(e.cone_one_minus_cos_max(on), 0.0) << "radius " << sphere.radius;
            Vec3f beyond(sphere.center + normalize(dir) * (sphere.radius * 1.01));
            EXPECT_GT(e.cone_one_minus_cos_max(beyond), 0.0) << "radius " << sphere.radius;
        }
        EXPECT_GT(outside, 0) << "the test should round some points outside";
    }
}

TEST(SphereEmitter, ConePdfIsOneOverTheConeSolidAngle) {
    for (double d : {1.01, 1.5, 3.0, 10.0}) {
        SphereEmitter e{{Vec3d(0.0, 0.0, d), 1.0, false}};
        double cos_max = std::sqrt(1.0 - 1.0 / (d * d));
        float expected = static_cast<float>(1.0 / (2.0 * kPiD * (1.0 - cos_max)));
        // Any point of the sphere: the density over directions is constant on the cone.
        EXPECT_FLOAT_EQ(e.pdf({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, static_cast<float>(d) - 1.0f}, {0.0f, 0.0f, -1.0f}),
                        expected)
            << "d = " << d;
        std::optional<EmitterSample> s = e.sample({0.0f, 0.0f, 0.0f}, {0.3f, 0.7f});
        ASSERT_TRUE(s);
        EXPECT_FLOAT_EQ(s->pdf, expected);
    }
}

TEST(SphereEmitter, NarrowConePdfAvoidsCancellation) {
    // At d = 1e4 r, 1 - cos theta_max = 5e-9 is below float resolution near 1; the density must
    // still be 1 / (pi (r/d)^2 (1 + (r/d)^2 / 4 + ...)) and not infinite.
    SphereEmitter e{{Vec3d(0.0, 0.0, 1e4), 1.0, false}};
    double s2 = 1e-8;  // (r/d)^2
    double one_minus_cos = s2 / 2.0 + s2 * s2 / 8.0;
    float pdf = e.pdf({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 9999.0f}, {0.0f, 0.0f, -1.0f});
    EXPECT_FLOAT_EQ(pdf, static_cast<float>(1.0 / (2.0 * kPiD * one_minus_cos)));
    for (float ux : {0.0f, 0.5f, 0.9f, kOneMinusEpsilon}) {
        std::optional<EmitterSample> s = e.sample({0.0f, 0.0f, 0.0f}, {ux, 0.1f});
        ASSERT_TRUE(s);
        // On the near cap (z <= 1e4, up to float rounding), and sin theta = |p.xy| / |p| follows
        // u: sin^2 theta = u sin^2 theta_max to first order.
        EXPECT_LE(s->p.z, 1e4f);
        EXPECT_GE(s->p.z, 9999.0f);
        Vec3d p(s->p);
        double sin2 = (p.x * p.x + p.y * p.y) / length_squared(p);
        EXPECT_NEAR(sin2 / s2, static_cast<double>(ux), 1e-4);
    }
}

TEST(SphereEmitter, PdfFromInsideIsTheConvertedAreaDensity) {
    const Sphere sphere{Vec3d(0.0, 0.0, 0.0), 2.0, true};
    SphereEmitter e{sphere};
    const Vec3f ref(0.5f, 0.0f, 0.0f);
    const Vec3f p(0.0f, 2.0f, 0.0f), n(0.0f, -1.0f, 0.0f);
    // dist^2 = 4.25, cos theta_light = 2 / sqrt(4.25), area 16 pi.
    double expected = 4.25 / (2.0 / std::sqrt(4.25)) / (16.0 * kPiD);
    EXPECT_FLOAT_EQ(e.pdf(ref, p, n), static_cast<float>(expected));
}

TEST(SphereEmitter, AreaIsFourPiRSquared) {
    SphereEmitter e{{Vec3d(1.0, 2.0, 3.0), 1.5, false}};
    EXPECT_FLOAT_EQ(e.area(), static_cast<float>(9.0 * kPiD));
}

}  // namespace
}  // namespace candela
