// Blackbody emission of temperature grids: pbrt-v4's BlackbodySpectrum in candela's units, and
// RGB mode's table of its colours.
#include "candela/media/blackbody_emission.h"

#include <gtest/gtest.h>

#include <cmath>

#include "candela/sampling/rng.h"
#include "candela/spectrum/color_space.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The largest channel difference relative to the largest channel.
float relative_difference(const Rgb& a, const Rgb& b) {
    const float scale = std::max({std::abs(b.r), std::abs(b.g), std::abs(b.b)});
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) / scale;
}

TEST(BlackbodyEmission, PeaksAtKCieYIntegralAtWiensWavelength) {
    for (float kelvin : {800.0f, 3000.0f, 5000.0f, 6500.0f}) {
        const float peak_nm = float(kWienDisplacement / double(kelvin) * 1e9);
        const Color v = blackbody_radiance(kelvin, Color::from_channels(peak_nm, peak_nm - 40, peak_nm + 40, 560.0f));
        EXPECT_NEAR(v[0], kCieYIntegral, 1e-3f * kCieYIntegral);
        EXPECT_LT(v[1], v[0]);
        EXPECT_LT(v[2], v[0]);
        // Planck's law itself, normalized independently.
        const double expected = planck(560.0, double(kelvin)) / planck(double(peak_nm), double(kelvin)) * double(kCieYIntegral);
        EXPECT_NEAR(v[3], expected, 1e-4 * expected);
    }
}

TEST(BlackbodyEmission, RgbTableMatchesTheExactIntegral) {
    const BlackbodyRgbTable table = make_blackbody_rgb_table();
    Rng rng(61, 62);
    for (int i = 0; i < 500; ++i) {
        // Log-uniform over 100.5 K .. 2 10^7 K (beyond 10^7 the table extrapolates: 2e-3 off at
        // 10^8 K, a temperature no scene has).
        const float kelvin = 100.5f * std::exp(12.2f * rng.next_float());
        const Rgb exact = blackbody_rgb_exact(double(kelvin));
        // Below about 300 K the colour is below float's range (exp(-hc / lambda k T) < 1e-30).
        if (!(exact.g > 1e-30f)) continue;
        EXPECT_LT(relative_difference(table.at(kelvin), exact), 1e-3f) << kelvin << " K";
    }
}

TEST(BlackbodyEmission, ControlTheTableTellsOnePercentOfTemperatureApart) {
    const BlackbodyRgbTable table = make_blackbody_rgb_table();
    for (float kelvin : {1200.0f, 2500.0f, 6500.0f, 15000.0f})
        EXPECT_GT(relative_difference(table.at(kelvin * 1.01f), blackbody_rgb_exact(double(kelvin))), 1e-3f) << kelvin;
}

TEST(BlackbodyEmission, SpectralRadianceIntegratesToTheRgbModesColour) {
    // What the sensor makes of the spectral radiance (the matching functions times it, over
    // kCieYIntegral; film/sensor.h) is RGB mode's colour: the two modes render the same fire.
    for (float kelvin : {1500.0f, 3000.0f, 7000.0f}) {
        Vec3d xyz(0.0);
        for (int i = 0; i < kCieSamples; i += 4) {
            const float l0 = kCieLambdaMin + float(i);
            const Color v = blackbody_radiance(kelvin, Color::from_channels(l0, l0 + 1, l0 + 2, l0 + 3));
            for (int c = 0; c < 4 && i + c < kCieSamples; ++c)
                xyz += Vec3d(double(kCieX[i + c]), double(kCieY[i + c]), double(kCieZ[i + c])) * double(v[c]);
        }
        const Rgb rgb = xyz_to_linear_srgb(xyz / double(kCieYIntegral));
        EXPECT_LT(relative_difference(rgb, blackbody_rgb_exact(double(kelvin))), 1e-4f) << kelvin;
    }
}

TEST(BlackbodyEmission, ColoursFollowTemperature) {
    const BlackbodyRgbTable table = make_blackbody_rgb_table();
    const Rgb warm = table.at(2000.0f), white = table.at(6504.0f), cold = table.at(20000.0f);
    EXPECT_GT(warm.r, warm.g);
    EXPECT_GT(warm.g, warm.b);
    EXPECT_GT(cold.b, cold.r);
    // Near D65's temperature the colour is near white (the Planckian locus passes close to D65).
    EXPECT_LT(relative_difference(white, Rgb(white.g)), 0.1f);
    // Brighter with temperature over the visible range at the same peak: a 2000 K body peaks in
    // the infrared, so its visible luminance is below a 6504 K body's.
    EXPECT_LT(warm.g, white.g);
}

}  // namespace
}  // namespace candela
