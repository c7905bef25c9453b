// erfinv against a double-precision reference, and the normal samplers as inverse CDFs.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/math/constants.h"
#include "candela/sampling/normal.h"
#include "support/chi2.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// erfinv(x) in double by Newton's method on std::erf, started from the float approximation.
double erfinv_reference(double x) {
    double y = static_cast<double>(erfinv(static_cast<float>(x)));
    for (int i = 0; i < 50; ++i) {
        double step = (std::erf(y) - x) / (2.0 / std::sqrt(kPiD) * std::exp(-y * y));
        y -= step;
        if (std::abs(step) < 1e-15 * std::max(1.0, std::abs(y))) break;
    }
    return y;
}

// The CDF of the normal N(0, sigma^2) truncated to [-radius, radius].
double truncated_normal_cdf(double x, double sigma, double radius) {
    double mass = std::erf(radius / (sigma * std::sqrt(2.0)));
    return 0.5 * (1.0 + std::erf(x / (sigma * std::sqrt(2.0))) / mass);
}

TEST(Erfinv, MatchesDoublePrecisionInverseOfErf) {
    // Over the whole range, and towards +-1 where erfinv grows like sqrt(-log(1 - x)).
    double worst = 0.0;
    auto relative_error = [](float x) {
        double reference = erfinv_reference(static_cast<double>(x));
        double err = std::abs(static_cast<double>(erfinv(x)) - reference);
        return err / std::max(1.0, std::abs(reference));
    };
    for (int i = -1000; i <= 1000; ++i)
        worst = std::max(worst, relative_error(static_cast<float>(i / 1000.5)));
    for (int k = 1; k <= 7; ++k)
        worst = std::max(worst, relative_error(1.0f - std::pow(10.0f, static_cast<float>(-k))));
    EXPECT_LT(worst, 2e-6);
}

TEST(Erfinv, IsOddAndZeroAtZero) {
    EXPECT_EQ(erfinv(0.0f), 0.0f);
    for (float x : {0.1f, 0.5f, 0.9f, 0.999f}) EXPECT_EQ(erfinv(-x), -erfinv(x));
}

TEST(Erfinv, StaysFiniteAtPlusMinusOne) {
    EXPECT_TRUE(std::isfinite(erfinv(1.0f)));
    EXPECT_GT(erfinv(1.0f), erfinv(kOneMinusEpsilon));
    EXPECT_GT(erfinv(1.0f), 3.5f);
    EXPECT_EQ(erfinv(-1.0f), -erfinv(1.0f));
}

TEST(NormalSampling, StandardNormalInvertsItsCdf) {
    EXPECT_EQ(sample_standard_normal(0.5f), 0.0f);
    for (float u : {0.001f, 0.02f, 0.3f, 0.7f, 0.95f, 0.999f}) {
        double x = static_cast<double>(sample_standard_normal(u));
        EXPECT_NEAR(0.5 * std::erfc(-x / std::sqrt(2.0)), static_cast<double>(u), 1e-6) << u;
    }
    EXPECT_NEAR(standard_normal_pdf(0.0f), 0.398942280f, 1e-7f);
    EXPECT_NEAR(standard_normal_pdf(1.0f), 0.241970725f, 1e-7f);
}

TEST(NormalSampling, TruncatedNormalInvertsItsCdfAndStaysInside) {
    const float sigma = 0.5f, radius = 1.5f;
    for (float u : {0.0f, 1e-6f, 0.1f, 0.5f, 0.77f, 0.999f, kOneMinusEpsilon}) {
        float x = sample_truncated_normal(u, sigma, radius);
        EXPECT_LE(std::abs(x), radius);
        double cdf = truncated_normal_cdf(static_cast<double>(x), 0.5, 1.5);
        EXPECT_NEAR(cdf, static_cast<double>(u), 2e-6) << u;
    }
    EXPECT_EQ(truncated_normal_pdf(1.6f, sigma, radius), 0.0f);
    EXPECT_GT(truncated_normal_pdf(1.5f, sigma, radius), 0.0f);
}

TEST(NormalSampling, TruncatedNormalPdfIntegratesToOne) {
    test::PlanarDomain strip{{-2.0, 0.0}, {2.0, 1.0}};  // wider than the support [-1.2, 1.2]
    auto pdf = [](Vec2f p) { return truncated_normal_pdf(p.x, 0.8f, 1.2f); };
    EXPECT_NEAR(test::integrate_pdf(strip, pdf), 1.0, 1e-5);
}

}  // namespace
}  // namespace candela
