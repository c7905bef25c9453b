// Lights given as spectra render the same in both modes where the scene is grey. RGB mode's light
// is the spectrum's colour at luminance 1 (emission_rgb) and spectral mode's the spectrum at
// luminance 1; with every reflectance constant over wavelength, each pixel is the light's
// spectrum times one grey transport factor, which the sensor (linear in the spectrum) maps to
// that factor times the spectrum's colour: the two modes agree exactly in expectation. The light
// comes from the scene loader (docs/SCENE_FORMAT.md, "Spectra"), so its normalization is tested
// end to end; z-tests on the difference of two independent renders check it (the control that
// this test has the power to see a difference is SpectralMode.SaturatedCornellBoxDiffersFromRgbMode).
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kBlock = 8;
constexpr int kSpp = 256;

// The grey Cornell box of spectral_render_test.cpp, its light's emission `emission` as the scene
// file writes it (with "emission_scale": 4), read by the scene loader.
Scene grey_scene_lit_by(const std::string& emission) {
    const Scene light = load_scene_from_string(
        R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [{"type": "sphere", "center": [0, 0, 0],
            "radius": 1, "material": "m", "emission": )" + emission + R"(, "emission_scale": 4}]})",
        "light.json");
    Scene s = test::cornell_glass_scene(kSize, kSize, kSpp);
    s.materials[test::kCornellWhite] = make_diffuse(Rgb(0.73f));
    s.materials[test::kCornellRed] = make_diffuse(Rgb(0.4f));
    s.materials[test::kCornellGreen] = make_diffuse(Rgb(0.3f));
    s.materials[test::kCornellMirror] = make_mirror(Rgb(0.95f));
    const Shape& emitter = light.shapes.at(0);
    for (Shape& shape : s.shapes) {
        if (shape.emission.is_black()) continue;
        shape.emission = emitter.emission;
        if (emitter.emission_spectrum != kNoSpectrum)
            shape.emission_spectrum = s.textures.add_spectrum(light.textures.spectrum(emitter.emission_spectrum));
    }
    return s;
}

// z-tests of every block and the whole image: `spectral` rendered in spectral mode minus `rgb`
// in RGB mode, variances added (independent renders: other seeds).
test::ZTestFamily compare(Scene rgb, Scene spectral) {
    rgb.integrator.spectral = false;
    spectral.integrator.spectral = true;
    spectral.sampler.seed = rgb.sampler.seed + 1000;
    const test::RenderMoments a_moments = test::render_moments(spectral);
    const test::RenderMoments b_moments = test::render_moments(rgb);
    EXPECT_EQ(a_moments.dropped, 0u);
    EXPECT_EQ(b_moments.dropped, 0u);
    return test::compare_blocks_and_whole(a_moments, b_moments, kBlock);
}

// Illuminant A, a 2856 K blackbody: a warm light whose colour is inside the sRGB gamut.
TEST(SpectralLights, BlackbodyLightRendersAsInRgbMode) {
    const Scene s = grey_scene_lit_by(R"({"blackbody": 2856})");
    // Without its spectrum spectral mode would uplift the RGB colour, which agrees as well.
    int spectral_lights = 0;
    for (const Shape& shape : s.shapes) spectral_lights += shape.emission_spectrum != kNoSpectrum;
    EXPECT_EQ(spectral_lights, 1);
    test::ZTestFamily family = compare(s, s);
    EXPECT_TRUE(family.passed()) << family.summary();
}

// D65 at luminance 1 is the white of RGB (1, 1, 1): a spectral render of it is an RGB render of
// white emission 4.
TEST(SpectralLights, D65LightRendersAsRgbWhite) {
    Scene white = grey_scene_lit_by("1");
    for (const Shape& shape : white.shapes) {
        if (!shape.emission.is_black()) {
            EXPECT_EQ(shape.emission, Rgb(4.0f));
        }
    }
    test::ZTestFamily family = compare(white, grey_scene_lit_by(R"({"spectrum": "stdillum-D65"})"));
    EXPECT_TRUE(family.passed()) << family.summary();
}

}  // namespace
}  // namespace candela
