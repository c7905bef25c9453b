// Chi-square goodness of fit of each pixel filter's samples against filter_pdf, with sample
// indices cycling as a renderer uses them (tests/support/chi2.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "candela/film/filter.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 5;

// The film around one pixel: [-1, 2]^2 holds every filter's support, and 60 x 60 cells of 0.05
// pixel put the box, tent and smallpt support edges on cell edges. Sample indices run
// first_index, first_index + index_step, ...
template <class Pdf>
Chi2Result filter_chi2(FilterType type, uint32_t first_index, uint32_t index_step, Pdf pdf) {
    Chi2Options opt;
    opt.res_x = opt.res_y = 60;
    opt.test_count = kChi2Tests;
    uint32_t index = first_index;
    auto sampler = [&](Sampler& rng) {
        Vec2f p = sample_filter(type, index, rng.next_vec2f());
        index += index_step;
        return p;
    };
    return chi2_test(PlanarDomain{{-1.0, -1.0}, {2.0, 2.0}}, sampler, pdf, opt);
}

// All sample indices in turn, against filter_pdf.
Chi2Result filter_chi2(FilterType type) {
    return filter_chi2(type, 0, 1, [type](Vec2f p) { return filter_pdf(type, p); });
}

TEST(FilterChi2, BoxMatchesPdf) {
    Chi2Result r = filter_chi2(FilterType::kBox);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(FilterChi2, TentMatchesPdf) {
    Chi2Result r = filter_chi2(FilterType::kTent);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(FilterChi2, GaussianMatchesPdf) {
    Chi2Result r = filter_chi2(FilterType::kGaussian);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(FilterChi2, SmallptWithCyclingSampleIndicesMatchesPdf) {
    Chi2Result r = filter_chi2(FilterType::kSmallpt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(FilterChi2, SmallptSubpixelThreeIsATentAroundItsCentre) {
    // Indices 3, 7, 11 ... all pick the bottom-right subpixel, centred at (0.75, 0.75).
    auto pdf = [](Vec2f p) {
        auto tent = [](float d) { return std::max(0.0f, 0.5f - std::abs(d)) / 0.25f; };
        return tent(p.x - 0.75f) * tent(p.y - 0.75f);
    };
    Chi2Result r = filter_chi2(FilterType::kSmallpt, 3, 4, pdf);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
