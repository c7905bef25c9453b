// Pixel filters: supports, smallpt's subpixel pattern and formula, exact inversion of the
// Gaussian, and pdfs that integrate to 1. Distributions: filter_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/film/filter.h"
#include "candela/math/constants.h"
#include "support/chi2.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr FilterType kAllFilters[] = {FilterType::kBox, FilterType::kTent, FilterType::kGaussian,
                                      FilterType::kSmallpt};

// Uniform samples on a grid, including 0 and the largest float below 1.
std::vector<float> unit_grid() {
    std::vector<float> us;
    for (int i = 0; i <= 16; ++i) us.push_back(static_cast<float>(i) / 16.0f);
    us.back() = kOneMinusEpsilon;
    return us;
}

TEST(Filter, RadiiAreTheDocumentedHalfWidths) {
    EXPECT_EQ(filter_radius(FilterType::kBox), 0.5f);
    EXPECT_EQ(filter_radius(FilterType::kTent), 1.0f);
    EXPECT_EQ(filter_radius(FilterType::kGaussian), 1.5f);
    EXPECT_EQ(filter_radius(FilterType::kSmallpt), 0.75f);
}

TEST(Filter, SamplesStayWithinTheRadiusOfThePixelCentre) {
    for (FilterType type : kAllFilters) {
        float r = filter_radius(type);
        for (uint32_t index = 0; index < 8; ++index)
            for (float ux : unit_grid())
                for (float uy : unit_grid()) {
                    Vec2f p = sample_filter(type, index, Vec2f(ux, uy));
                    ASSERT_LE(std::abs(p.x - 0.5f), r) << static_cast<int>(type) << " " << ux;
                    ASSERT_LE(std::abs(p.y - 0.5f), r) << static_cast<int>(type) << " " << uy;
                }
    }
}

TEST(Filter, BoxSampleIsTheUniformSample) {
    for (float u : unit_grid()) {
        Vec2f v(u, 0.5f * u);
        EXPECT_EQ(sample_filter(FilterType::kBox, 3, v), v);
    }
}

TEST(Filter, SmallptCyclesThroughTheFourSubpixelsBySampleIndex) {
    // u = 0.5 is the middle of the tent: the sample lands on its subpixel's centre.
    const Vec2f centres[] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}};
    for (uint32_t i = 0; i < 12; ++i)
        EXPECT_EQ(sample_filter(FilterType::kSmallpt, i, Vec2f(0.5f, 0.5f)), centres[i % 4]) << i;
}

TEST(Filter, SmallptMatchesSmallptsFormula) {
    // smallpt.cpp: r1 = 2 erand48, dx = r1 < 1 ? sqrt(r1) - 1 : 1 - sqrt(2 - r1), and the film
    // position in pixels is (sx + .5 + dx) / 2 (the same along y with r2, dy and sy).
    auto smallpt = [](double u, int s) {
        double r = 2.0 * u;
        double d = r < 1.0 ? std::sqrt(r) - 1.0 : 1.0 - std::sqrt(2.0 - r);
        return (s + 0.5 + d) / 2.0;
    };
    for (uint32_t i = 0; i < 4; ++i)
        for (float ux : unit_grid())
            for (float uy : {0.1f, 0.6f}) {
                Vec2f p = sample_filter(FilterType::kSmallpt, i, Vec2f(ux, uy));
                auto sx = static_cast<int>(i % 2), sy = static_cast<int>(i / 2);
                EXPECT_NEAR(static_cast<double>(p.x), smallpt(static_cast<double>(ux), sx), 1e-6);
                EXPECT_NEAR(static_cast<double>(p.y), smallpt(static_cast<double>(uy), sy), 1e-6);
            }
}

TEST(Filter, GaussianSamplesInvertTheTruncatedNormalCdfExactly) {
    // Exact inversion is what makes weight 1 correct: the position's CDF value is u.
    const double sigma = 0.5, radius = 1.5;
    double mass = std::erf(radius / (sigma * std::sqrt(2.0)));
    for (float u : unit_grid()) {
        Vec2f p = sample_filter(FilterType::kGaussian, 0, Vec2f(u, 0.5f));
        double x = static_cast<double>(p.x) - 0.5;
        double cdf = 0.5 * (1.0 + std::erf(x / (sigma * std::sqrt(2.0))) / mass);
        EXPECT_NEAR(cdf, static_cast<double>(u), 2e-6) << u;
    }
}

TEST(Filter, PdfsAreSymmetricAboutThePixelCentreAndZeroOutside) {
    for (FilterType type : kAllFilters) {
        float r = filter_radius(type);
        for (Vec2f d : {Vec2f(0.1f, 0.2f), Vec2f(0.4f, 0.05f), Vec2f(0.3f, 0.45f)}) {
            float at = filter_pdf(type, Vec2f(0.5f + d.x, 0.5f + d.y));
            EXPECT_GT(at, 0.0f);
            EXPECT_FLOAT_EQ(at, filter_pdf(type, Vec2f(0.5f - d.x, 0.5f + d.y)));
            EXPECT_FLOAT_EQ(at, filter_pdf(type, Vec2f(0.5f + d.x, 0.5f - d.y)));
        }
        EXPECT_EQ(filter_pdf(type, Vec2f(0.5f + r + 0.01f, 0.5f)), 0.0f);
        EXPECT_EQ(filter_pdf(type, Vec2f(0.5f, 0.5f - r - 0.01f)), 0.0f);
    }
}

TEST(Filter, PdfsIntegrateToOne) {
    test::PlanarDomain film{{-1.0, -1.0}, {2.0, 2.0}};  // holds every support (Gaussian: [-1, 2])
    for (FilterType type : kAllFilters) {
        auto pdf = [type](Vec2f p) { return filter_pdf(type, p); };
        EXPECT_NEAR(test::integrate_pdf(film, pdf, 30, 30), 1.0, 1e-5) << static_cast<int>(type);
    }
}

TEST(Filter, SeparablePdfsAreTheInverseJacobianOfTheirSampling) {
    constexpr float kH = 1e-3f;
    for (FilterType type : {FilterType::kBox, FilterType::kTent, FilterType::kGaussian}) {
        for (Vec2f u : {Vec2f(0.13f, 0.71f), Vec2f(0.62f, 0.27f), Vec2f(0.9f, 0.4f)}) {
            auto at = [type](float x, float y) { return sample_filter(type, 0, Vec2f(x, y)); };
            double dx = static_cast<double>(at(u.x + kH, u.y).x - at(u.x - kH, u.y).x);
            double dy = static_cast<double>(at(u.x, u.y + kH).y - at(u.x, u.y - kH).y);
            double jacobian = dx * dy / (4.0 * static_cast<double>(kH) * static_cast<double>(kH));
            double pdf = static_cast<double>(filter_pdf(type, at(u.x, u.y)));
            EXPECT_NEAR(pdf * jacobian, 1.0, 2e-3) << static_cast<int>(type);
        }
    }
}

}  // namespace
}  // namespace candela
