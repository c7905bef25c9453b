// RGB to spectrum (spectrum/rgb_to_spectrum.h): the round trip rgb -> spectrum -> XYZ -> sRGB of
// the three forms over the gamut, greys exactly constant, and the forms' small contracts.
#include "candela/spectrum/rgb_to_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/spectrum/rgb_to_spectrum_table.h"
#include "candela/spectrum/spectrum_rgb.h"
#include "spectrum_round_trip.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Colours over the RGB cube: every channel at (i + 1/2) / 23, i < 23, which falls between the
// table's nodes, and at i / 10, i <= 10, which takes in its faces, edges and corners (primaries,
// secondaries, black, white, greys).
std::vector<Rgb> gamut_grid() {
    std::vector<float> a, b;
    for (int i = 0; i < 23; ++i) a.push_back(float((i + 0.5) / 23.0));
    for (int i = 0; i <= 10; ++i) b.push_back(float(i / 10.0));
    std::vector<Rgb> grid;
    for (const auto* axis : {&a, &b})
        for (float r : *axis)
            for (float g : *axis)
                for (float bl : *axis) grid.emplace_back(r, g, bl);
    return grid;
}

struct Worst {
    float error = 0.0f;
    Rgb at;
    void update(float e, const Rgb& c) {
        if (e > error) {
            error = e;
            at = c;
        }
    }
};

std::ostream& operator<<(std::ostream& os, const Worst& w) {
    return os << "largest error " << w.error << " at (" << w.at.r << ", " << w.at.g << ", " << w.at.b << ")";
}

TEST(RgbToSpectrum, AlbedoRoundTripsWithin1e3OverTheGamut) {
    Worst worst;
    for (const Rgb& c : gamut_grid()) {
        const Rgb back = reflectance_rgb(test::sampled(rgb_albedo_spectrum(c)));
        worst.update(test::largest_difference(back, c), c);
    }
    EXPECT_LT(worst.error, 1e-3f) << worst;
}

// The unbounded and illuminant forms are 2m times a bounded spectrum (m the largest channel), so
// their error is the table's at rgb / 2m times 2m: 1e-3 of max(1, m).
TEST(RgbToSpectrum, UnboundedRoundTripsWithin1e3OfItsLargestChannel) {
    Worst worst;
    for (float scale : {0.8f, 3.5f, 40.0f})
        for (const Rgb& c0 : gamut_grid()) {
            const Rgb c = c0 * scale;
            const Rgb back = reflectance_rgb(test::sampled(rgb_unbounded_spectrum(c)));
            worst.update(test::largest_difference(back, c) / std::max(1.0f, c.max_component()), c);
        }
    EXPECT_LT(worst.error, 1e-3f) << worst;
}

TEST(RgbToSpectrum, IlluminantEmitsItsColourWithin1e3OfItsLargestChannel) {
    // The emission's own XYZ, no illuminant: D65 has Y = 1 and is the sRGB white.
    Worst worst;
    for (float scale : {0.8f, 3.5f, 40.0f})
        for (const Rgb& c0 : gamut_grid()) {
            const Rgb c = c0 * scale;
            const Rgb back = test::emitted_rgb(test::sampled(rgb_illuminant_spectrum(c)));
            worst.update(test::largest_difference(back, c) / std::max(1.0f, c.max_component()), c);
        }
    EXPECT_LT(worst.error, 1e-3f) << worst;
}

// Greys, including the smallest and largest floats of [0, 1] and values where
// s((v - 1/2) / sqrt(v (1 - v))) in float misses v.
std::vector<float> greys() {
    std::vector<float> v = {0.0f, 1e-30f, 1e-7f, 0.001f, 0.18f, 0.2f, 0.5f, 0.7f, 0.8f, 0.999f, 0.99999994f, 1.0f};
    for (int i = 1; i < 200; ++i) v.push_back(float(i) / 200.0f + 1e-4f);
    return v;
}
std::vector<float> wavelengths() {
    std::vector<float> l;
    for (float lambda = 360.0f; lambda <= 830.0f; lambda += 0.37f) l.push_back(lambda);
    return l;
}

TEST(RgbToSpectrum, GreysAreExactlyConstantInEveryForm) {
    const DenseSpectrum& d65 = d65_illuminant();
    const std::vector<float> lambdas = wavelengths();
    for (float v : greys()) {
        const RgbSpectrum albedo = rgb_albedo_spectrum(Rgb(v));
        for (float m : {1.0f, 2.5f, 1000.0f}) {
            const RgbSpectrum unbounded = rgb_unbounded_spectrum(Rgb(v * m));
            const RgbSpectrum illuminant = rgb_illuminant_spectrum(Rgb(v * m));
            for (float lambda : lambdas) {
                ASSERT_EQ(unbounded(lambda), v * m) << v << " x " << m << " at " << lambda;
                ASSERT_EQ(illuminant(lambda), v * m * d65(lambda)) << v << " x " << m << " at " << lambda;
            }
        }
        for (float lambda : lambdas) ASSERT_EQ(albedo(lambda), v) << v << " at " << lambda;
        const Color four = albedo.eval(Color::from_channels(360.0f, 512.3f, 700.1f, 830.0f));
        EXPECT_EQ(four, Color(v)) << v;
    }
}

