// The scene file's point, spot and directional lights: every key changes the loaded light, bad
// values are located errors, lights that emit nothing are dropped with a warning, and the bsdf
// integrator, which cannot see them, refuses them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// The one delta light of a scene whose `lights` array holds `light`.
DeltaLightSettings only_light(const std::string& light) {
    Scene s = load_json(R"({"lights": [)" + light + "]}");
    EXPECT_EQ(s.delta_lights.size(), 1u);
    return s.delta_lights.empty() ? DeltaLightSettings{} : s.delta_lights[0];
}

template <class T>
T only(const std::string& light) {
    DeltaLightSettings settings = only_light(light);
    const T* l = std::get_if<T>(&settings.light);
    EXPECT_NE(l, nullptr);
    return l != nullptr ? *l : T{};
}

void expect_color_near(const Color& a, const Color& b, float relative = 1e-6f) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], relative * std::abs(b[c])) << "channel " << c;
}

TEST(SceneLoaderDeltaLights, PointPositionAndIntensity) {
    PointLight p = only<PointLight>(R"({"type": "point", "position": [1, 2, 3], "intensity": [4, 5, 6]})");
    EXPECT_EQ(p.position, Vec3f(1, 2, 3));
    EXPECT_EQ(p.intensity, Color(4, 5, 6));
    // Intensity defaults to 1 (white), as pbrt-v4's I defaults to the colour space's illuminant.
    EXPECT_EQ(only<PointLight>(R"({"type": "point", "position": [0, 0, 0]})").intensity, Color(1.0f));
}

TEST(SceneLoaderDeltaLights, PointScaleMultipliesAndPowerNormalizes) {
    EXPECT_EQ(only<PointLight>(R"({"type": "point", "position": [0, 0, 0], "intensity": 2, "scale": 3})").intensity,
              Color(6.0f));
    // pbrt-v4: I = colour x scale x power / (4 pi).
    expect_color_near(only<PointLight>(R"({"type": "point", "position": [0, 0, 0], "power": 100})").intensity,
                      Color(100.0f / (4.0f * kPi)));
    expect_color_near(only<PointLight>(R"({"type": "point", "position": [0, 0, 0], "intensity": [1, 0.5, 0.25],
                                          "scale": 2, "power": 100})")
                          .intensity,
                      Color(1.0f, 0.5f, 0.25f) * (200.0f / (4.0f * kPi)));
}

TEST(SceneLoaderDeltaLights, SpotKeys) {
    SpotLight s = only<SpotLight>(R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 3],
                                      "intensity": 50, "cone_angle": 30, "cone_delta": 5})");
    EXPECT_EQ(s.position, Vec3f(0, 4, 0));
    EXPECT_NEAR(s.axis.y, -0.8f, 1e-6f);
    EXPECT_NEAR(s.axis.z, 0.6f, 1e-6f);
    EXPECT_EQ(s.intensity, Color(50.0f));
    EXPECT_FLOAT_EQ(s.cos_falloff_end, std::cos(radians(30.0f)));
    EXPECT_FLOAT_EQ(s.cos_falloff_start, std::cos(radians(25.0f)));
    SpotLight wide = only<SpotLight>(R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0],
                                         "cone_angle": 60, "cone_delta": 20})");
    EXPECT_FLOAT_EQ(wide.cos_falloff_end, 0.5f);
    EXPECT_FLOAT_EQ(wide.cos_falloff_start, std::cos(radians(40.0f)));
}

TEST(SceneLoaderDeltaLights, SpotDefaultsArePbrts) {
    SpotLight s = only<SpotLight>(R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0]})");
    EXPECT_EQ(s.intensity, Color(1.0f));
    EXPECT_FLOAT_EQ(s.cos_falloff_end, std::cos(radians(30.0f)));
    EXPECT_FLOAT_EQ(s.cos_falloff_start, std::cos(radians(25.0f)));
    // A cone narrower than the default falloff falls off over its whole width.
    SpotLight narrow = only<SpotLight>(R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0],
                                           "cone_angle": 3})");
    EXPECT_FLOAT_EQ(narrow.cos_falloff_start, 1.0f);
    // cone_delta 0: a hard edge.
    SpotLight hard = only<SpotLight>(R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0],
                                         "cone_delta": 0})");
    EXPECT_EQ(hard.cos_falloff_start, hard.cos_falloff_end);
}

