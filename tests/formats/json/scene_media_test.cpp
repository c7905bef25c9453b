// The scene file's `media`, the camera's and shapes' media and the `interface` material: each
// key changes the loaded scene as pbrt-v4's MakeNamedMedium would, and bad values are located
// errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// The one medium of a scene whose `media` holds "m": `medium`.
HomogeneousMedium only_homogeneous(const std::string& medium) {
    Scene s = load_json(R"({"media": {"m": )" + medium + "}}");
    EXPECT_EQ(s.media.size(), 1u);
    const HomogeneousMedium* h = s.media.empty() ? nullptr : std::get_if<HomogeneousMedium>(&s.media[0]);
    EXPECT_NE(h, nullptr);
    return h ? *h : HomogeneousMedium{};
}

TEST(SceneLoaderMedia, HomogeneousDefaultsAreOnesAsPbrtV4s) {
    const HomogeneousMedium m = only_homogeneous(R"({"type": "homogeneous"})");
    EXPECT_EQ(m.sigma_a.rgb, Rgb(1.0f));
    EXPECT_EQ(m.sigma_s.rgb, Rgb(1.0f));
    EXPECT_FALSE(m.emissive);
    EXPECT_EQ(m.g, 0.0f);
    // Grey 1 is the constant spectrum 1 at every wavelength (pbrt-v4's RGBUnboundedSpectrum).
    for (float v : m.sigma_s.spectrum.v) EXPECT_NEAR(v, 1.0f, 1e-5f);
}

TEST(SceneLoaderMedia, ScaleMultipliesBothCoefficientsAndGIsKept) {
    const HomogeneousMedium m =
        only_homogeneous(R"({"type": "homogeneous", "sigma_a": [0.1, 0.2, 0.4], "sigma_s": 2, "scale": 10, "g": -0.4})");
    EXPECT_NEAR(m.sigma_a.rgb.r, 1.0f, 1e-6f);
    EXPECT_NEAR(m.sigma_a.rgb.b, 4.0f, 1e-6f);
    EXPECT_NEAR(m.sigma_s.rgb.g, 20.0f, 1e-5f);
    EXPECT_NEAR(m.sigma_s.spectrum(550.0f), 20.0f, 1e-4f);
    EXPECT_EQ(m.g, -0.4f);
    // The spectrum of a chromatic coefficient follows its colour: more at the blue end.
    EXPECT_GT(m.sigma_a.spectrum(450.0f), m.sigma_a.spectrum(650.0f));
}

TEST(SceneLoaderMedia, SpectrumCoefficientsAreUsedAsTheyAre) {
    const HomogeneousMedium m = only_homogeneous(R"({"type": "homogeneous", "sigma_a": {"spectrum": [400, 1, 700, 3]}})");
    EXPECT_NEAR(m.sigma_a.spectrum(400.0f), 1.0f, 1e-5f);
    EXPECT_NEAR(m.sigma_a.spectrum(550.0f), 2.0f, 1e-5f);
    EXPECT_GT(m.sigma_a.rgb.r, m.sigma_a.rgb.b);
}

TEST(SceneLoaderMedia, PresetsAreMeasuredCoefficients) {
    const HomogeneousMedium m = only_homogeneous(R"({"type": "homogeneous", "preset": "Wholemilk", "scale": 2})");
    // Jensen et al. 2001 via pbrt-v4: sigma_s' (2.55, 3.21, 3.77), sigma_a (0.0011, 0.0024, 0.014), per mm.
    EXPECT_NEAR(m.sigma_s.rgb.r, 5.10f, 1e-5f);
    EXPECT_NEAR(m.sigma_a.rgb.b, 0.028f, 1e-7f);
}

TEST(SceneLoaderMedia, EmissionIsNormalizedAsAnAreaLightsAndScaled) {
    const HomogeneousMedium rgb = only_homogeneous(R"({"type": "homogeneous", "Le": [1, 2, 3], "Le_scale": 2})");
    EXPECT_TRUE(rgb.emissive);
    EXPECT_EQ(rgb.Le.rgb, Rgb(2.0f, 4.0f, 6.0f));
    const HomogeneousMedium bb = only_homogeneous(R"({"type": "homogeneous", "Le": {"blackbody": 3000}})");
    EXPECT_TRUE(bb.emissive);
    // Normalized to luminance 1: its RGB's luminance is 1.
    EXPECT_NEAR(0.2126f * bb.Le.rgb.r + 0.7152f * bb.Le.rgb.g + 0.0722f * bb.Le.rgb.b, 1.0f, 0.01f);
    EXPECT_FALSE(only_homogeneous(R"({"type": "homogeneous", "Le": 0})").emissive);
}

