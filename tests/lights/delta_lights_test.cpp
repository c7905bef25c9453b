// Point, spot and directional lights (pbrt-v4's PointLight, SpotLight, DistantLight): what one
// sample gives a reference point, the spot's smoothstep falloff, their power against its
// definition, and their place in the LightSet: chosen by power (or uniformly) together with area
// lights and the environment, sampled with the selection probability as their pdf and marked
// is_delta.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "candela/lights/delta_light.h"
#include "candela/lights/light_set.h"
#include "lights/light_test_scene.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

const Vec3f kOrigin{0.0f, 0.0f, 0.0f};

TEST(PointLight, IrradianceFallsWithTheSquareOfTheDistance) {
    PointLight light{{1.0f, 2.0f, 2.0f}, Color(9.0f, 18.0f, 27.0f)};
    std::optional<DeltaLightSample> s = light.sample(kOrigin);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->p, light.position);
    EXPECT_NEAR(s->wi.x, 1.0f / 3.0f, 1e-7f);
    EXPECT_NEAR(s->wi.y, 2.0f / 3.0f, 1e-7f);
    EXPECT_NEAR(s->wi.z, 2.0f / 3.0f, 1e-7f);
    EXPECT_FALSE(s->infinite);
    EXPECT_FLOAT_EQ(s->Li[0], 1.0f);  // I / r^2, r = 3
    EXPECT_FLOAT_EQ(s->Li[1], 2.0f);
    EXPECT_FLOAT_EQ(s->Li[2], 3.0f);
    EXPECT_FALSE(light.sample(light.position));  // no direction from the light itself
    EXPECT_FLOAT_EQ(light.power(1.0f), 4.0f * kPi * Rgb(9.0f, 18.0f, 27.0f).luminance());
}

// A spot at the origin pointing down +z with cone_angle 40 and cone_delta 15 degrees.
SpotLight spot_40_15(Color intensity = Color(2.0f)) {
    SpotLight light;
    light.position = kOrigin;
    light.axis = {0.0f, 0.0f, 1.0f};
    light.intensity = intensity;
    light.cos_falloff_start = std::cos(radians(25.0f));
    light.cos_falloff_end = std::cos(radians(40.0f));
    return light;
}

// The point at angle `degrees` from +z (towards +x) at distance r from the origin.
Vec3f at_angle(float degrees, float r) {
    return Vec3f(std::sin(radians(degrees)), 0.0f, std::cos(radians(degrees))) * r;
}

TEST(SpotLight, FallsOffAsTheSmoothstepOfTheCosine) {
    const SpotLight light = spot_40_15();
    const float cs = light.cos_falloff_start, ce = light.cos_falloff_end;
    EXPECT_EQ(light.falloff(1.0f), 1.0f);
    EXPECT_EQ(light.falloff(cs), 1.0f);
    EXPECT_EQ(light.falloff(ce), 0.0f);
    EXPECT_EQ(light.falloff(-1.0f), 0.0f);
    // t = (cos - cos_end) / (cos_start - cos_end); s(t) = t^2 (3 - 2 t).
    for (float t : {0.1f, 0.25f, 0.5f, 0.8f}) {
        float expected = t * t * (3.0f - 2.0f * t);
        EXPECT_NEAR(light.falloff(ce + t * (cs - ce)), expected, 1e-5f) << "t = " << t;
    }
    // Through sample(): I s(t) / r^2 at distance 2, none outside the cone.
    for (float degrees : {0.0f, 10.0f, 25.0f, 30.0f, 35.0f, 39.0f}) {
        std::optional<DeltaLightSample> s = light.sample(at_angle(degrees, 2.0f));
        ASSERT_TRUE(s) << degrees;
        float t = (std::cos(radians(degrees)) - ce) / (cs - ce);
        float expected = 2.0f * (t >= 1.0f ? 1.0f : t * t * (3.0f - 2.0f * t)) / 4.0f;
        EXPECT_NEAR(s->Li[1], expected, 2e-6f) << degrees << " degrees";
        EXPECT_NEAR(dot(s->wi, -normalize(at_angle(degrees, 1.0f))), 1.0f, 1e-6f);
    }
    EXPECT_FALSE(light.sample(at_angle(40.5f, 2.0f)));
    EXPECT_FALSE(light.sample(at_angle(120.0f, 2.0f)));
}

