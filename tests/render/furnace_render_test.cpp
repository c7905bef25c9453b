// The white furnace (DESIGN.md, "Correctness"): a camera inside a closed sphere (or a cube of six
// quad lights) whose inside emits radiance Le and reflects diffusely with albedo a. Every point
// sees the same radiance L, and L = Le + a L (the walls see only the walls), so L = Le / (1 - a)
// in every pixel, whatever the camera's position inside. Any estimator that loses or
// double-counts energy at some bounce (a wrong light pdf, MIS weights not summing to 1, a wrong
// Russian roulette weight, a missing cosine) moves this value.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

enum class Enclosure { kSphere, kCube };

struct FurnaceCase {
    std::string name;
    Enclosure enclosure;
    IntegratorType type;
    bool mis;
    float albedo;
    float rr_probability;  // 0: survival by throughput
    bool spectral = false;  // transport four wavelengths: grey albedo and a white (D65) emitter
                            // give every wavelength the same answer, which the sensor maps to
                            // the same pixel value as in RGB mode
};

constexpr int kSize = 32;        // pixels per side; square, so the whole image is one block
constexpr int kBlock = 4;        // pixels per block side for the local z-tests
constexpr int kSpp = 64;
constexpr int kMaxDepth = 1000;  // truncation bias a^1000 L / (1 - a) < 1e-96 for a <= 0.8

Scene furnace_scene(const FurnaceCase& c) {
    Scene s;
    s.materials = {make_diffuse(Rgb(c.albedo))};
    s.material_names = {"furnace"};
    if (c.enclosure == Enclosure::kSphere) {
        test::add_sphere(s, {0, 0, 0}, 1.0, 0, /*reverse_orientation=*/true);
    } else {
        // The cube [-1, 1]^3, every face facing in: six lights for next-event estimation to pick.
        // Not with NEE alone: near an edge, area sampling the adjacent face gives contributions
        // growing as 1 / distance^2 whose variance is infinite, so no z-test would be valid. Nor
        // with BSDF sampling alone, whose furnace estimate (emission 1 at every bounce) does not
        // depend on the geometry at all: the sphere cases test it.
        test::add_quad(s, {-1, -1, -1}, {0, 0, 2}, {2, 0, 0});  // y = -1, +y
        test::add_quad(s, {-1, 1, -1}, {2, 0, 0}, {0, 0, 2});   // y = 1, -y
        test::add_quad(s, {-1, -1, 1}, {0, 2, 0}, {2, 0, 0});   // z = 1, -z
        test::add_quad(s, {-1, -1, -1}, {2, 0, 0}, {0, 2, 0});  // z = -1, +z
        test::add_quad(s, {-1, -1, -1}, {0, 2, 0}, {0, 0, 2});  // x = -1, +x
        test::add_quad(s, {1, -1, -1}, {0, 0, 2}, {0, 2, 0});   // x = 1, -x
    }
    for (uint32_t shape = 0; shape < s.shapes.size(); ++shape) test::set_emission(s, shape, Rgb(1.0f));
    // Off centre and looking sideways, so distances and angles to the wall vary over the image.
    test::set_camera(s, Vec3f{0.3f, -0.2f, 0.1f}, Vec3f{1.0f, 0.4f, -0.5f}, 90, kSize, kSize);
    s.sampler.spp = kSpp;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 11;
    s.integrator.type = c.type;
    s.integrator.mis = c.mis;
    s.integrator.max_depth = kMaxDepth;
    s.integrator.rr_probability = c.rr_probability;
    s.integrator.spectral = c.spectral;
    return s;
}

// z-tests of every block and of the whole image against `expected`, Sidak-corrected together.
test::ZTestFamily test_against(const test::RenderMoments& m, double expected) {
    const long blocks = long(kSize / kBlock) * long(kSize / kBlock);
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, 3 * (blocks + 1)));
    for (int c = 0; c < 3; ++c) {
        for (int y = 0; y < kSize; y += kBlock) {
            for (int x = 0; x < kSize; x += kBlock) {
                test::BlockEstimate b = test::block_estimate(m, x, y, kBlock, c);
                family.add(b.mean - expected, b.variance, x, y, c);
            }
        }
        test::BlockEstimate whole = test::block_estimate(m, 0, 0, kSize, c);
        family.add(whole.mean - expected, whole.variance, -1, -1, c);
    }
    return family;
}

class WhiteFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(WhiteFurnace, EveryPixelSeesEmissionOverOneMinusAlbedo) {
    const FurnaceCase& c = GetParam();
    test::RenderMoments m = test::render_moments(furnace_scene(c));
    const double expected = 1.0 / (1.0 - double(c.albedo));
    EXPECT_EQ(m.dropped, 0u);

    test::ZTestFamily family = test_against(m, expected);
    EXPECT_TRUE(family.passed()) << family.summary();

