// Lights whose colour is a spectrum (docs/SCENE_FORMAT.md, "Spectra"; formats/json/scene_spectra.h
// read_light_spectrum): a shape's `emission` (with `emission_scale`) and a point, spot or
// directional light's `intensity` / `irradiance` (with `scale` and `power`). As pbrt-v4 does, the
// spectrum is normalized to luminance 1 and the light's scale and power apply to it as to an RGB
// colour; RGB mode gets the spectrum's colour at luminance 1 (emission_rgb) times the same factors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/named_spectra.h"
#include "candela/spectrum/spectrum_rgb.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene whose one shape, a sphere of material "m", has the extra keys `keys` (",
// \"emission\": ..." and so on).
Scene sphere_with(const std::string& keys) {
    return load_json(R"({"materials": {"m": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m")" + keys + "}]}");
}
SceneError sphere_error(const std::string& keys) {
    return load_error(R"({"materials": {"m": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m")" + keys + "}]}");
}

// `s` divided by its luminance, in the loader's arithmetic (a float scale of 1 / Y).
DenseSpectrum normalized(const DenseSpectrum& s) {
    DenseSpectrum n = s;
    n *= float(1.0 / spectrum_to_xyz(s).y);
    return n;
}

bool has_warning(const Scene& s, const std::string& part) {
    for (const std::string& w : s.warnings)
        if (w.find(part) != std::string::npos) return true;
    ADD_FAILURE() << "no warning contains: " << part;
    return false;
}

void expect_rgb_near(const Rgb& a, const Rgb& b, float tolerance) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

// ---- shape emission

TEST(SceneLightSpectra, BlackbodyEmissionIsNormalizedToLuminanceOne) {
    const Scene s = sphere_with(R"(, "emission": {"blackbody": 2856})");
    const Shape& shape = s.shapes.at(0);
    const DenseSpectrum bb = blackbody_spectrum(2856.0f);
    // RGB mode: the blackbody's colour at luminance 1 (every channel in gamut at 2856 K).
    EXPECT_EQ(shape.emission, emission_rgb(bb));
    EXPECT_NEAR(linear_srgb_to_xyz(shape.emission).y, 1.0, 1e-6);
    // Spectral mode: the spectrum itself, scaled to Y = 1.
    ASSERT_NE(shape.emission_spectrum, kNoSpectrum);
    const DenseSpectrum& loaded = s.textures.spectrum(shape.emission_spectrum);
    EXPECT_EQ(loaded.v, normalized(bb).v);
    EXPECT_NEAR(spectrum_to_xyz(loaded).y, 1.0, 1e-6);
}

TEST(SceneLightSpectra, D65EmissionIsWhite) {
    const Shape shape = sphere_with(R"(, "emission": {"spectrum": "stdillum-D65"})").shapes.at(0);
    // D65 is the sRGB white: RGB (1, 1, 1) up to the rounding of the XYZ-to-RGB matrix.
    expect_rgb_near(shape.emission, Rgb(1.0f), 1e-5f);
}

TEST(SceneLightSpectra, EmissionScaleMultipliesBothModes) {
    const Scene s = sphere_with(R"(, "emission": {"spectrum": "stdillum-A"}, "emission_scale": 5)");
    const Shape& shape = s.shapes.at(0);
    const DenseSpectrum& a = *named_spectrum("stdillum-A");
    EXPECT_EQ(shape.emission, emission_rgb(a) * 5.0f);
    DenseSpectrum expected = normalized(a);
    expected *= 5.0f;
    ASSERT_NE(shape.emission_spectrum, kNoSpectrum);
    EXPECT_EQ(s.textures.spectrum(shape.emission_spectrum).v, expected.v);
    // On an RGB emission too, as pbrt-v4's `scale` on an area light's L.
    EXPECT_EQ(sphere_with(R"(, "emission": [1, 2, 3], "emission_scale": 0.5)").shapes.at(0).emission,
              Rgb(0.5f, 1.0f, 1.5f));
}

