// Scenes built to break the numbers (issue 6, "Numbers"): glass that does not refract, a closed
// box that reflects everything, a light of radiance 1e30, the Cornell box a millionth and a
// million times its size, and coincident quads. Each must render without a NaN or infinite pixel,
// with every dropped sample counted in RenderStats, in bounded work, and with the value the
// physics says: scale invariance, linearity in emission, the closed form of a truncated furnace.
// Comparisons between renders are per-block z-tests with the variances measured from the samples
// (support/render_moments.h), each with a control proving it could fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "candela/render/renderer.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 16;
constexpr int kBlock = 4;
constexpr long kBlockTests = 3L * (kSize / kBlock) * (kSize / kBlock);  // block-channels per image

// Renders `scene` as the CLI does and checks what must hold for any scene: every sample taken and
// accounted for, every pixel finite.
RenderResult render_checked(const Scene& scene) {
    RenderResult r = render(scene, {.threads = 2});
    const uint64_t samples = uint64_t(scene.camera.width) * uint64_t(scene.camera.height) * uint64_t(scene.sampler.spp);
    EXPECT_EQ(r.stats.samples, samples);
    EXPECT_LE(r.stats.dropped_samples, samples);
    for (int y = 0; y < r.image.height; ++y)
        for (int x = 0; x < r.image.width; ++x)
            EXPECT_TRUE(r.image.at(x, y).is_finite()) << "pixel " << x << ", " << y;
    return r;
}

// The scene under test: rendered as the CLI does (render_checked) with no sample dropped, then its
// per-pixel moments for the z-tests, again with none dropped.
test::RenderMoments checked_moments(const Scene& scene) {
    EXPECT_EQ(render_checked(scene).stats.dropped_samples, 0u);
    test::RenderMoments m = test::render_moments(scene);
    EXPECT_EQ(m.dropped, 0u);
    return m;
}

// `scene` with every length multiplied by `scale`: geometry and camera.
Scene scaled(Scene scene, float scale) {
    for (TriangleMesh& mesh : scene.meshes)
        for (Vec3f& p : mesh.positions) p = p * scale;
    for (Sphere& sphere : scene.spheres) {
        sphere.center = sphere.center * double(scale);
        sphere.radius *= double(scale);
    }
    scene.camera.position = scene.camera.position * scale;
    scene.camera.look_at = scene.camera.look_at * scale;
    scene.camera.near *= scale;
    return scene;
}

// z-tests of every block-channel of `a` against `b` scaled by `scale_b`.
test::ZTestFamily compare(const test::RenderMoments& a, const test::RenderMoments& b, double scale_b = 1.0) {
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, kBlockTests));
    test::compare_renders(a, b, kBlock, family, scale_b);
    return family;
}

// Index 1 makes a dielectric invisible: Fresnel reflectance 0, rays pass straight through. Its
// image must be that of the box without the sphere (an independent render: another seed). The
// control: the same sphere at index 1.5 is visibly different.
TEST(AdversarialScenes, GlassOfIndexOneIsInvisible) {
    Scene empty = test::cornell_walls_scene(kSize, kSize, 64);
    empty.sampler.seed = 8;
    Scene glass = test::cornell_walls_scene(kSize, kSize, 64);
    glass.materials.push_back(make_dielectric(1.0f));
    glass.material_names.push_back("ior1");
    test::add_sphere(glass, {0.1, -0.3, 0.0}, 0.6, uint32_t(glass.materials.size() - 1));
    const test::RenderMoments m_glass = checked_moments(glass);
    const test::RenderMoments m_empty = test::render_moments(empty);
    const test::ZTestFamily family = compare(m_glass, m_empty);
    EXPECT_TRUE(family.passed()) << family.summary();

    Scene refracting = glass;
    refracting.materials.back() = make_dielectric(1.5f);
    const test::ZTestFamily control = compare(test::render_moments(refracting), m_empty);
    EXPECT_FALSE(control.passed()) << control.summary();
}