TEST(SceneLoaderDeltaLights, SpotScaleAndPower) {
    const std::string spot = R"({"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0], "intensity": 2,
                                 "cone_angle": 60, "cone_delta": 20, )";
    EXPECT_EQ(only<SpotLight>(spot + R"("scale": 4})").intensity, Color(8.0f));
    // pbrt-v4: I = colour x scale x power / (2 pi (1 - (cos_start + cos_end) / 2)).
    const float k = 2.0f * kPi * (1.0f - 0.5f * (std::cos(radians(40.0f)) + 0.5f));
    expect_color_near(only<SpotLight>(spot + R"("power": 30})").intensity, Color(2.0f * 30.0f / k), 1e-5f);
}

TEST(SceneLoaderDeltaLights, DirectionalKeys) {
    DeltaLightSettings d = only_light(R"({"type": "directional", "direction": [0, -2, 0], "irradiance": [3, 2, 1]})");
    const DirectionalLight& light = std::get<DirectionalLight>(d.light);
    EXPECT_EQ(light.direction, Vec3f(0, -1, 0));
    EXPECT_EQ(light.irradiance, Color(3, 2, 1));
    EXPECT_FALSE(d.directional_power);
    EXPECT_EQ(only<DirectionalLight>(R"({"type": "directional", "direction": [1, 0, 0], "scale": 0.5})").irradiance,
              Color(0.5f));
    // With `power` the irradiance waits for the scene's size: the colour x scale is kept, and the
    // power.
    DeltaLightSettings by_power =
        only_light(R"({"type": "directional", "direction": [1, 0, 0], "irradiance": 2, "scale": 3, "power": 40})");
    EXPECT_EQ(std::get<DirectionalLight>(by_power.light).irradiance, Color(6.0f));
    ASSERT_TRUE(by_power.directional_power);
    EXPECT_EQ(*by_power.directional_power, 40.0f);
}

