// The white furnace with `multiscatter` end to end: a rough white metal or rough clear glass
// sphere under a constant environment of radiance 1 renders as 1 everywhere, through next-event
// estimation with MIS and through BSDF sampling alone, because the compensation lobes return the
// light the microfacets lose (materials/microfacet_multiscatter.h). Without them the sphere is
// visibly darker, which the same test detects. The z-tests allow each block the tables' error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 16;
constexpr int kBlock = 2;

struct Case {
    std::string name;
    bool glass;  // else metal
    float alpha;
    IntegratorType type;
};

RoughnessParams roughness(float alpha) { return RoughnessParams{FloatParam{alpha}, FloatParam{alpha}}; }

// A conductor that reflects everything (F = 1 - 1e-8) of roughness alpha.
LobeParams white_metal(float alpha, bool multiscatter) {
    return ConductorParams{ColorParam{Rgb(1.0f)}, ColorParam{Rgb(2e4f)}, roughness(alpha), multiscatter};
}
LobeParams clear_glass(float alpha, bool multiscatter) {
    return RoughDielectricParams{1.5f, ColorParam{Rgb(1.0f)}, roughness(alpha), multiscatter};
}

Scene furnace(const Case& c, bool multiscatter) {
    Scene s;
    s.materials = {make_material(c.glass ? clear_glass(c.alpha, multiscatter) : white_metal(c.alpha, multiscatter))};
    s.material_names = {"sphere"};
    test::add_sphere(s, {0, 0, 0}, 1.0);
    test::set_camera(s, Vec3f{0, 0.3f, 4}, Vec3f{0, 0, 0}, 40, kSize, kSize);
    s.sampler.spp = 256;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 5;
    s.integrator.type = c.type;
    s.integrator.max_depth = 256;  // glass: internal reflections; truncation is then negligible
    Image sky(1, 1);
    sky.at(0, 0) = Rgb(1.0f);
    s.environment = EnvironmentSettings{std::move(sky), 1.0f, Transform(), EnvironmentSampling::kImportance};
    return s;
}

// z-tests of 2x2 blocks against `expected`, allowing each a bias of `tolerance` (the tables'
// interpolation error, about 0.1% per bounce on the metal and 0.4% on glass, measured by
// tests/materials/microfacet_multiscatter_test.cpp): |mean - expected| - tolerance must be
// within the Sidak-corrected critical z of the block's standard error.
test::ZTestFamily blocks_against(const test::RenderMoments& r, double expected, double tolerance) {
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, 3L * (kSize / kBlock) * (kSize / kBlock)));
    for (int y = 0; y < kSize; y += kBlock)
        for (int x = 0; x < kSize; x += kBlock)
            for (int c = 0; c < 3; ++c) {
                test::BlockEstimate e = test::block_estimate(r, x, y, kBlock, c);
                double d = e.mean - expected;
                double beyond = std::max(0.0, std::abs(d) - tolerance);
                family.add(d < 0.0 ? -beyond : beyond, e.variance, x, y, c);
            }
    return family;
}

class MultiscatterFurnace : public ::testing::TestWithParam<Case> {};

TEST_P(MultiscatterFurnace, RoughWhiteSphereRendersAsOneEverywhere) {
    const Case& c = GetParam();
    const double tolerance = c.glass ? 0.01 : 0.003;
    test::RenderMoments r = test::render_moments(furnace(c, true));
    EXPECT_EQ(r.dropped, 0u);
    test::ZTestFamily family = blocks_against(r, 1.0, tolerance);
    EXPECT_TRUE(family.passed()) << family.summary();
    if (!family.passed()) test::write_diagnostic(r, "multiscatter_furnace_" + c.name);
    // Power: the sphere is noisy (it is not the sky), and without the compensation the same
    // test rejects the image.
    EXPECT_GT(r.variance_of_mean(8, 8, 0), 0.0);
    test::ZTestFamily single = blocks_against(test::render_moments(furnace(c, false)), 1.0, tolerance);
    EXPECT_FALSE(single.passed()) << single.summary();
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

INSTANTIATE_TEST_SUITE_P(
    MetalAndGlass, MultiscatterFurnace,
    ::testing::Values(Case{"metal_a05_path", false, 0.5f, IntegratorType::kPath},
                      Case{"metal_a1_path", false, 1.0f, IntegratorType::kPath},
                      Case{"metal_a1_bsdf", false, 1.0f, IntegratorType::kBsdf},
                      Case{"glass_a05_path", true, 0.5f, IntegratorType::kPath},
                      Case{"glass_a1_bsdf", true, 1.0f, IntegratorType::kBsdf}),
    [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace candela