// A closed sphere of albedo exactly 1 that emits 1 everywhere (the white furnace at a = 1): the
// radiance L = Le + a L has no finite solution, and throughput roulette never fires (the
// throughput stays 1), so max_depth alone ends the paths. Truncated after D bounces every pixel is
// sum_{k=0..D} a^k Le = D + 1 in expectation (each vertex adds Le once, split by MIS between the
// light sample and the BSDF sample that finds it), and every path takes D bounces.
//
// Up to float rounding: the throughput after k bounces is a product of k factors f |cos| / pdf,
// each 1 within a few roundings, so it drifts by up to about 3 k ulps (u = 2^-24), and the sum over
// k of k drifts by up to 3 u D^2 / 2 = 9 for D = 10^4. (Measured: 0.25, systematic; the noise is
// 0.05.) The mean must lie within that rounding bound plus the z-test's noise bound.
TEST(AdversarialScenes, AlbedoOneClosedSphereEndsAtMaxDepth) {
    constexpr int kDepth = 10000, kPixels = 2, kSpp = 8;
    Scene s;
    s.materials = {make_diffuse(Rgb(1.0f))};
    s.material_names = {"white"};
    test::add_sphere(s, {0, 0, 0}, 1.0, 0, /*reverse_orientation=*/true);
    test::set_emission(s, 0, Rgb(1.0f));
    test::set_camera(s, Vec3f{0.2f, 0.1f, 0.0f}, Vec3f{1.0f, 0.3f, -0.4f}, 60, kPixels, kPixels);
    s.sampler.spp = kSpp;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 3;
    s.integrator.max_depth = kDepth;

    const RenderResult r = render_checked(s);
    EXPECT_EQ(r.stats.dropped_samples, 0u);
    const double samples = double(r.stats.samples);
    // Every path runs to max_depth (roulette could end one only if rounding left the throughput a
    // hair under 1), and none beyond it.
    EXPECT_LE(double(r.stats.rays.bounce), samples * kDepth);
    EXPECT_GT(double(r.stats.rays.bounce), 0.99 * samples * kDepth);

    const test::RenderMoments m = test::render_moments(s);
    const double rounding = 3.0 * 0x1p-24 * double(kDepth) * double(kDepth) / 2.0;
    const double z = test::sidak_critical_z(test::kRenderTestAlpha, 3);
    for (int c = 0; c < 3; ++c) {
        const test::BlockEstimate whole = test::block_estimate(m, 0, 0, kPixels, c);
        EXPECT_NEAR(whole.mean, kDepth + 1, rounding + z * std::sqrt(whole.variance)) << "channel " << c;
        // Power: paths ended early (by roulette, after some 7 bounces: an answer near 8) or energy
        // lost at each bounce would be far outside.
        EXPECT_LT(rounding + z * std::sqrt(whole.variance), 0.01 * (kDepth + 1));
    }
}

// The same closed sphere with a fixed roulette survival probability of 0.8 (GAMES101): roulette,
// not max_depth, now ends the paths: 3 bounces, then as many as the survivals of a probability
// 0.8 (0.8 / 0.2 = 4 on average), so 7 bounce rays per sample on average. (The
// estimator is unbiased but of unbounded variance here, with survivors' weights growing as
// 1.25^k, so only finiteness and the path lengths are asserted.)
TEST(AdversarialScenes, AlbedoOneClosedSphereEndsByFixedRoulette) {
    Scene s;
    s.materials = {make_diffuse(Rgb(1.0f))};
    s.material_names = {"white"};
    test::add_sphere(s, {0, 0, 0}, 1.0, 0, /*reverse_orientation=*/true);
    test::set_emission(s, 0, Rgb(1.0f));
    test::set_camera(s, Vec3f{0.2f, 0.1f, 0.0f}, Vec3f{1.0f, 0.3f, -0.4f}, 60, kSize, kSize);
    s.sampler.spp = 16;
    s.integrator.max_depth = 10000;
    s.integrator.rr_probability = 0.8f;

    const RenderResult r = render_checked(s);
    EXPECT_EQ(r.stats.dropped_samples, 0u);
    const double mean_bounces = double(r.stats.rays.bounce) / double(r.stats.samples);
    // 4096 paths: the survivals have a standard deviation of sqrt(0.8) / 0.2 = 4.5 per path, so
    // their mean one of 0.07.
    EXPECT_NEAR(mean_bounces, 3.0 + 0.8 / 0.2, 0.5);
}

// Radiance is linear in emission and the samples' random decisions do not depend on its scale
// (light selection and roulette see only ratios and throughputs), so a light of 1e30 gives the
// image of a light of 1 times 1e30, to float rounding, and nothing overflows: 1e30 is far from
// the float limit of 3.4e38 even after the estimator's divisions by pdfs.
TEST(AdversarialScenes, LightOfRadiance1e30ScalesTheImage) {
    Scene unit = test::cornell_box_scene(kSize, kSize, 16);
    const Rgb emission(4.0f, 3.2f, 2.4f);
    ASSERT_EQ(unit.shapes[5].emission, emission);  // the ceiling light of cornell_walls_scene
    Scene bright = unit;
    bright.shapes[5].emission = emission * 1e30f;

    const RenderResult a = render_checked(unit);
    const RenderResult b = render_checked(bright);
    EXPECT_EQ(a.stats.dropped_samples, 0u);
    EXPECT_EQ(b.stats.dropped_samples, 0u);
    int lit = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double expected = 1e30 * double(a.image.at(x, y)[c]);
                EXPECT_NEAR(double(b.image.at(x, y)[c]), expected, 1e-4 * expected) << x << ", " << y << " c" << c;
                lit += expected > 0.0 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(lit, kSize * kSize * 3 / 2);  // the comparison is not between black images
}

