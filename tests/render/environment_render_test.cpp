// Environment lighting end to end. The white furnace: a sphere of albedo 1 (diffuse, glass or
// mirror) under a constant environment of radiance 1 renders as 1 everywhere, because no energy is
// lost or created. Agreement: importance-sampled and uniformly sampled environment light and pure
// BSDF sampling converge to the same image of an environment-lit scene.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "candela/render/renderer.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Float rounding of exactly-1 paths (f |cos| / pdf for a mirror) is noise-free but not exact.
constexpr double kRoundingSigma = 1e-5;

Image constant_map(float value) {
    Image map(1, 1);
    map.at(0, 0) = Rgb(value);
    return map;
}

// A sky with a smooth gradient, darker below the horizon, and a bright "sun" of 2x2 texels.
Image sky_map() {
    Image map(32, 16);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            map.at(x, y) = y < 8 ? Rgb(0.4f + 0.05f * float(y), 0.6f, 1.0f) * (0.5f + 0.5f * float(x) / 32.0f)
                                 : Rgb(0.2f, 0.15f, 0.1f);
    for (int y = 3; y < 5; ++y)
        for (int x = 9; x < 11; ++x) map.at(x, y) = Rgb(30.0f, 27.0f, 20.0f);
    return map;
}

Scene sphere_under_sky(Material material, Image map, int size, int spp) {
    Scene s;
    s.materials = {material};
    s.material_names = {"sphere"};
    test::add_sphere(s, {0, 0, 0}, 1.0);
    test::set_camera(s, Vec3f{0, 0.3f, 4}, Vec3f{0, 0, 0}, 40, size, size);
    s.sampler.spp = spp;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 3;
    s.integrator.max_depth = 256;  // glass: internal reflections; truncation is then negligible
    s.environment = EnvironmentSettings{std::move(map), 1.0f, Transform(), EnvironmentSampling::kImportance};
    return s;
}

using FurnaceCase = std::tuple<std::string, IntegratorType>;
class EnvironmentFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(EnvironmentFurnace, AlbedoOneSphereRendersAsOneEverywhere) {
    const auto& [material_name, type] = GetParam();
    Material m = material_name == "diffuse" ? make_diffuse(Rgb(1.0f))
                 : material_name == "glass" ? make_dielectric(1.5f)
                                            : make_mirror(Rgb(1.0f));
    Scene scene = sphere_under_sky(m, constant_map(1.0f), 16, 64);
    scene.integrator.type = type;
    test::RenderMoments r = test::render_moments(scene);
    EXPECT_EQ(r.dropped, 0u);
    const int block = 2;
    const long tests = 3L * (16 / block) * (16 / block);
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, tests));
    for (int y = 0; y < 16; y += block)
        for (int x = 0; x < 16; x += block)
            for (int c = 0; c < 3; ++c) {
                test::BlockEstimate e = test::block_estimate(r, x, y, block, c);
                family.add(e.mean - 1.0, e.variance + kRoundingSigma * kRoundingSigma, x, y, c);
            }
    EXPECT_TRUE(family.passed()) << family.summary();
    // The sphere fills the middle of the image, so the test covers it and not only the background:
    // there the estimate is noisy (except for the mirror, whose single path is deterministic).
    if (material_name != "mirror") {
        EXPECT_GT(r.variance_of_mean(8, 8, 0), 0.0);
    }
}

INSTANTIATE_TEST_SUITE_P(
    MaterialsAndEstimators, EnvironmentFurnace,
    ::testing::Combine(::testing::Values("diffuse", "glass", "mirror"),
                       ::testing::Values(IntegratorType::kPath, IntegratorType::kBsdf)),
    [](const auto& param_info) {
        return std::get<0>(param_info.param) +
               (std::get<1>(param_info.param) == IntegratorType::kPath ? "_path" : "_bsdf");
    });

class EqualAreaFurnace : public ::testing::TestWithParam<bool> {};

