// Spectral mode against RGB mode. Where every colour of a scene is grey (reflectances constant
// over wavelength, lights white) the two modes compute the same expectation, pixel by pixel: a
// grey reflectance is exactly a constant spectrum and a white light is D65, which the sensor maps
// to RGB (1, 1, 1). z-tests on the difference of two independent renders check it, and the same
// test on a Cornell box with saturated walls, where the modes differ (the reason the spectral
// mode exists), must reject.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 32;
constexpr int kBlock = 8;

// The Cornell box with its mirror and glass spheres, every colour replaced by a grey.
Scene grey_scene(int spp) {
    Scene s = test::cornell_glass_scene(kSize, kSize, spp);
    s.materials[test::kCornellWhite] = make_diffuse(Rgb(0.73f));
    s.materials[test::kCornellRed] = make_diffuse(Rgb(0.4f));
    s.materials[test::kCornellGreen] = make_diffuse(Rgb(0.3f));
    s.materials[test::kCornellMirror] = make_mirror(Rgb(0.95f));
    for (Shape& shape : s.shapes)
        if (!shape.emission.is_black()) shape.emission = Rgb(4.0f);
    return s;
}

// z-tests of every block and the whole image: spectral minus RGB, variances added (the renders
// are independent: other seeds).
test::ZTestFamily compare_modes(Scene scene) {
    scene.integrator.spectral = false;
    const test::RenderMoments rgb = test::render_moments(scene);
    scene.integrator.spectral = true;
    scene.sampler.seed += 1000;
    const test::RenderMoments spectral = test::render_moments(scene);
    EXPECT_EQ(rgb.dropped, 0u);
    EXPECT_EQ(spectral.dropped, 0u);
    return test::compare_blocks_and_whole(spectral, rgb, kBlock);
}

TEST(SpectralMode, GreySceneRendersAsInRgbMode) {
    test::ZTestFamily family = compare_modes(grey_scene(256));
    EXPECT_TRUE(family.passed()) << family.summary();
}

// The control: saturated walls (and a coloured light) do not give RGB mode's image, and this
// test has the power to see it at the same sample count.
TEST(SpectralMode, SaturatedCornellBoxDiffersFromRgbMode) {
    test::ZTestFamily family = compare_modes(test::cornell_box_scene(kSize, kSize, 256));
    EXPECT_FALSE(family.passed()) << family.summary();
}

}  // namespace
}  // namespace candela
