// PixelFilter (film/pixel_filter.h): the scene file's named filters sample exactly as before with
// weight 1, the parameterized box and triangle are pbrt-v4's, and the tabulated filters (pbrt-v4's
// Gaussian, Mitchell, Lanczos) weight each sample by f / pdf of their table.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/film/filter.h"
#include "candela/film/pixel_filter.h"

namespace candela {
namespace CANDELA_UNITY_ID {

FilterSettings settings(FilterType type, float radius) {
    FilterSettings s;
    s.type = type;
    s.radius = {radius, radius};
    return s;
}

TEST(PixelFilter, NamedFiltersSampleBitForBitAsBeforeWithWeightOne) {
    for (FilterType type : {FilterType::kBox, FilterType::kTent, FilterType::kGaussian, FilterType::kSmallpt}) {
        const PixelFilter filter{FilterSettings(type)};
        EXPECT_FALSE(filter.weighted());
        for (uint32_t i = 0; i < 8; ++i)
            for (float ux : {0.0f, 1e-9f, 0.1f, 0.37f, 0.5f, 0.8f, 0.99999994f})
                for (float uy : {0.0f, 0.25f, 0.6f, 0.99999994f}) {
                    const FilterSample s = filter.sample(i, Vec2f(ux, uy));
                    EXPECT_EQ(s.position, sample_filter(type, i, Vec2f(ux, uy))) << int(type);
                    EXPECT_EQ(s.weight, 1.0f);
                }
    }
}

TEST(PixelFilter, NamedFiltersKeepTheirRadii) {
    EXPECT_EQ(FilterSettings(FilterType::kBox).radius, Vec2f(0.5f, 0.5f));
    EXPECT_EQ(FilterSettings(FilterType::kTent).radius, Vec2f(1.0f, 1.0f));
    EXPECT_EQ(FilterSettings(FilterType::kGaussian).radius, Vec2f(1.5f, 1.5f));
}

TEST(PixelFilter, PbrtDefaultRadii) {
    EXPECT_EQ(default_filter_radius(FilterType::kBox), 0.5f);
    EXPECT_EQ(default_filter_radius(FilterType::kTent), 2.0f);
    EXPECT_EQ(default_filter_radius(FilterType::kOffsetGaussian), 1.5f);
    EXPECT_EQ(default_filter_radius(FilterType::kMitchell), 2.0f);
    EXPECT_EQ(default_filter_radius(FilterType::kLanczos), 4.0f);
}

TEST(PixelFilter, BoxAndTriangleStayWithinTheirRadius) {
    FilterSettings box = settings(FilterType::kBox, 1.0f);
    box.radius.y = 0.25f;
    const PixelFilter b(box), t(settings(FilterType::kTent, 2.0f));
    for (float u : {0.0f, 0.3f, 0.5f, 0.99999994f}) {
        const Vec2f p = b.sample(0, Vec2f(u, u)).position, q = t.sample(0, Vec2f(u, u)).position;
        EXPECT_LE(std::abs(p.x - 0.5f), 1.0f);
        EXPECT_LE(std::abs(p.y - 0.5f), 0.25f);
        EXPECT_LE(std::abs(q.x - 0.5f), 2.0f);
    }
    EXPECT_EQ(b.sample(0, Vec2f(0.0f, 0.0f)).position, Vec2f(-0.5f, 0.25f));
    EXPECT_EQ(b.pdf(Vec2f(0.5f, 0.5f)), 1.0f / (4.0f * 1.0f * 0.25f));
}

TEST(PixelFilter, FunctionsArePbrtV4s) {
    const FilterSettings gaussian = settings(FilterType::kOffsetGaussian, 1.5f);
    // The Gaussian less its value at the radius: 0 there, g(0) - g(1.5) at the centre.
    const double g0 = 1.0 / (std::sqrt(2.0 * kPiD) * 0.5), g15 = g0 * std::exp(-1.5 * 1.5 / (2.0 * 0.25));
    EXPECT_NEAR(double(filter_function_1d(gaussian, 0.0f, 1.5f)), g0 - g15, 1e-6);
    EXPECT_EQ(filter_function_1d(gaussian, 1.5f, 1.5f), 0.0f);
    EXPECT_EQ(filter_function_1d(gaussian, 1.6f, 1.5f), 0.0f);
    // Mitchell-Netravali at 0 is (6 - 2B) / 6; at half the radius (x = 1) it is (B + ... ) = B / 6.
    const FilterSettings mitchell = settings(FilterType::kMitchell, 2.0f);
    EXPECT_NEAR(filter_function_1d(mitchell, 0.0f, 2.0f), (6.0f - 2.0f / 3.0f) / 6.0f, 1e-6f);
    EXPECT_NEAR(filter_function_1d(mitchell, 1.0f, 2.0f), (1.0f / 3.0f) / 6.0f, 1e-6f);
    EXPECT_LT(filter_function_1d(mitchell, 1.5f, 2.0f), 0.0f);  // the negative lobe
    // Lanczos: 1 at 0, 0 at the integers, negative between 1 and 2.
    const FilterSettings lanczos = settings(FilterType::kLanczos, 4.0f);
    EXPECT_EQ(filter_function_1d(lanczos, 0.0f, 4.0f), 1.0f);
    EXPECT_NEAR(filter_function_1d(lanczos, 1.0f, 4.0f), 0.0f, 1e-6f);
    EXPECT_LT(filter_function_1d(lanczos, 1.5f, 4.0f), 0.0f);
    EXPECT_EQ(filter_function_1d(lanczos, 4.5f, 4.0f), 0.0f);
}

// Every tabulated sample's weight is f / pdf of the table: the table's integral of |f| with the
// sign of f where it lands.
TEST(PixelFilter, TabulatedWeightIsValueOverPdf) {
    for (FilterType type : {FilterType::kOffsetGaussian, FilterType::kMitchell, FilterType::kLanczos}) {
        const PixelFilter filter(settings(type, default_filter_radius(type)));
        EXPECT_TRUE(filter.weighted());
        int negative = 0;
        for (int i = 0; i < 64; ++i)
            for (int j = 0; j < 64; ++j) {
                const Vec2f u((float(i) + 0.5f) / 64.0f, (float(j) + 0.5f) / 64.0f);
                const FilterSample s = filter.sample(0, u);
                const float pdf = filter.pdf(s.position), value = filter.value(s.position);
                ASSERT_GT(pdf, 0.0f);
                EXPECT_NEAR(s.weight, value / pdf, 1e-4f * filter.table_integral()) << int(type);
                EXPECT_EQ(std::abs(s.weight), filter.table_integral());
                negative += s.weight < 0.0f;
            }
        if (type == FilterType::kOffsetGaussian) EXPECT_EQ(negative, 0);
        else EXPECT_GT(negative, 0) << int(type);  // the negative lobes are sampled
    }
}

TEST(PixelFilter, TabulatedPdfsIntegrateToOne) {
    // The pdf is constant on each table cell (32 per pixel of radius), so the sum of its values at
    // the cell centres times the cell area is its integral.
    for (FilterType type : {FilterType::kOffsetGaussian, FilterType::kMitchell, FilterType::kLanczos}) {
        const float r = default_filter_radius(type);
        const PixelFilter filter(settings(type, r));
        const int n = int(32.0f * r);
        const double cell = 2.0 * double(r) / n;
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double x = 0.5 - double(r) + (i + 0.5) * cell, y = 0.5 - double(r) + (j + 0.5) * cell;
                sum += double(filter.pdf(Vec2f(float(x), float(y))));
            }
        EXPECT_NEAR(sum * cell * cell, 1.0, 1e-5) << int(type);
    }
}

TEST(PixelFilter, TableIntegratesToTheFiltersIntegral) {
    // Mitchell-Netravali integrates to 1 over its support of 4 half-radii: r / 2 per axis (pbrt-v4's
    // Integral(): radius.x * radius.y / 4). The table is constant on its 64 x 64 cells, so a sum at
    // the cell centres is its integral; the midpoint table is within 1e-3 of the filter's.
    const PixelFilter mitchell(settings(FilterType::kMitchell, 2.0f));
    double sum = 0.0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j)
            sum += double(mitchell.value(Vec2f(-1.5f + (float(i) + 0.5f) / 16.0f, -1.5f + (float(j) + 0.5f) / 16.0f)));
    EXPECT_NEAR(sum / 256.0, 1.0, 1e-3);
    EXPECT_GT(mitchell.table_integral(), 1.0f);  // |f| counts the negative lobes too
}

}  // namespace
}  // namespace candela
