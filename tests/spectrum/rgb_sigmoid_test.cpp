// The sigmoid polynomial (spectrum/rgb_sigmoid.h): the sigmoid against its closed form in double,
// its limits, and the four-wavelength evaluation and maximum against the scalar values.
#include "candela/spectrum/rgb_sigmoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Jakob & Hanika's eq. 4 in double, the reference for the float evaluation: for x < 0 as
// 1 / (2 r (r - x)), r = sqrt(1 + x^2), the same number without the cancellation that would leave
// double only six correct digits of s(-1e5) = 2.5e-11.
double sigmoid_reference(double x) {
    const double r = std::sqrt(1.0 + x * x);
    return x < 0.0 ? 1.0 / (2.0 * r * (r - x)) : 0.5 + x / (2.0 * r);
}

TEST(RgbSigmoid, LimitsAreExactZeroHalfAndOne) {
    EXPECT_EQ(rgb_sigmoid_s(0.0f), 0.5f);
    EXPECT_EQ(rgb_sigmoid_s(-0.0f), 0.5f);
    EXPECT_EQ(rgb_sigmoid_s(kInf), 1.0f);
    EXPECT_EQ(rgb_sigmoid_s(-kInf), 0.0f);
    // Where x^2 overflows (|x| > 1.8e19) the value is the limit, not 1/2.
    EXPECT_EQ(rgb_sigmoid_s(1e30f), 1.0f);
    EXPECT_EQ(rgb_sigmoid_s(-1e30f), 0.0f);
    EXPECT_EQ(rgb_sigmoid_s(std::numeric_limits<float>::max()), 1.0f);
    EXPECT_EQ(rgb_sigmoid_s(-std::numeric_limits<float>::max()), 0.0f);
    EXPECT_TRUE(std::isnan(rgb_sigmoid_s(std::numeric_limits<float>::quiet_NaN())));
}

TEST(RgbSigmoid, MatchesTheClosedFormWithTheTailsRelativePrecision) {
    // Absolute error at most a few float ulps of 1/2 everywhere; for x < 0 also relative, down
    // the far tail where s ~ 1 / (4 x^2) (the closed form in float cancels there: at x = -1e3
    // it would keep no correct digit of s = 2.5e-7).
    auto check = [](float x) {
        const double expected = sigmoid_reference(double(x));
        const double got = double(rgb_sigmoid_s(x));
        EXPECT_NEAR(got, expected, 2e-7) << "x = " << x;
        if (x < 0.0f) {
            EXPECT_NEAR(got / expected, 1.0, 1e-6) << "x = " << x;
        }
    };
    for (int i = -1000; i <= 1000; ++i) check(float(i) * 0.01f);
    for (double m = 10.0; m < 1e5; m *= 1.03) {
        check(float(m));
        check(float(-m));
    }
}

TEST(RgbSigmoid, IncreasesMonotonicallyWithinZeroOne) {
    float previous = 0.0f;
    for (float x = -1e6f; x < 1e6f; x = x < 0.0f ? (x < -1.0f ? x * 0.99f : x + 1e-3f) : (x < 1.0f ? x + 1e-3f : x * 1.01f)) {
        const float s = rgb_sigmoid_s(x);
        EXPECT_GE(s, previous) << "x = " << x;
        EXPECT_GE(s, 0.0f);
        EXPECT_LE(s, 1.0f);
        previous = s;
    }
}

TEST(RgbSigmoid, IsTheSigmoidOfTheQuadraticInNanometres) {
    const RgbSigmoid s{-1.2e-4f, 0.131f, -35.0f};
    for (float lambda = 360.0f; lambda <= 830.0f; lambda += 1.0f) {
        const double l = double(lambda);
        const double x = double(s.c0) * l * l + double(s.c1) * l + double(s.c2);
        EXPECT_NEAR(s(lambda), sigmoid_reference(x), 1e-5) << lambda;
    }
}

TEST(RgbSigmoid, EvalGivesTheScalarValuesAtEachWavelength) {
    const RgbSigmoid s{2.1e-4f, -0.19f, 41.0f};
    const Color lambda = Color::from_channels(380.5f, 512.25f, 640.0f, 829.9f);
    const Color v = s.eval(lambda);
    for (int i = 0; i < kColorChannels; ++i) EXPECT_EQ(v[i], s(lambda[i])) << i;
}

TEST(RgbSigmoid, MaxValueIsTheLargestValueOverTheVisibleRange) {
    const RgbSigmoid shapes[] = {
        {-1.2e-4f, 0.131f, -35.0f},  // a peak inside (vertex near 546 nm)
        {1.2e-4f, -0.131f, 35.0f},   // a dip inside: the maximum is at an end
        {0.0f, 0.01f, -5.0f},        // increasing
        {0.0f, -0.01f, 5.0f},        // decreasing
        {0.0f, 0.0f, 0.3f},          // constant
        {-1e-5f, 0.02f, -2.0f},      // vertex at 1000 nm, outside
    };
    for (const RgbSigmoid& s : shapes) {
        float sampled = 0.0f;
        for (float lambda = 360.0f; lambda <= 830.0f; lambda += 0.25f) sampled = std::max(sampled, s(lambda));
        EXPECT_GE(s.max_value(), sampled) << s.c0 << " " << s.c1 << " " << s.c2;
        EXPECT_NEAR(s.max_value(), sampled, 1e-6f) << s.c0 << " " << s.c1 << " " << s.c2;
    }
}

}  // namespace
}  // namespace candela