TEST_P(EqualAreaFurnace, ConstantMapRendersADiffuseSphereAtItsAlbedo) {
    // An 8 x 8 equal-area map of radiance 1 (not 1 x 1: lookups cross the folded edges and
    // corners, and sampling goes through the square's distribution) in a rotated frame, around a
    // diffuse sphere of albedo 1: a convex sphere sees only the sky, so it renders at its albedo,
    // 1, as the background does. In spectral mode too: the map's texels are uplifted as
    // illuminants (D65 at luminance 1 for white), which the sensor turns back into 1.
    Image map(8, 8);
    for (Rgb& p : map.pixels) p = Rgb(1.0f);
    Scene scene = sphere_under_sky(make_diffuse(Rgb(1.0f)), map, 16, 64);
    scene.environment->mapping = EnvironmentMapping::kEqualArea;
    scene.environment->to_world = Transform::rotate(Vec3d(1.0, 0.5, -0.3), 0.9);
    scene.integrator.spectral = GetParam();
    test::RenderMoments r = test::render_moments(scene);
    EXPECT_EQ(r.dropped, 0u);
    const int block = 2;
    const long tests = 3L * (16 / block) * (16 / block);
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, tests));
    for (int y = 0; y < 16; y += block)
        for (int x = 0; x < 16; x += block)
            for (int c = 0; c < 3; ++c) {
                test::BlockEstimate e = test::block_estimate(r, x, y, block, c);
                family.add(e.mean - 1.0, e.variance + kRoundingSigma * kRoundingSigma, x, y, c);
            }
    EXPECT_TRUE(family.passed()) << family.summary();
    EXPECT_GT(r.variance_of_mean(8, 8, 0), 0.0);  // the sphere is in the test, not only the sky
}

INSTANTIATE_TEST_SUITE_P(RgbAndSpectral, EqualAreaFurnace, ::testing::Bool(),
                         [](const auto& param_info) { return std::string(param_info.param ? "spectral" : "rgb"); });

// Mean red value of the image's columns [x0, x1).
double column_mean(const Image& img, int x0, int x1) {
    double sum = 0.0;
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x) sum += double(img.at(x, y).r);
    return sum / double((x1 - x0) * img.height);
}

TEST(EnvironmentOrientation, SunAtQuarterULightsThePlusXSideAndRotationMovesIt) {
    // Black map with a bright patch at u = 0.25, v = 0.5: by the convention (u = atan2(d.x, -d.z)
    // / 2pi, v = acos(d.y) / pi) the direction +x on the horizon. The camera looks along -z, so
    // image right is +x: the sphere's right half is lit. Rotating the light 180 degrees about +y
    // sends the patch to -x, the left half.
    Image map(64, 32);
    for (int y = 15; y < 17; ++y)
        for (int x = 15; x < 17; ++x) map.at(x, y) = Rgb(100.0f);
    Scene scene = sphere_under_sky(make_diffuse(Rgb(0.8f)), map, 32, 32);
    scene.camera.position = {0, 0, 4};
    Image lit_right = render(scene, {.threads = 2}).image;
    EXPECT_GT(column_mean(lit_right, 16, 32), 20.0 * column_mean(lit_right, 0, 16));
    scene.environment->to_world = Transform::rotate(Vec3d(0, 1, 0), kPiD);
    Image lit_left = render(scene, {.threads = 2}).image;
    EXPECT_GT(column_mean(lit_left, 0, 16), 20.0 * column_mean(lit_left, 16, 32));
}