TEST(SceneLightSpectra, RgbEmissionKeepsNoSpectrum) {
    const Scene s = sphere_with(R"(, "emission": [4, 3, 2])");
    EXPECT_EQ(s.shapes.at(0).emission, Rgb(4.0f, 3.0f, 2.0f));
    EXPECT_EQ(s.shapes.at(0).emission_spectrum, kNoSpectrum);
    EXPECT_EQ(s.textures.spectrum_count(), 0u);
}

// A spectrum far outside the sRGB gamut (a narrow line in the blue) has negative channels in
// linear sRGB: RGB mode clips them to 0, spectral mode keeps the spectrum.
TEST(SceneLightSpectra, OutOfGamutEmissionIsClippedInRgbMode) {
    const Scene s = sphere_with(R"(, "emission": {"spectrum": [440, 0, 450, 1, 460, 0]})");
    const Shape& shape = s.shapes.at(0);
    const Rgb unclipped = emission_rgb(s.textures.spectrum(shape.emission_spectrum));
    ASSERT_LT(unclipped.g, 0.0f);
    EXPECT_EQ(shape.emission, Rgb(unclipped.r, 0.0f, unclipped.b));
}

TEST(SceneLightSpectra, DarkSpectrumWarnsAsEmissionZero) {
    const Scene s = sphere_with(R"(, "emission": {"spectrum": [400, 0, 700, 0]})");
    EXPECT_TRUE(s.shapes.at(0).emission.is_black());
    EXPECT_EQ(s.shapes.at(0).emission_spectrum, kNoSpectrum);
    EXPECT_TRUE(has_warning(s, "/shapes/0/emission: emission 0: the shape is not a light"));
}

TEST(SceneLightSpectra, EmissionErrorsAreLocated) {
    SceneError negative = sphere_error(R"(, "emission": {"spectrum": [400, -0.5, 700, 1]})");
    EXPECT_EQ(negative.where().json_pointer, "/shapes/0/emission");
    EXPECT_EQ(negative.message(), "a light's spectrum must be >= 0 at every wavelength, got -0.5");
    SceneError zero_scale = sphere_error(R"(, "emission": 1, "emission_scale": 0)");
    EXPECT_EQ(zero_scale.where().json_pointer, "/shapes/0/emission_scale");
    EXPECT_EQ(zero_scale.message(), "expected a number > 0, got 0");
    SceneError alone = sphere_error(R"(, "emission_scale": 2)");
    EXPECT_EQ(alone.where().json_pointer, "/shapes/0/emission_scale");
    EXPECT_EQ(alone.message(), "emission_scale without emission: the shape is not a light");
    SceneError overflow = sphere_error(R"(, "emission": 1e30, "emission_scale": 1e30)");
    EXPECT_EQ(overflow.where().json_pointer, "/shapes/0/emission_scale");
    // A spectrum's own keys are all it takes: a scale belongs to the shape.
    SceneError inner = sphere_error(R"(, "emission": {"blackbody": 3000, "scale": 2})");
    EXPECT_EQ(inner.where().json_pointer, "/shapes/0/emission");
    EXPECT_NE(inner.message().find("unknown key \"scale\""), std::string::npos) << inner.message();
}

TEST(SceneLightSpectra, SpectralEmitterCannotBeCutOut) {
    SceneError e = load_error(R"({"materials": {"leaf": {"type": "diffuse", "alpha": 0.5}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "leaf",
                    "emission": {"blackbody": 5000}}]})");
    EXPECT_EQ(e.where().json_pointer, "/shapes/0/emission");
    EXPECT_EQ(e.message(), "a light cannot be cut out: its material \"leaf\" has alpha < 1");
}

// ---- point, spot and directional lights

// The scene of the one light `light`, which must load as one delta light.
Scene light_scene(const std::string& light) {
    Scene s = load_json(R"({"lights": [)" + light + "]}");
    EXPECT_EQ(s.delta_lights.size(), 1u);
    return s;
}