// Radiance does not depend on the unit of length. The Cornell box a millionth and a million times
// its size (lights, walls, boxes or spheres, and camera) must render the unit box's image, compared
// block by block with an independent render; ray offsets, light pdfs (areas of 1e-12 and 1e12)
// and the accelerator must all scale. The control: the same test against the unit image made 10%
// brighter rejects (scale bugs are grosser: light leaking through walls, self-shadowed surfaces).
struct ScaleCase {
    std::string name;
    Scene (*scene)(int width, int height, int spp);
    float scale;
    int spp;  // the glass scene is noisier and needs more for the control to have its power
};

class ScaledCornellBox : public ::testing::TestWithParam<ScaleCase> {};

TEST_P(ScaledCornellBox, RendersTheUnitBoxImage) {
    const Scene unit = GetParam().scene(kSize, kSize, GetParam().spp);
    Scene big_or_small = scaled(unit, GetParam().scale);
    big_or_small.sampler.seed = unit.sampler.seed + 1;
    const test::RenderMoments m_scaled = checked_moments(big_or_small);
    const test::RenderMoments m_unit = test::render_moments(unit);
    const test::ZTestFamily family = compare(m_scaled, m_unit);
    EXPECT_TRUE(family.passed()) << family.summary();
    const test::ZTestFamily control = compare(m_scaled, m_unit, 1.1);
    EXPECT_FALSE(control.passed()) << control.summary();
    if (!family.passed()) test::write_diagnostic(m_scaled, "adversarial_scaled_" + GetParam().name);
}

void PrintTo(const ScaleCase& c, std::ostream* os) { *os << c.name; }

// The boxes (triangles) and the glass scene (mirror and glass spheres, intersected in double).
INSTANTIATE_TEST_SUITE_P(Scales, ScaledCornellBox,
                         ::testing::Values(ScaleCase{"box_micro", test::cornell_box_scene, 1e-6f, 64},
                                           ScaleCase{"box_mega", test::cornell_box_scene, 1e6f, 64},
                                           ScaleCase{"glass_micro", test::cornell_glass_scene, 1e-6f, 256},
                                           ScaleCase{"glass_mega", test::cornell_glass_scene, 1e6f, 256}),
                         [](const auto& param_info) { return param_info.param.name; });

// z-tests that every block-channel of `m`, scaled by `scale`, lies between those of `a` and `b`:
// its distance from the interval of their means, against the variance of its mean and of the
// nearer end's.
test::ZTestFamily between(const test::RenderMoments& m, const test::RenderMoments& a, const test::RenderMoments& b,
                          double scale = 1.0) {
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, kBlockTests));
    for (int y = 0; y < kSize; y += kBlock) {
        for (int x = 0; x < kSize; x += kBlock) {
            for (int c = 0; c < 3; ++c) {
                const test::BlockEstimate e = test::block_estimate(m, x, y, kBlock, c, scale);
                test::BlockEstimate lo = test::block_estimate(a, x, y, kBlock, c);
                test::BlockEstimate hi = test::block_estimate(b, x, y, kBlock, c);
                if (lo.mean > hi.mean) std::swap(lo, hi);
                const test::BlockEstimate& end = e.mean < lo.mean ? lo : hi;
                const double outside = std::max({lo.mean - e.mean, e.mean - hi.mean, 0.0});
                family.add(outside, e.variance + end.variance, x, y, c);
            }
        }
    }
    return family;
}

// Two coincident back walls, white and green (z-fighting): which one a ray hits is arbitrary, but
// each hit is a proper hit of one of them, so every block lies between the renders with only the
// white wall and only the green one (within their noise). A ray leaving one wall must not stop on
// the other at distance 0, which would darken the image below both. The control: the image made
// 20% darker falls outside.
TEST(AdversarialScenes, CoincidentQuadsRenderBetweenTheirMaterials) {
    Scene white = test::cornell_walls_scene(kSize, kSize, 64);
    constexpr uint32_t kBackWall = 2;
    ASSERT_EQ(white.shapes[kBackWall].material, test::kCornellWhite);
    Scene green = white;
    green.shapes[kBackWall].material = test::kCornellGreen;
    Scene both = white;
    both.meshes.push_back(both.meshes[both.shapes[kBackWall].index]);
    both.shapes.push_back({ShapeKind::kMesh, uint32_t(both.meshes.size() - 1), test::kCornellGreen, {}, false});
    white.sampler.seed = 21;
    green.sampler.seed = 22;
    const test::RenderMoments m_both = checked_moments(both);
    const test::RenderMoments m_white = test::render_moments(white);
    const test::RenderMoments m_green = test::render_moments(green);
    const test::ZTestFamily family = between(m_both, m_white, m_green);
    EXPECT_TRUE(family.passed()) << family.summary();
    const test::ZTestFamily control = between(m_both, m_white, m_green, 0.8);
    EXPECT_FALSE(control.passed()) << control.summary();
}

}  // namespace
}  // namespace candela
