// Area lights on the clipped quadrics (lights/quadric_emitter.h): a floor lit by an emitting
// cylinder, partial sphere and partial disk, each under an uneven scale (where uniform in object
// space is not uniform in the world, and the emitter's area density must carry the Jacobian),
// rendered by next-event estimation alone (`path` without MIS) and by BSDF sampling alone
// (`bsdf`). The two estimators share no sampling code for the light: one samples the emitter and
// divides by its pdf, the other finds it by chance, so a wrong pdf, a wrong area or points off the
// clipped surface make them disagree. z-tests of every block and the whole image, with variances
// measured from the samples.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kBlock = 8;

std::string scene(const std::string& emitter, const char* integrator, int seed) {
    return R"({
  "integrator": )" + std::string(integrator) + R"(,
  "sampler": {"type": "independent", "spp": 1024, "seed": )" + std::to_string(seed) + R"(},
  "camera": {"type": "perspective", "position": [0, 3, -3.5], "look_at": [0, 0.4, 0],
             "up": [0, 1, 0], "fov": 45, "resolution": [32, 32]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.7, 0.6, 0.5]},
                "lamp": {"type": "diffuse", "albedo": 0.3}},
  "shapes": [
    {"type": "quad", "corner": [-4, 0, -4], "edge1": [0, 0, 8], "edge2": [8, 0, 0], "material": "floor"},
    )" + emitter + R"(
  ]
})";
}

constexpr const char* kNeeOnly = R"({"type": "path", "max_depth": 2, "mis": false})";
constexpr const char* kBsdfOnly = R"({"type": "bsdf", "max_depth": 2})";

void expect_estimators_agree(const std::string& emitter, const char* name) {
    const std::filesystem::path file = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "inline.json";
    const Scene nee = load_scene_from_string(scene(emitter, kNeeOnly, 1), file);
    const Scene bsdf = load_scene_from_string(scene(emitter, kBsdfOnly, 2), file);
    ASSERT_EQ(nee.quadrics.size(), 1u);
    const test::RenderMoments a = test::render_moments(nee), b = test::render_moments(bsdf);
    EXPECT_EQ(a.dropped, 0u);
    EXPECT_EQ(b.dropped, 0u);
    EXPECT_GT(test::lit_blocks(a, kBlock), 40);
    test::ZTestFamily family = test::compare_blocks_and_whole(a, b, kBlock);
    if (!family.passed()) {
        test::write_diagnostic(a, std::string("quadric_light_nee_") + name);
        test::write_diagnostic(b, std::string("quadric_light_bsdf_") + name);
    }
    EXPECT_TRUE(family.passed()) << family.summary();
    // The control: the same comparison with one estimate 5% off must fail, so the test has the
    // power to see an error of that size (sampling a partial disk or sphere as if it were whole, as pbrt-v4 does, is off by far more).
    EXPECT_FALSE(test::compare_blocks_and_whole(a, b, kBlock, 1.05).passed());
}

TEST(QuadricLightRender, CylinderNextEventEstimationAgreesWithBsdfSampling) {
    // Two-sided, cut open by phi_max so that its inside shows and lights the floor too.
    expect_estimators_agree(R"({"type": "cylinder", "radius": 0.35, "z_min": -0.6, "z_max": 0.6, "phi_max": 250,
      "material": "lamp", "emission": [3, 2.5, 2], "two_sided": true,
      "transform": [{"scale": [1.6, 1, 0.8]}, {"rotate": {"axis": [0, 1, 0], "angle": 30}}, {"translate": [0, 0.9, 0]}]})",
                            "cylinder");
}

TEST(QuadricLightRender, PartialSphereNextEventEstimationAgreesWithBsdfSampling) {
    expect_estimators_agree(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "z_min": -0.3, "z_max": 0.45,
      "phi_max": 220, "material": "lamp", "emission": [2, 3, 2.5],
      "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 70}}, {"scale": [1.5, 1, 0.8]}, {"translate": [0.2, 1.0, 0]}]})",
                            "sphere");
}

TEST(QuadricLightRender, PartialDiskNextEventEstimationAgreesWithBsdfSampling) {
    expect_estimators_agree(R"({"type": "disk", "center": [0, 1.1, 0], "normal": [0, -1, 0.3], "radius": 0.7,
      "inner_radius": 0.3, "phi_max": 260, "material": "lamp", "emission": [4, 3, 2],
      "transform": [{"scale": [1.8, 1, 0.7]}]})",
                            "disk");
}

}  // namespace
}  // namespace candela