// pbrt-v4's PointLight: I / SpectrumToPhotometric(I) x scale x power / (4 pi). RGB mode's
// intensity is the same factor times the spectrum's luminance-1 colour, so both modes emit the
// same luminance.
TEST(SceneLightSpectra, PointLightSpectrumScaleAndPower) {
    const Scene s = light_scene(
        R"({"type": "point", "position": [0, 0, 0], "intensity": {"blackbody": 3000}, "scale": 2, "power": 100})");
    ASSERT_EQ(s.delta_lights.size(), 1u);
    const DeltaLightSettings& settings = s.delta_lights[0];
    const auto* point = std::get_if<PointLight>(&settings.light);
    ASSERT_NE(point, nullptr);
    const float factor = 100.0f / PointLight::power_per_intensity();
    EXPECT_EQ(settings.spectrum_scale, 2.0f * factor);
    const Rgb rgb = emission_rgb(blackbody_spectrum(3000.0f));
    EXPECT_EQ(point->intensity, from_rgb(rgb) * 2.0f * factor);
    ASSERT_NE(settings.spectrum, kNoSpectrum);
    EXPECT_EQ(s.textures.spectrum(settings.spectrum).v, normalized(blackbody_spectrum(3000.0f)).v);
}

TEST(SceneLightSpectra, SpotLightSpectrumPower) {
    const Scene s = light_scene(
        R"({"type": "spot", "position": [0, 0, 0], "look_at": [0, 0, -1], "intensity": {"blackbody": 3000},
            "power": 10})");
    ASSERT_EQ(s.delta_lights.size(), 1u);
    const DeltaLightSettings& settings = s.delta_lights[0];
    const auto* spot = std::get_if<SpotLight>(&settings.light);
    ASSERT_NE(spot, nullptr);
    const float factor = 10.0f / SpotLight::power_per_intensity(spot->cos_falloff_start, spot->cos_falloff_end);
    EXPECT_EQ(settings.spectrum_scale, factor);
    EXPECT_EQ(spot->intensity, from_rgb(emission_rgb(blackbody_spectrum(3000.0f))) * factor);
}

// A directional light's power needs the scene's size: spectrum_scale holds only `scale`, and
// build_light_set multiplies both modes by power / (pi r^2).
TEST(SceneLightSpectra, DirectionalLightSpectrumWaitsForThePower) {
    const Scene s = light_scene(
        R"({"type": "directional", "direction": [0, 0, -1], "irradiance": {"blackbody": 3000}, "scale": 3,
            "power": 7})");
    ASSERT_EQ(s.delta_lights.size(), 1u);
    const DeltaLightSettings& settings = s.delta_lights[0];
    ASSERT_NE(settings.spectrum, kNoSpectrum);
    const auto* directional = std::get_if<DirectionalLight>(&settings.light);
    ASSERT_NE(directional, nullptr);
    EXPECT_EQ(settings.spectrum_scale, 3.0f);
    EXPECT_EQ(settings.directional_power, 7.0f);
    EXPECT_EQ(directional->irradiance, from_rgb(emission_rgb(blackbody_spectrum(3000.0f))) * 3.0f);
}

TEST(SceneLightSpectra, RgbDeltaLightKeepsNoSpectrum) {
    const Scene s = light_scene(R"({"type": "point", "position": [0, 0, 0], "intensity": 2, "power": 5})");
    ASSERT_EQ(s.delta_lights.size(), 1u);
    EXPECT_EQ(s.delta_lights[0].spectrum, kNoSpectrum);
    EXPECT_EQ(s.textures.spectrum_count(), 0u);
}

TEST(SceneLightSpectra, DarkOrNegativeDeltaLightSpectrum) {
    Scene dark = load_json(
        R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": {"spectrum": [400, 0, 700, 0]}}]})");
    EXPECT_TRUE(dark.delta_lights.empty());
    EXPECT_TRUE(has_warning(dark, "/lights/0: the point light emits nothing (its intensity is 0)"));
    SceneError negative = load_error(
        R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": {"spectrum": [400, -1, 700, 1]}}]})");
    EXPECT_EQ(negative.where().json_pointer, "/lights/0/intensity");
    EXPECT_EQ(negative.message(), "a light's spectrum must be >= 0 at every wavelength, got -1");
}

}  // namespace
}  // namespace candela
