// Chi-square goodness of fit of PixelFilter's sampling against its pdf (tests/support/chi2.h), for
// pbrt-v4's parameterized box and triangle and its tabulated Gaussian, Mitchell and Lanczos
// filters. The histogram spans the support, its cells aligned with the tables' cells (32 per pixel
// of radius) so that no histogram cell straddles a step of the piecewise-constant pdf.
#include <gtest/gtest.h>

#include "candela/film/pixel_filter.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 6;

Chi2Result pixel_filter_chi2(const FilterSettings& settings, int res_x, int res_y) {
    const PixelFilter filter(settings);
    Chi2Options opt;
    opt.res_x = res_x;
    opt.res_y = res_y;
    opt.test_count = kChi2Tests;
    const Vec2d r(settings.radius.x, settings.radius.y);
    const PlanarDomain support{{0.5 - r.x, 0.5 - r.y}, {0.5 + r.x, 0.5 + r.y}};
    return chi2_test(
        support, [&](Sampler& rng) { return filter.sample(0, rng.next_vec2f()).position; },
        [&](Vec2f p) { return filter.pdf(p); }, opt);
}

FilterSettings settings(FilterType type, Vec2f radius) {
    FilterSettings s;
    s.type = type;
    s.radius = radius;
    return s;
}

TEST(PixelFilterChi2, BoxWithUnequalRadii) {
    Chi2Result r = pixel_filter_chi2(settings(FilterType::kBox, {1.0f, 0.25f}), 40, 10);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PixelFilterChi2, TriangleOfPbrtsDefaultRadius) {
    Chi2Result r = pixel_filter_chi2(settings(FilterType::kTent, {2.0f, 2.0f}), 40, 40);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PixelFilterChi2, OffsetGaussian) {
    Chi2Result r = pixel_filter_chi2(settings(FilterType::kOffsetGaussian, {1.5f, 1.5f}), 48, 48);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PixelFilterChi2, OffsetGaussianWithUnequalRadiiAndSigma) {
    FilterSettings s = settings(FilterType::kOffsetGaussian, {2.0f, 1.0f});
    s.sigma = 0.8f;
    Chi2Result r = pixel_filter_chi2(s, 32, 32);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PixelFilterChi2, MitchellIncludingItsNegativeLobes) {
    Chi2Result r = pixel_filter_chi2(settings(FilterType::kMitchell, {2.0f, 2.0f}), 64, 64);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(PixelFilterChi2, LanczosIncludingItsNegativeLobes) {
    Chi2Result r = pixel_filter_chi2(settings(FilterType::kLanczos, {4.0f, 4.0f}), 64, 64);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