TEST(SpotLight, HardEdgeWithoutFalloff) {
    SpotLight light = spot_40_15();
    light.cos_falloff_start = light.cos_falloff_end;  // cone_delta 0
    EXPECT_TRUE(light.sample(at_angle(39.9f, 1.0f)));
    EXPECT_EQ(light.sample(at_angle(39.9f, 1.0f))->Li, Color(2.0f));
    EXPECT_FALSE(light.sample(at_angle(40.1f, 1.0f)));
}

TEST(SpotLight, PowerIsTheIntensityIntegratedOverTheSphere) {
    // pbrt-v4's closed form 2 pi ((1 - cos_start) + (cos_start - cos_end) / 2) against the
    // falloff integrated numerically: dω = dφ d(cos θ), so P = 2 pi ∫ falloff(c) dc.
    for (auto [angle, delta] : {std::pair{40.0f, 15.0f}, std::pair{30.0f, 30.0f}, std::pair{90.0f, 5.0f},
                                std::pair{170.0f, 60.0f}, std::pair{10.0f, 0.0f}}) {
        SpotLight light = spot_40_15(Color(1.0f));
        light.cos_falloff_start = std::cos(radians(angle - delta));
        light.cos_falloff_end = std::cos(radians(angle));
        constexpr int kSteps = 200000;
        double integral = 0.0;
        for (int i = 0; i < kSteps; ++i) {
            double c = -1.0 + 2.0 * (i + 0.5) / kSteps;
            integral += static_cast<double>(light.falloff(static_cast<float>(c))) * 2.0 / kSteps;
        }
        // The midpoint rule misplaces a hard edge by up to one step (2 / kSteps in cos theta);
        // a smooth falloff it integrates far more closely. Float cosines add about 1e-6.
        const double tolerance = (delta > 0.0f ? 1e-5 : 2.0 / kSteps / integral) + 1e-5;
        EXPECT_NEAR(static_cast<double>(light.power(1.0f)) / (2.0 * kPiD * integral), 1.0, tolerance)
            << "cone " << angle << ", delta " << delta;
    }
}

TEST(DirectionalLight, ArrivesFromAgainstItsDirectionFromInfinitelyFar) {
    DirectionalLight light{normalize(Vec3f(1.0f, -2.0f, 2.0f)), Color(0.5f, 1.0f, 1.5f)};
    for (Vec3f ref : {kOrigin, Vec3f(100.0f, -3.0f, 7.0f)}) {
        std::optional<DeltaLightSample> s = light.sample(ref);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->wi, -light.direction);
        EXPECT_TRUE(s->infinite);
        EXPECT_EQ(s->Li, light.irradiance);  // the same at any distance
        EXPECT_EQ(s->p, ref - light.direction);
    }
    // Power: E over the disk of the scene's bounding sphere, pi r^2 E.
    EXPECT_FLOAT_EQ(light.power(2.0f), kPi * 4.0f * Rgb(0.5f, 1.0f, 1.5f).luminance());
}

// A quad light (area 1, radiance 2), a constant environment of radiance 0.5, and a point, a spot
// and a directional light, in a scene of bounding radius 2.
struct MixedLights {
    LightTestScene scene;
    Image sky{1, 1};
    double powers[5] = {};  // quad, environment, point, spot, directional

    MixedLights() {
        scene.add_mesh(make_quad({-0.5f, -0.5f, 2.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}), Rgb(2.0f));
        scene.add_delta_light(PointLight{{0.0f, 3.0f, 0.0f}, Color(1.0f)});
        SpotLight spot = spot_40_15(Color(3.0f));
        spot.position = {0.0f, -3.0f, 0.0f};
        spot.axis = {0.0f, 1.0f, 0.0f};
        scene.add_delta_light(spot);
        scene.add_delta_light(DirectionalLight{{0.0f, 0.0f, -1.0f}, Color(0.25f)});
        sky.at(0, 0) = Rgb(0.5f);
        const double cs = std::cos(kPiD * 25.0 / 180.0), ce = std::cos(kPiD * 40.0 / 180.0);
        powers[0] = kPiD * 1.0 * 2.0;
        powers[1] = kPiD * 4.0 * 0.5;
        powers[2] = 4.0 * kPiD;
        powers[3] = 3.0 * 2.0 * kPiD * ((1.0 - cs) + (cs - ce) / 2.0);
        powers[4] = kPiD * 4.0 * 0.25;
    }
    LightSet light_set(LightSelection selection) const {
        return scene.light_set(selection, EnvironmentLight(sky, 1.0f, Transform(), EnvironmentSampling::kUniform), 2.0f);
    }
};