TEST(RgbToSpectrum, GreySigmoidIsTheConstant) {
    for (float v : greys()) {
        const RgbSigmoid s = rgb_to_sigmoid(Rgb(v));
        EXPECT_EQ(s.c0, 0.0f);
        EXPECT_EQ(s.c1, 0.0f);
        // The closed form is exact in real numbers; in float within a few ulps of v.
        EXPECT_NEAR(s(550.0f), v, 4e-7f * v) << v;
    }
    EXPECT_EQ(rgb_to_sigmoid(Rgb(0.0f))(550.0f), 0.0f);
    EXPECT_EQ(rgb_to_sigmoid(Rgb(1.0f))(550.0f), 1.0f);
    EXPECT_EQ(rgb_to_sigmoid(Rgb(0.5f))(550.0f), 0.5f);
}

TEST(RgbToSpectrum, AlbedoClampsToTheUnitCube) {
    const RgbSpectrum clamped = rgb_albedo_spectrum(Rgb(1.7f, -0.3f, 0.4f));
    const RgbSpectrum inside = rgb_albedo_spectrum(Rgb(1.0f, 0.0f, 0.4f));
    for (float lambda : wavelengths()) EXPECT_EQ(clamped(lambda), inside(lambda)) << lambda;
}

TEST(RgbToSpectrum, BlackIsZeroInEveryForm) {
    for (const RgbSpectrum& s : {rgb_albedo_spectrum(Rgb(0.0f)), rgb_unbounded_spectrum(Rgb(0.0f)), rgb_illuminant_spectrum(Rgb(0.0f))}) {
        for (float lambda : wavelengths()) EXPECT_EQ(s(lambda), 0.0f) << lambda;
        EXPECT_EQ(s.max_value(), 0.0f);
    }
}

TEST(RgbToSpectrum, EvalGivesTheScalarValuesAtEachWavelength) {
    const Color lambda = Color::from_channels(371.2f, 498.7f, 602.5f, 815.0f);
    const Rgb c(0.8f, 0.3f, 0.05f);
    for (const RgbSpectrum& s : {rgb_albedo_spectrum(c), rgb_unbounded_spectrum(c * 7.0f), rgb_illuminant_spectrum(c * 7.0f)}) {
        const Color v = s.eval(lambda);
        for (int i = 0; i < kColorChannels; ++i) EXPECT_EQ(v[i], s(lambda[i])) << i;
    }
}

TEST(RgbToSpectrum, MaxValueBoundsTheSpectrumAndAlbedosStayBelowOne) {
    for (const Rgb& c : {Rgb(0.9f, 0.1f, 0.1f), Rgb(0.1f, 0.8f, 0.7f), Rgb(0.02f, 0.05f, 0.95f), Rgb(1.0f, 1.0f, 0.0f)}) {
        for (const RgbSpectrum& s : {rgb_albedo_spectrum(c), rgb_unbounded_spectrum(c * 3.0f), rgb_illuminant_spectrum(c * 3.0f)}) {
            float sampled = 0.0f;
            for (float lambda : wavelengths()) sampled = std::max(sampled, s(lambda));
            EXPECT_GE(s.max_value() * (1.0f + 1e-6f), sampled);
        }
        EXPECT_LE(rgb_albedo_spectrum(c).max_value(), 1.0f);
    }
}

TEST(RgbToSpectrum, NeighbouringSlicesGiveTheSameSpectrum) {
    // Where two channels tie for largest, the colour lies on the boundary of two slices of the
    // table; on either side of it the lookups use different slices and nodes, and agree within
    // the interpolation error (2.3e-4 at most here; a slice read with its channels permuted
    // would be off by tenths).
    for (const Rgb& c : {Rgb(0.6f, 0.6f, 0.2f), Rgb(0.3f, 0.9f, 0.9f), Rgb(0.05f, 0.02f, 0.05f), Rgb(0.99f, 0.5f, 0.99f)}) {
        const float e = 1e-5f;
        const int a = c.r == c.g ? 0 : (c.g == c.b ? 1 : 2), b = (a + 1) % 3;
        float lo[3] = {c.r, c.g, c.b}, hi[3] = {c.r, c.g, c.b};
        lo[a] += e;
        hi[b] += e;
        const RgbSigmoid s0 = rgb_to_sigmoid(Rgb(lo[0], lo[1], lo[2])), s1 = rgb_to_sigmoid(Rgb(hi[0], hi[1], hi[2]));
        float largest = 0.0f;
        for (float lambda : wavelengths()) largest = std::max(largest, std::abs(s0(lambda) - s1(lambda)));
        EXPECT_LT(largest, 1e-3f) << "(" << c.r << ", " << c.g << ", " << c.b << ")";
    }
}

}  // namespace
}  // namespace candela
