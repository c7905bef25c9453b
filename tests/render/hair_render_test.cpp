// The hair material end to end: a white fibre-parametrized sphere (no absorption) inside a black
// sphere that emits radiance 1. The hair scatters everything over the whole sphere of directions
// (hair.h), so every path ends on the wall and every pixel sees exactly 1, in both colour modes,
// with MIS and with BSDF sampling alone. A lost or doubled contribution, a pdf that disagrees
// with sampling, or a frame that is not the one the lobe assumes (x along dpdu) would show.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 24;
constexpr int kBlock = 4;

struct HairCase {
    std::string name;
    IntegratorType type;
    bool spectral;
};

Scene hair_furnace(const HairCase& c) {
    Scene s;
    HairParams hair;
    hair.sigma_a = ColorParam{Rgb(0.0f), kNoTexture, 0.0f, kUnbounded, SpectrumForm::kUnbounded};
    hair.beta_m = FloatParam{0.25f};
    hair.beta_n = FloatParam{0.4f};
    s.materials = {make_diffuse(Rgb(0.0f)), make_material(hair)};
    s.material_names = {"wall", "hair"};
    test::add_sphere(s, {0, 0, 0}, 3.0, 0, /*reverse_orientation=*/true);
    test::set_emission(s, 0, Rgb(1.0f));
    test::add_sphere(s, {0, 0, 0}, 1.0, 1);
    test::set_camera(s, Vec3f{0.0f, 0.3f, 2.5f}, Vec3f{0.0f, 0.0f, 0.0f}, 50, kSize, kSize);
    s.sampler.spp = 64;
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.seed = 5;
    s.integrator.type = c.type;
    s.integrator.max_depth = 1000;
    s.integrator.spectral = c.spectral;
    return s;
}

class HairFurnaceRender : public ::testing::TestWithParam<HairCase> {};

TEST_P(HairFurnaceRender, EveryPixelSeesTheWallsRadiance) {
    const HairCase& c = GetParam();
    test::RenderMoments m = test::render_moments(hair_furnace(c));
    EXPECT_EQ(m.dropped, 0u);
    const long blocks = long(kSize / kBlock) * long(kSize / kBlock);
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, 3 * blocks));
    for (int ch = 0; ch < 3; ++ch)
        for (int y = 0; y < kSize; y += kBlock)
            for (int x = 0; x < kSize; x += kBlock) {
                // BSDF sampling alone weighs every bounce by 1 up to float rounding (hair.h's
                // sampling density is f |cos| itself), so its variance can be near 0: differences
                // within 1e-6 (a few float roundings per bounce) count as none.
                test::BlockEstimate b = test::block_estimate(m, x, y, kBlock, ch);
                const double d = b.mean - 1.0;
                family.add(std::abs(d) <= 1e-6 ? 0.0 : d, b.variance, x, y, ch);
            }
    EXPECT_TRUE(family.passed()) << family.summary();
    if (!family.passed()) test::write_diagnostic(m, "hair_furnace_" + c.name);
}

void PrintTo(const HairCase& c, std::ostream* os) { *os << c.name; }

INSTANTIATE_TEST_SUITE_P(BothModes, HairFurnaceRender,
                         ::testing::Values(HairCase{"path_rgb", IntegratorType::kPath, false},
                                           HairCase{"bsdf_rgb", IntegratorType::kBsdf, false},
                                           HairCase{"path_spectral", IntegratorType::kPath, true},
                                           HairCase{"bsdf_spectral", IntegratorType::kBsdf, true}),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace candela