// Which of MixedLights' lights a sample came from.
int light_of(const LightSample& s) {
    if (!s.is_delta) return s.infinite ? 1 : 0;
    if (s.infinite) return 4;
    return s.p.y > 0.0f ? 2 : 3;
}

void expect_selection(const MixedLights& mixed, LightSelection selection) {
    const LightSet lights = mixed.light_set(selection);
    ASSERT_EQ(lights.size(), 5u);
    EXPECT_TRUE(lights.uses_choice());
    EXPECT_TRUE(lights.has_delta_lights());
    double total = 0.0;
    double expected[5];
    for (int i = 0; i < 5; ++i) total += selection == LightSelection::kPower ? mixed.powers[i] : 1.0;
    for (int i = 0; i < 5; ++i) expected[i] = (selection == LightSelection::kPower ? mixed.powers[i] : 1.0) / total;
    // Choice numbers on a fine grid: each light is picked for a share of them equal to its
    // probability (to the grid's resolution).
    constexpr int kChoices = 100000;
    int counts[5] = {};
    const Vec3f ref(0.0f, 0.0f, 0.5f);  // sees the quad's front, the point and the spot's cone
    for (int i = 0; i < kChoices; ++i) {
        const float uc = (static_cast<float>(i) + 0.5f) / kChoices;
        std::optional<LightSample> s = lights.sample(ref, uc, {0.3f, 0.7f});
        ASSERT_TRUE(s) << "uc " << uc;
        const int light = light_of(*s);
        ++counts[light];
        const double probability = expected[light];
        if (s->is_delta) {
            // Certain given the light: the pdf is the selection probability alone.
            EXPECT_NEAR(static_cast<double>(s->pdf) / probability, 1.0, 1e-6);
        } else if (!s->infinite) {
            EXPECT_EQ(lights.pdf(ref, 0, s->p, s->n), s->pdf);
            EXPECT_NEAR(static_cast<double>(lights.selection_probability(0)) / probability, 1.0, 1e-6);
        } else {
            EXPECT_NEAR(static_cast<double>(lights.environment_pdf(s->wi)) / (probability / (4.0 * kPiD)), 1.0, 1e-6);
        }
    }
    for (int i = 0; i < 5; ++i)
        EXPECT_NEAR(counts[i] / static_cast<double>(kChoices), expected[i], 2.0 / kChoices) << "light " << i;
}

TEST(LightSetDeltaLights, ChosenByPowerWithAreaLightsAndTheEnvironment) {
    expect_selection(MixedLights(), LightSelection::kPower);
}

TEST(LightSetDeltaLights, ChosenUniformlyWithAreaLightsAndTheEnvironment) {
    expect_selection(MixedLights(), LightSelection::kUniform);
}

TEST(LightSetDeltaLights, SamplesCarryTheLightsIrradiance) {
    LightTestScene scene;
    scene.add_delta_light(SpotLight{{0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}, Color(8.0f), 0.9f, 0.8f});
    const LightSet lights = scene.light_set();
    EXPECT_FALSE(lights.uses_choice());  // one light
    std::optional<LightSample> s = lights.sample(kOrigin, 0.7f, {0.1f, 0.2f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta);
    EXPECT_FALSE(s->infinite);
    EXPECT_EQ(s->pdf, 1.0f);
    EXPECT_EQ(s->Le, Color(2.0f));  // 8 / 2^2 on the axis
    EXPECT_EQ(s->p, Vec3f(0.0f, 0.0f, 2.0f));
    EXPECT_EQ(s->wi, Vec3f(0.0f, 0.0f, 1.0f));
    // Outside the cone nothing arrives, and there is nothing to sample.
    EXPECT_FALSE(lights.sample({5.0f, 0.0f, 0.0f}, 0.7f, {0.1f, 0.2f}));
    // No shape is a delta light: hits never find one.
    EXPECT_EQ(lights.selection_probability(0), 0.0f);
}

TEST(LightSetDeltaLights, LightsOfZeroPowerAreLeftOut) {
    LightTestScene scene;
    scene.add_delta_light(PointLight{kOrigin, Color(0.0f)});
    scene.add_delta_light(DirectionalLight{{0.0f, -1.0f, 0.0f}, Color(0.0f)});
    EXPECT_TRUE(scene.light_set().empty());
    EXPECT_FALSE(scene.light_set().has_delta_lights());
    scene.add_delta_light(PointLight{kOrigin, Color(1.0f)});
    EXPECT_EQ(scene.light_set().size(), 1u);
}

}  // namespace
}  // namespace candela::test