TEST(EqualAreaEnvironmentRender, ImportanceAndBsdfSamplingAgreeWithASun) {
    // A 16 x 16 equal-area sky: blue in the inner diamond (z > 0 in the light's frame), brown in
    // the corners, a 2 x 2 sun off-centre; the light frame's +z turned to world +y as a pbrt-v4
    // scene's transform would. A diffuse ball on a ground plane, bilinear and point lookups: the
    // path tracer's light sampling (and MIS) must agree with BSDF sampling alone.
    Image map(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            float u = std::abs((x + 0.5f) / 8.0f - 1.0f), v = std::abs((y + 0.5f) / 8.0f - 1.0f);
            map.at(x, y) = u + v < 1.0f ? Rgb(0.3f + 0.04f * float(x), 0.5f, 1.0f) : Rgb(0.2f, 0.15f, 0.1f);
        }
    for (int y = 5; y < 7; ++y)
        for (int x = 9; x < 11; ++x) map.at(x, y) = Rgb(40.0f, 36.0f, 25.0f);
    for (auto filter : {EnvironmentFilter::kBilinear, EnvironmentFilter::kPoint}) {
        Scene base = sphere_under_sky(make_diffuse(Rgb(0.7f, 0.6f, 0.5f)), map, 16, 2048);
        base.environment->mapping = EnvironmentMapping::kEqualArea;
        base.environment->filter = filter;
        base.environment->to_world = Transform::rotate(Vec3d(1, 0, 0), -kPiD / 2.0);
        base.materials.push_back(make_diffuse(Rgb(0.5f)));
        test::add_quad(base, {-20, -1, 20}, {40, 0, 0}, {0, 0, -40}, 1);
        base.camera.position = {0, 1.5f, 5};
        Scene bsdf = base;
        bsdf.integrator.type = IntegratorType::kBsdf;
        bsdf.sampler.spp = 8192;
        bsdf.sampler.seed = 21;
        test::RenderMoments a = test::render_moments(base), b = test::render_moments(bsdf);
        EXPECT_EQ(a.dropped + b.dropped, 0u);
        const int block = 4;
        const long tests = 2L * 3 * (16 / block) * (16 / block);
        const double z_critical = test::sidak_critical_z(test::kRenderTestAlpha, tests);
        test::ZTestFamily pair(z_critical);
        test::compare_renders(a, b, block, pair);
        EXPECT_TRUE(pair.passed()) << pair.summary();
        // Power: against a 5% brighter image the comparison fails broadly.
        test::ZTestFamily control(z_critical);
        test::compare_renders(a, b, block, control, 1.05);
        EXPECT_GE(control.rejected(), test::lit_blocks(b, block) / 4) << control.summary();
    }
}

TEST(EnvironmentAgreement, ImportanceUniformAndBsdfSamplingAgree) {
    // A diffuse ball on a ground plane under the sky with a sun: shadows, sky light and sun light.
    Scene base = sphere_under_sky(make_diffuse(Rgb(0.7f, 0.6f, 0.5f)), sky_map(), 32, 256);
    base.materials.push_back(make_diffuse(Rgb(0.5f)));
    test::add_quad(base, {-20, -1, 20}, {40, 0, 0}, {0, 0, -40}, 1);
    base.camera.position = {0, 1.5f, 5};
    struct Variant {
        std::string name;
        IntegratorType type;
        EnvironmentSampling sampling;
        int spp;
    };
    const std::vector<Variant> variants = {{"importance", IntegratorType::kPath, EnvironmentSampling::kImportance, 2048},
                                           {"uniform", IntegratorType::kPath, EnvironmentSampling::kUniform, 8192},
                                           {"bsdf", IntegratorType::kBsdf, EnvironmentSampling::kImportance, 8192}};
    std::vector<test::RenderMoments> renders;
    uint64_t seed = 11;
    for (const Variant& v : variants) {
        Scene s = base;
        s.integrator.type = v.type;
        s.environment->sampling = v.sampling;
        s.sampler.spp = v.spp;
        s.sampler.seed = seed++;
        renders.push_back(test::render_moments(s));
        EXPECT_EQ(renders.back().dropped, 0u) << v.name;
    }
    const int block = 4;
    const long tests = 3L * 3 * (32 / block) * (32 / block);
    const double z_critical = test::sidak_critical_z(test::kRenderTestAlpha, tests);
    for (size_t i = 0; i < renders.size(); ++i) {
        for (size_t j = i + 1; j < renders.size(); ++j) {
            test::ZTestFamily pair(z_critical);
            test::compare_renders(renders[i], renders[j], block, pair);
            EXPECT_TRUE(pair.passed()) << variants[i].name << " vs " << variants[j].name << ": " << pair.summary();
            // Power: the same comparison against a 5% brighter image must fail broadly.
            test::ZTestFamily control(z_critical);
            test::compare_renders(renders[i], renders[j], block, control, 1.05);
            EXPECT_GE(control.rejected(), test::lit_blocks(renders[j], block) / 4)
                << variants[i].name << " vs " << variants[j].name << " x 1.05: " << control.summary();
        }
    }
}

}  // namespace
}  // namespace candela