TEST(SceneLoaderMedia, CameraAndShapesNameTheirMedia) {
    Scene s = load_json(R"({"media": {"fog": {"type": "homogeneous"}, "ink": {"type": "homogeneous", "sigma_s": 0}},
                            "camera": {"medium": "fog"},
                            "materials": {"glass": {"type": "dielectric"}, "b": {"type": "interface"}},
                            "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass",
                                        "interior": "ink", "exterior": "fog"},
                                       {"type": "sphere", "center": [3, 0, 0], "radius": 1, "material": "b",
                                        "interior": "ink", "exterior": ""},
                                       {"type": "sphere", "center": [6, 0, 0], "radius": 1, "material": "glass"}]})");
    EXPECT_EQ(s.camera_medium, 0u);
    EXPECT_EQ(s.shapes[0].interior, 1u);
    EXPECT_EQ(s.shapes[0].exterior, 0u);
    EXPECT_TRUE(s.shapes[0].is_medium_boundary());
    EXPECT_EQ(s.shapes[1].exterior, kNoMedium);
    EXPECT_TRUE(s.materials[1].interface);
    EXPECT_FALSE(s.materials[0].interface);
    EXPECT_FALSE(s.shapes[2].is_medium_boundary());
    EXPECT_EQ(load_json("{}").camera_medium, kNoMedium);
}

TEST(SceneLoaderMedia, IntegratorsThatIgnoreMediaAreWarnedAbout) {
    const std::string scene = R"({"media": {"fog": {"type": "homogeneous"}}, "camera": {"medium": "fog"},
                                  "lights": [{"type": "environment", "color": 1}], "integrator": {"type": ")";
    const Scene path = load_json(scene + R"(path"}})");
    ASSERT_EQ(path.warnings.size(), 1u);
    EXPECT_NE(path.warnings[0].find("the path integrator ignores them"), std::string::npos) << path.warnings[0];
    EXPECT_TRUE(load_json(scene + R"(volpath"}})").warnings.empty());
}

void expect_error(const std::string& json, const std::string& pointer, const std::string& message) {
    SceneError e = load_error(json);
    EXPECT_EQ(e.where().json_pointer, pointer) << json;
    EXPECT_EQ(e.message(), message) << json;
}

TEST(SceneLoaderMedia, BadValuesAreLocated) {
    expect_error(R"({"media": {"m": {"type": "homogeneous", "sigma_a": -1}}})", "/media/m/sigma_a",
                 "expected a number >= 0, got -1");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "sigma_s": [1, -2, 3]}}})", "/media/m/sigma_s/1",
                 "expected a number >= 0, got -2");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "sigma_s": {"spectrum": [400, 1, 700, -1]}}}})",
                 "/media/m/sigma_s",
                 "a medium's coefficient must be finite and >= 0 at every wavelength; it is -0.0066666603 at 551 nm");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "g": 1.5}}})", "/media/m/g",
                 "expected a number in [-1, 1], got 1.5");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "preset": "Milk"}}})", "/media/m/preset",
                 "unknown medium preset \"Milk\"; the presets are Apple, Apple Juice, Budweiser Beer, Cappuccino "
                 "Powder, Chardonnay, Chicken1, Chicken2, Clorox, Coke, Coors Light Beer, Cranberry Juice, Cream, "
                 "Espresso, Gatorade, Grape Juice, Head & Shoulders Shampoo, Ketchup, Lemon Tea Powder, Lowfat "
                 "Chocolate Milk, Lowfat Milk, Lowfat Soy Milk, Marble, Merlot, Mint Mocha Coffee, Orange Powder, "
                 "Pepsi, Pink Lemonade Powder, Potato, Reduced Milk, Regular Chocolate Milk, Regular Milk, Regular "
                 "Soy Milk, Ruby Grapefruit Juice, Salt Powder, Shampoo, Skimmilk, Skin1, Skin2, Spectralon, "
                 "Sprite, Strawberry Shampoo, Sugar Powder, Suisse Mocha Powder, White Grapefruit Juice, White "
                 "Zinfandel, Wholemilk");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "preset": "Apple", "sigma_a": 1}}})", "/media/m",
                 "give \"preset\" or \"sigma_a\", not both");
    expect_error(R"({"media": {"m": {"type": "fog"}}})", "/media/m/type",
                 "unknown medium type \"fog\"; expected one of: cloud, homogeneous, nanovdb, openvdb, rgbgrid, uniformgrid");
    expect_error(R"({"media": {"m": {"type": "homogeneous", "density": 1}}})", "/media/m",
                 "unknown key \"density\"; expected one of: Le, Le_scale, g, preset, scale, sigma_a, sigma_s, "
                 "transform, type");
    expect_error(R"({"media": {"m": {"type": "homogeneous"}}, "camera": {"medium": "smoke"}})", "/camera/medium",
                 "unknown medium \"smoke\"; defined media: m");
    expect_error(R"({"camera": {"medium": "smoke"}})", "/camera/medium",
                 "unknown medium \"smoke\"; no media are defined");
    expect_error(R"({"media": {"m": {"type": "homogeneous"}}, "materials": {"w": {"type": "diffuse"}},
                     "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "w",
                                 "interior": "n"}]})",
                 "/shapes/0/interior", "unknown medium \"n\"; defined media: m");
    expect_error(R"({"materials": {"b": {"type": "interface", "alpha": 0.5}}})", "/materials/b",
                 "unknown key \"alpha\"; expected one of: type");
}

}  // namespace
}  // namespace candela
