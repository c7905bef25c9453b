// How the integrators treat delta lights: bsdf, which can only find light by hitting it, refuses
// them; next-event estimation weights them 1 whether MIS is on or off (no BSDF-sampled ray can
// find them), so path tracing with and without MIS renders the very same bits when delta lights
// are the only lights.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "candela/core/error.h"
#include "candela/geometry/accelerator.h"
#include "candela/lights/light_set.h"
#include "candela/integrators/integrator.h"
#include "candela/render/renderer.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// small_box_scene lit by a point, a spot and a directional light only.
Scene box_under_delta_lights(int spp) {
    Scene s = test::small_box_scene(24, 16, spp);
    s.delta_lights.push_back({PointLight{{0.2f, 0.6f, -0.5f}, Color(2.0f, 1.5f, 1.0f)}, std::nullopt});
    s.delta_lights.push_back({SpotLight{{-0.5f, 0.8f, -0.2f}, normalize(Vec3f(0.3f, -1.0f, 0.4f)), Color(4.0f),
                              std::cos(radians(20.0f)), std::cos(radians(35.0f))},
                              std::nullopt});
    s.delta_lights.push_back({DirectionalLight{normalize(Vec3f(0.5f, -1.0f, 0.8f)), Color(0.7f)}, 10.0f});
    s.integrator.max_depth = 4;
    return s;
}

TEST(DeltaLightIntegrators, BsdfRefusesDeltaLightsAndTheOthersAccept) {
    Scene s = box_under_delta_lights(1);
    Accelerator accel(s.meshes, s.spheres, s.disks, s.shapes);
    LightSet lights = build_light_set(s, accel);
    ASSERT_TRUE(lights.has_delta_lights());
    for (IntegratorType type : {IntegratorType::kPath, IntegratorType::kWhitted, IntegratorType::kNormals,
                                IntegratorType::kDepth, IntegratorType::kAlbedo, IntegratorType::kAo}) {
        s.integrator.type = type;
        EXPECT_NE(make_integrator(s, accel, lights), nullptr);
    }
    s.integrator.type = IntegratorType::kBsdf;
    EXPECT_THROW(make_integrator(s, accel, lights), RenderError);
}

TEST(DeltaLightIntegrators, MisLeavesDeltaLightSamplesAlone) {
    Scene with_mis = box_under_delta_lights(4);
    Scene without = with_mis;
    without.integrator.mis = false;
    Image a = render(with_mis, {.threads = 2}).image, b = render(without, {.threads = 2}).image;
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)), 0);
    // And they are lit: the test compares images, not two black frames (the box fills about a
    // third of the view).
    int lit = 0;
    for (const Rgb& p : a.pixels) lit += p.max_component() > 0.0f;
    EXPECT_GT(lit, int(a.pixels.size()) / 4);
}

TEST(DeltaLightIntegrators, DirectionalPowerBecomesIrradianceOverTheScenesDisk) {
    // power / (pi r^2), r the radius of the scene's bounding sphere.
    Scene s = box_under_delta_lights(1);
    s.delta_lights.resize(2);
    s.delta_lights[0].light = DirectionalLight{{0.0f, -1.0f, 0.0f}, Color(2.0f)};
    s.delta_lights[0].directional_power = 30.0f;
    s.delta_lights[1].light = DirectionalLight{{0.0f, -1.0f, 0.0f}, Color(2.0f)};
    s.delta_lights[1].directional_power = std::nullopt;
    Accelerator accel(s.meshes, s.spheres, s.disks, s.shapes);
    LightSet lights = build_light_set(s, accel);
    Bounds3f b = accel.bounds();
    const float r = 0.5f * length(b.diagonal());
    const float by_power = 2.0f * 30.0f / (kPi * r * r);
    // Selection by power: the one given by power emits 2 x 30 W, the other pi r^2 x 2.
    const double p_first = 60.0 / (60.0 + double(kPi * r * r * 2.0f));
    int first = 0, second = 0;
    constexpr int kChoices = 10000;
    for (int i = 0; i < kChoices; ++i) {
        std::optional<LightSample> ls = lights.sample({0.0f, 0.0f, 0.0f}, (float(i) + 0.5f) / kChoices, {0.5f, 0.5f});
        ASSERT_TRUE(ls);
        if (std::abs(ls->Le[1] - by_power) < 1e-5f * by_power) ++first;
        if (ls->Le == Color(2.0f)) ++second;
    }
    EXPECT_EQ(first + second, kChoices);
    EXPECT_NEAR(double(first) / kChoices, p_first, 2.0 / kChoices);
}

}  // namespace
}  // namespace candela
