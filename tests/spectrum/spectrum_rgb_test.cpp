// Spectra reduced to RGB for RGB mode (spectrum/spectrum_rgb.h): a constant reflectance is its
// grey, D65 light is white, and the reductions are linear or scale-free as documented.
#include "candela/spectrum/spectrum_rgb.h"

#include <gtest/gtest.h>

#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/named_spectra.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The XYZ of 1 x D65 is the colour space's white bit for bit (the same float products summed in
// the same order), and rgb_from_xyz times the white is (1, 1, 1) within a few double ulps (the
// matrix and its inverse are each rounded to double): rounded to float, 1 within half a float ulp
// (6e-8). 1e-7 bounds it.
TEST(SpectrumRgb, ConstantOneReflectsWhite) {
    const Rgb c = reflectance_rgb(dense_constant(1.0f));
    EXPECT_NEAR(c.r, 1.0f, 1e-7f);
    EXPECT_NEAR(c.g, 1.0f, 1e-7f);
    EXPECT_NEAR(c.b, 1.0f, 1e-7f);
}

// Linear: a constant 0.25 is grey 0.25 (scaling the spectrum by a power of 2 is exact, so the
// result is a quarter of the white's, within its rounding).
TEST(SpectrumRgb, ConstantReflectanceIsItsGrey) {
    const Rgb c = reflectance_rgb(dense_constant(0.25f));
    EXPECT_NEAR(c.r, 0.25f, 3e-8f);
    EXPECT_NEAR(c.g, 0.25f, 3e-8f);
    EXPECT_NEAR(c.b, 0.25f, 3e-8f);
}

// D65 is the colour space's white, at luminance 1 (named_spectra.h): (1, 1, 1), as for the
// reflectance above; and an emitter's colour does not depend on its brightness.
TEST(SpectrumRgb, D65EmitsWhite) {
    const Rgb c = emission_rgb(*named_spectrum("stdillum-D65"));
    EXPECT_NEAR(c.r, 1.0f, 1e-7f);
    EXPECT_NEAR(c.g, 1.0f, 1e-7f);
    EXPECT_NEAR(c.b, 1.0f, 1e-7f);
    DenseSpectrum brighter = *named_spectrum("stdillum-D65");
    brighter *= 8.0f;
    EXPECT_EQ(emission_rgb(brighter), c);
}

// An emission's luminance is 1: Y of linear sRGB (Rec. 709 weights, rounded to 4 decimals in
// Rgb::luminance) within 1e-4.
TEST(SpectrumRgb, EmissionHasLuminanceOne) {
    for (const char* name : {"stdillum-A", "stdillum-F2", "stdillum-F11"})
        EXPECT_NEAR(emission_rgb(*named_spectrum(name)).luminance(), 1.0f, 1e-4f) << name;
    EXPECT_NEAR(emission_rgb(blackbody_spectrum(3000.0f)).luminance(), 1.0f, 1e-4f);
}

// A 6500 K blackbody is close to D65 but not on the daylight locus (x, y = 0.3135, 0.3237
// against 0.3127, 0.3290): slightly magenta, each channel within 5 % of white. Warmer
// blackbodies are redder, hotter ones bluer.
TEST(SpectrumRgb, BlackbodiesAreNearWhiteAt6500KelvinAndWarmerBelow) {
    const Rgb white = emission_rgb(blackbody_spectrum(6500.0f));
    EXPECT_NEAR(white.r, 1.0f, 0.05f);
    EXPECT_NEAR(white.g, 1.0f, 0.05f);
    EXPECT_NEAR(white.b, 1.0f, 0.05f);
    const Rgb warm = emission_rgb(blackbody_spectrum(2700.0f));
    EXPECT_GT(warm.r, warm.g);
    EXPECT_GT(warm.g, warm.b);
    const Rgb cool = emission_rgb(blackbody_spectrum(10000.0f));
    EXPECT_GT(cool.b, cool.g);
    EXPECT_GT(cool.g, cool.r);
}

TEST(SpectrumRgb, BlackEmitsBlack) {
    EXPECT_EQ(emission_rgb(dense_constant(0.0f)), Rgb(0.0f));
    EXPECT_EQ(reflectance_rgb(dense_constant(0.0f)), Rgb(0.0f));
}

}  // namespace
}  // namespace candela
