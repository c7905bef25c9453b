// Disk emitters: points on the disk (or ellipse) with the disk's front normal, uniform by area
// (pbrt-v4's Disk::Sample), pdf() equal to the sampled pdf bit for bit, power from the area, and
// what light sampling sees agreeing with what rays hitting the disk see.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "candela/geometry/accelerator.h"
#include "candela/lights/disk_emitter.h"
#include "candela/sampling/rng.h"
#include "lights/light_test_scene.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

const Vec3f kOrigin{0.0f, 0.0f, 0.0f};

Disk ellipse() {
    return transform_disk(make_round_disk({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0),
                          Transform::translate({0.3, -0.2, 2.0}) * Transform::rotate({1.0, 0.0, 0.0}, 0.4) *
                              Transform::scale({1.5, 0.5, 1.0}),
                          false);
}

TEST(DiskEmitter, SamplesLieOnTheDiskWithItsFrontNormal) {
    for (const Disk& disk : {make_round_disk({1.0, 2.0, 3.0}, {0.2, -1.0, 0.1}, 0.8), ellipse()}) {
        DiskEmitter emitter(disk);
        EXPECT_FLOAT_EQ(emitter.area(), static_cast<float>(disk.area()));
        Rng rng(4, 5);
        for (int i = 0; i < 2000; ++i) {
            std::optional<EmitterSample> s = emitter.sample(kOrigin, rng.next_vec2f());
            ASSERT_TRUE(s);
            Vec2<double> q = disk.local(Vec3d(s->p));
            EXPECT_LE(q.x * q.x + q.y * q.y, 1.0 + 1e-6);
            EXPECT_NEAR(dot(Vec3d(s->p) - disk.center, disk.normal), 0.0, 1e-6);
            EXPECT_EQ(s->n, Vec3f(disk.normal));
            EXPECT_EQ(emitter.pdf(kOrigin, s->p, s->n), s->pdf);
            EXPECT_NEAR(dot(s->wi, normalize(s->p)), 1.0f, 1e-6f);
        }
    }
}

TEST(DiskEmitter, PdfIsDistanceSquaredOverAreaAndCosine) {
    // A disk of radius 0.5 at distance 4 along its normal, seen from its axis: the centre's
    // density is d^2 / (A cos) = 16 / (pi / 4).
    DiskEmitter emitter(make_round_disk({0.0, 0.0, 4.0}, {0.0, 0.0, -1.0}, 0.5));
    EXPECT_NEAR(emitter.pdf(kOrigin, {0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, -1.0f}), 16.0f / (kPi * 0.25f), 1e-4f);
}

TEST(DiskEmitter, PowerAndSidesInTheLightSet) {
    LightTestScene scene;
    scene.add_disk(make_round_disk({0.0, 0.0, 2.0}, {0.0, 0.0, -1.0}, 0.5), Rgb(2.0f));  // faces the origin
    scene.add_disk(make_round_disk({0.0, 0.0, -2.0}, {0.0, 0.0, -1.0}, 1.0), Rgb(1.0f), true);
    LightSet lights = scene.light_set();
    // pi area L (sides): pi (pi / 4) 2 against pi pi 1 2.
    EXPECT_NEAR(lights.selection_probability(0), 0.5f / 2.5f, 1e-6f);
    EXPECT_NEAR(lights.selection_probability(1), 2.0f / 2.5f, 1e-6f);
    // The first is one-sided: black seen from behind; the second two-sided.
    EXPECT_TRUE(lights.emitted(0, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}).is_black());
    EXPECT_EQ(lights.emitted(0, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -1.0f}), Color(2.0f));
    EXPECT_EQ(lights.emitted(1, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}), Color(1.0f));
}

TEST(DiskEmitter, SampledPointsNormalsAndRadianceAgreeWithHits) {
    LightTestScene scene;
    scene.add_disk(ellipse(), Rgb(1.0f));
    scene.add_disk(transform_disk(make_round_disk({-2.0, 0.5, 1.0}, {1.0, 0.0, 0.3}, 0.7), Transform(), true),
                   Rgb(3.0f));  // its front faces away from the origin
    LightSet lights = scene.light_set(LightSelection::kUniform);
    Accelerator accel(scene.meshes, scene.spheres, scene.disks, scene.shapes);
    Rng rng(2, 8);
    int seen[2] = {0, 0};
    for (int i = 0; i < 2000; ++i) {
        float uc = rng.next_float();
        std::optional<LightSample> s = lights.sample(kOrigin, uc, rng.next_vec2f());
        ASSERT_TRUE(s);
        std::optional<SurfaceHit> hit = accel.intersect(Ray{kOrigin, s->wi, 0.0f, kInfinity});
        ASSERT_TRUE(hit);
        ++seen[hit->shape_id];
        EXPECT_LT(length(hit->p - s->p), 1e-5f);
        EXPECT_EQ(hit->ng, s->n);
        EXPECT_EQ(lights.emitted(hit->shape_id, hit->ng, -s->wi), s->Le);
        EXPECT_NEAR(lights.pdf(kOrigin, hit->shape_id, hit->p, hit->ng) / s->pdf, 1.0f, 1e-4f);
    }
    EXPECT_GT(seen[0], 800);
    EXPECT_GT(seen[1], 800);
}

}  // namespace
}  // namespace candela::test
