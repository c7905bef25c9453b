// The BVH light sampler (LightSelection::kBvh) against the power sampler: choosing lights
// differently changes only the noise, so the two renders of a scene with several lights agree
// block by block (z-tests, tests/support/render_moments.h), with path tracing (the Cornell box
// with its quad, a point and a spot light and a constant environment) and with volpath in a
// medium (tests/data/pbrt-media/cloud-box.pbrt: a spot and a quad light, whose medium vertices
// choose with no normal). Each has a control that must fail: the bvh render scaled by 1.1.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "candela/formats/scene_file.h"
#include "candela/render/renderer.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kBlock = 4;

void expect_agreement(Scene scene, const std::string& name) {
    scene.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    Scene power = scene, bvh = scene;
    power.integrator.light_selection = LightSelection::kPower;
    bvh.integrator.light_selection = LightSelection::kBvh;
    bvh.sampler.seed = scene.sampler.seed + 1;
    test::RenderMoments a = test::render_moments(power), b = test::render_moments(bvh);
    EXPECT_EQ(a.dropped + b.dropped, 0u);
    test::ZTestFamily family = test::compare_blocks_and_whole(a, b, kBlock);
    EXPECT_TRUE(family.passed()) << family.summary();
    test::ZTestFamily control = test::compare_blocks_and_whole(a, b, kBlock, 1.1);
    EXPECT_GE(control.rejected(), test::lit_blocks(a, kBlock) / 4) << control.summary();
    if (!family.passed()) {
        test::write_diagnostic(a, "light_sampler_" + name + "_power");
        test::write_diagnostic(b, "light_sampler_" + name + "_bvh");
    }
}

TEST(LightSamplerAgreement, PathBvhAgreesWithPowerInTheCornellBoxWithFourKindsOfLight) {
    constexpr int kSize = 32;
    Scene s = test::cornell_box_scene(kSize, kSize, 512);
    s.delta_lights.push_back({PointLight{{-0.4f, 0.5f, -0.2f}, Color(1.5f, 1.2f, 1.0f)}, std::nullopt});
    SpotLight spot;
    spot.position = {0.6f, 0.7f, -0.6f};
    spot.axis = normalize(Vec3f(-0.3f, -1.0f, 0.5f));
    spot.intensity = Color(3.0f);
    spot.cos_falloff_start = std::cos(radians(15.0f));
    spot.cos_falloff_end = std::cos(radians(30.0f));
    s.delta_lights.push_back({spot, std::nullopt});
    Image sky(1, 1);
    sky.at(0, 0) = Rgb(0.3f);
    s.environment = EnvironmentSettings{std::move(sky), 1.0f, Transform(), EnvironmentSampling::kUniform};
    s.sampler.seed = 21;
    expect_agreement(s, "cornell");
}

TEST(LightSamplerAgreement, VolpathBvhAgreesWithPowerInACloudLitByASpotAndAQuad) {
    Scene s = load_scene_file(std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt-media" / "cloud-box.pbrt");
    ASSERT_EQ(s.integrator.type, IntegratorType::kVolPath);
    s.camera.width = 24;
    s.camera.height = 24;
    s.sampler.spp = 256;
    s.sampler.seed = 5;
    s.film.filter = FilterSettings();  // a box of one pixel: the moments are of plain pixel means
    expect_agreement(s, "cloud_box");
}

}  // namespace
}  // namespace candela