    // Power: the whole image's standard error is below 0.4% of the answer, so a 2% bias would
    // stand 5 sigma out; and the same test against an answer 2% off does reject.
    const double sigma = std::sqrt(test::block_estimate(m, 0, 0, kSize, 0).variance);
    EXPECT_LT(sigma, 0.004 * expected);
    // Paths are cut at kMaxDepth bounces: the energy lost, a^kMaxDepth / (1 - a), is negligible.
    EXPECT_LT(std::pow(double(c.albedo), kMaxDepth) * expected, 1e-6 * sigma);
    test::ZTestFamily wrong = test_against(m, 1.02 * expected);
    EXPECT_FALSE(wrong.passed()) << wrong.summary();
    if (!family.passed()) test::write_diagnostic(m, "furnace_" + c.name);
}

void PrintTo(const FurnaceCase& c, std::ostream* os) { *os << c.name; }

INSTANTIATE_TEST_SUITE_P(
    AllEstimators, WhiteFurnace,
    ::testing::Values(FurnaceCase{"sphere_path_a05", Enclosure::kSphere, IntegratorType::kPath, true, 0.5f, 0.0f},
                      FurnaceCase{"sphere_path_a08", Enclosure::kSphere, IntegratorType::kPath, true, 0.8f, 0.0f},
                      FurnaceCase{"sphere_path_a05_rr08", Enclosure::kSphere, IntegratorType::kPath, true, 0.5f, 0.8f},
                      FurnaceCase{"sphere_path_a08_rr08", Enclosure::kSphere, IntegratorType::kPath, true, 0.8f, 0.8f},
                      FurnaceCase{"sphere_nee_a05", Enclosure::kSphere, IntegratorType::kPath, false, 0.5f, 0.0f},
                      FurnaceCase{"sphere_nee_a08", Enclosure::kSphere, IntegratorType::kPath, false, 0.8f, 0.0f},
                      FurnaceCase{"sphere_nee_a05_rr08", Enclosure::kSphere, IntegratorType::kPath, false, 0.5f, 0.8f},
                      FurnaceCase{"sphere_nee_a08_rr08", Enclosure::kSphere, IntegratorType::kPath, false, 0.8f, 0.8f},
                      FurnaceCase{"sphere_bsdf_a05", Enclosure::kSphere, IntegratorType::kBsdf, true, 0.5f, 0.0f},
                      FurnaceCase{"sphere_bsdf_a08", Enclosure::kSphere, IntegratorType::kBsdf, true, 0.8f, 0.0f},
                      FurnaceCase{"sphere_bsdf_a05_rr08", Enclosure::kSphere, IntegratorType::kBsdf, true, 0.5f, 0.8f},
                      FurnaceCase{"sphere_bsdf_a08_rr08", Enclosure::kSphere, IntegratorType::kBsdf, true, 0.8f, 0.8f},
                      FurnaceCase{"cube_path_a08", Enclosure::kCube, IntegratorType::kPath, true, 0.8f, 0.0f},
                      FurnaceCase{"cube_path_a05_rr08", Enclosure::kCube, IntegratorType::kPath, true, 0.5f, 0.8f},
                      FurnaceCase{"sphere_path_a08_spectral", Enclosure::kSphere, IntegratorType::kPath, true, 0.8f, 0.0f, true},
                      FurnaceCase{"sphere_bsdf_a05_spectral", Enclosure::kSphere, IntegratorType::kBsdf, true, 0.5f, 0.0f, true},
                      FurnaceCase{"cube_path_a08_spectral", Enclosure::kCube, IntegratorType::kPath, true, 0.8f, 0.0f, true}),
    [](const auto& param_info) { return param_info.param.name; });

// The white furnace of DESIGN.md with a material that transmits: a sphere of diffuse_transmission
// with R + T = 1 under a uniform environment of radiance 1. It absorbs nothing and emits nothing,
// so every pixel, on the sphere or beside it, is 1 (paths through it, reflected or transmitted,
// any number of times, end in the environment); a lost or doubled side would move it. In both
// colour modes, with the same z-tests as above.
TEST(WhiteFurnace, ADiffuseTransmissionSphereOfReflectancePlusTransmittanceOneVanishes) {
    for (const bool spectral : {false, true}) {
        SCOPED_TRACE(spectral ? "spectral" : "rgb");
        const std::string json = R"({
          "integrator": {"type": "path", "max_depth": 1000, "spectral": )" +
                                 std::string(spectral ? "true" : "false") + R"(},
          "sampler": {"type": "independent", "spp": 64, "seed": 5},
          "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 45,
                     "resolution": [32, 32]},
          "materials": {"sheet": {"type": "diffuse_transmission", "reflectance": 0.3, "transmittance": 0.7}},
          "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "sheet"}],
          "lights": [{"type": "environment", "color": [1, 1, 1]}]
        })";
        const Scene scene = load_scene_from_string(json, "diffuse_transmission_furnace.json");
        test::RenderMoments m = test::render_moments(scene);
        EXPECT_EQ(m.dropped, 0u);
        test::ZTestFamily family = test_against(m, 1.0);
        EXPECT_TRUE(family.passed()) << family.summary();
        // Power: a 2% bias is rejected.
        test::ZTestFamily wrong = test_against(m, 1.02);
        EXPECT_FALSE(wrong.passed()) << wrong.summary();
        if (!family.passed()) test::write_diagnostic(m, spectral ? "furnace_dt_spectral" : "furnace_dt_rgb");
    }
}

}  // namespace
}  // namespace candela