TEST(SceneLoaderDeltaLights, SeveralLightsBesideAnEnvironment) {
    Scene s = load_json(R"({"lights": [{"type": "point", "position": [0, 1, 0]},
                                       {"type": "environment", "color": 0.1},
                                       {"type": "directional", "direction": [0, -1, 0]},
                                       {"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0]}]})");
    ASSERT_EQ(s.delta_lights.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<PointLight>(s.delta_lights[0].light));
    EXPECT_TRUE(std::holds_alternative<DirectionalLight>(s.delta_lights[1].light));
    EXPECT_TRUE(std::holds_alternative<SpotLight>(s.delta_lights[2].light));
    EXPECT_TRUE(s.environment);
}

TEST(SceneLoaderDeltaLights, ADeltaLightIsALight) {
    // warn_if_unlit: a scene lit only by a point light renders, without the "no lights" warning.
    Scene s = load_json(R"({"lights": [{"type": "point", "position": [0, 1, 0]}]})");
    EXPECT_TRUE(s.warnings.empty());
    Scene unlit = load_json(R"({"lights": []})");
    ASSERT_EQ(unlit.warnings.size(), 1u);
    EXPECT_NE(unlit.warnings[0].find("the scene has no lights"), std::string::npos);
}

TEST(SceneLoaderDeltaLights, LightsThatEmitNothingAreDroppedWithAWarning) {
    struct Case {
        const char* light;
        const char* why;
    };
    for (const Case& c : {Case{R"({"type": "point", "position": [0, 1, 0], "intensity": 0})", "its intensity is 0"},
                          Case{R"({"type": "point", "position": [0, 1, 0], "scale": 0})", "its scale is 0"},
                          Case{R"({"type": "spot", "position": [0, 1, 0], "look_at": [0, 0, 0], "power": 0})",
                               "its power is 0"},
                          Case{R"({"type": "directional", "direction": [0, -1, 0], "irradiance": [0, 0, 0]})",
                               "its irradiance is 0"}}) {
        Scene s = load_json(std::string(R"({"lights": [)") + c.light + "]}");
        EXPECT_TRUE(s.delta_lights.empty()) << c.light;
        ASSERT_GE(s.warnings.size(), 1u) << c.light;
        EXPECT_NE(s.warnings[0].find(std::string("/lights/0: the ")), std::string::npos) << s.warnings[0];
        EXPECT_NE(s.warnings[0].find(std::string("emits nothing (") + c.why + "); it is ignored"), std::string::npos)
            << s.warnings[0];
    }
}

// The error's pointer and message for a scene whose `lights` array holds `light`.
void expect_error(const std::string& light, const std::string& pointer, const std::string& message) {
    SceneError e = load_error(R"({"lights": [)" + light + "]}");
    EXPECT_EQ(e.where().json_pointer, pointer) << light;
    EXPECT_EQ(e.message(), message) << light;
}

TEST(SceneLoaderDeltaLights, BadValuesAreLocated) {
    expect_error(R"({"type": "point"})", "/lights/0", "missing required key \"position\"");
    expect_error(R"({"type": "point", "position": [0, 0, 0], "intensity": -1})", "/lights/0/intensity",
                 "expected a number >= 0, got -1");
    expect_error(R"({"type": "point", "position": [0, 0, 0], "power": -5})", "/lights/0/power",
                 "expected a number >= 0, got -5");
    expect_error(R"({"type": "point", "position": [0, 0, 0], "scale": -1})", "/lights/0/scale",
                 "expected a number >= 0, got -1");
    expect_error(R"({"type": "point", "position": [0, 0, 0], "look_at": [0, 0, 1]})", "/lights/0",
                 "unknown key \"look_at\"; expected one of: intensity, position, power, scale, type");
    expect_error(R"({"type": "spot", "position": [1, 2, 3], "look_at": [1, 2, 3]})", "/lights/0/look_at",
                 "look_at equals position [1, 2, 3]; the spot light has no direction");
    expect_error(R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, 1], "cone_angle": 0})",
                 "/lights/0/cone_angle", "expected a number in (0, 180], got 0");
    expect_error(R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, 1], "cone_angle": 200})",
                 "/lights/0/cone_angle", "expected a number in (0, 180], got 200");
    expect_error(R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, 1], "cone_angle": 20,
                     "cone_delta": 25})",
                 "/lights/0/cone_delta",
                 "cone_delta 25 is larger than cone_angle 20: the falloff must lie inside the cone "
                 "(expected a number in [0, 20])");
    expect_error(R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, 1], "cone_delta": -1})",
                 "/lights/0/cone_delta", "expected a number >= 0, got -1");
    expect_error(R"({"type": "directional", "direction": [0, 0, 0]})", "/lights/0/direction",
                 "expected a nonzero direction, got [0, 0, 0]");
    expect_error(R"({"type": "directional", "direction": [0, -1, 0], "position": [0, 0, 0]})", "/lights/0",
                 "unknown key \"position\"; expected one of: direction, irradiance, power, scale, type");
    expect_error(R"({"type": "point", "position": [0, 0, 0], "intensity": 1e30, "scale": 1e30})", "/lights/0/scale",
                 "the light's intensity overflows float range");
    expect_error(R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, 1], "cone_angle": 0.001,
                     "power": 1e38})",
                 "/lights/0/power", "the light's intensity overflows float range");
    expect_error(R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 1e30, "scale": 1e30})",
                 "/lights/0/scale", "the light's irradiance overflows float range");
    expect_error(R"({"type": "sun"})", "/lights/0/type",
                 "unknown light type \"sun\"; expected one of: directional, environment, point, spot");
}

TEST(SceneLoaderDeltaLights, BsdfIntegratorRefusesThem) {
    SceneError e = load_error(R"({"integrator": {"type": "bsdf"},
                                  "lights": [{"type": "environment", "color": 1},
                                             {"type": "spot", "position": [0, 1, 0], "look_at": [0, 0, 0]}]})");
    EXPECT_EQ(e.where().json_pointer, "/integrator/type");
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().column, 25);  // the "bsdf"
    EXPECT_EQ(e.message(),
              "the bsdf integrator finds light only by hitting it, so it cannot see the spot light at "
              "/lights/1 (point, spot and directional lights have no area); use path or whitted, or an area "
              "light (a shape with emission)");
    // path and whitted see them; a dark one, left out, is no reason to refuse.
    for (const char* type : {"path", "whitted"})
        EXPECT_EQ(load_json(std::string(R"({"integrator": {"type": ")") + type +
                            R"("}, "lights": [{"type": "point", "position": [0, 1, 0]}]})")
                      .delta_lights.size(),
                  1u);
    EXPECT_TRUE(load_json(R"({"integrator": {"type": "bsdf"},
                              "lights": [{"type": "point", "position": [0, 1, 0], "scale": 0}]})")
                    .delta_lights.empty());
}

}  // namespace
}  // namespace candela
