// Catmull-Rom splines (math/catmull_rom.h) on non-uniform nodes: what the spline must reproduce
// exactly (linear functions: its finite-difference slopes are exact for them), and the agreement
// of its value, integral, inverse and 2D sampling with each other.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/math/catmull_rom.h"

namespace candela {
namespace CANDELA_UNITY_ID {

const std::vector<float> kNodes = {0.0f, 0.1f, 0.15f, 0.4f, 0.5f, 0.9f, 1.6f, 2.0f};

// The spline through f at kNodes, evaluated at x by the weights.
float spline_at(const std::vector<float>& nodes, const std::vector<float>& f, float x) {
    int offset;
    float w[4];
    EXPECT_TRUE(catmull_rom_weights(nodes, x, &offset, w));
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k)
        if (w[k] != 0.0f) sum += w[k] * f[static_cast<size_t>(offset + k)];
    return sum;
}

TEST(CatmullRom, WeightsSumToOneAndReproduceLinearFunctions) {
    std::vector<float> linear;
    for (float x : kNodes) linear.push_back(3.0f * x - 1.0f);
    for (int i = 0; i <= 200; ++i) {
        const float x = 2.0f * static_cast<float>(i) / 200.0f;
        int offset;
        float w[4];
        ASSERT_TRUE(catmull_rom_weights(kNodes, x, &offset, w));
        EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0f, 1e-6f) << x;
        EXPECT_NEAR(spline_at(kNodes, linear, x), 3.0f * x - 1.0f, 1e-5f) << x;
    }
    // Missing neighbours at the ends have weight 0; nodes are interpolated exactly.
    int offset;
    float w[4];
    ASSERT_TRUE(catmull_rom_weights(kNodes, 0.0f, &offset, w));
    EXPECT_EQ(offset, -1);
    EXPECT_EQ(w[0], 0.0f);
    EXPECT_EQ(w[1], 1.0f);
    ASSERT_TRUE(catmull_rom_weights(kNodes, 2.0f, &offset, w));
    EXPECT_EQ(w[3], 0.0f);
    EXPECT_FALSE(catmull_rom_weights(kNodes, -0.01f, &offset, w));
    EXPECT_FALSE(catmull_rom_weights(kNodes, 2.01f, &offset, w));
    EXPECT_FALSE(catmull_rom_weights(kNodes, std::nanf(""), &offset, w));
}

// The integral against the spline's own value (midpoint rule on 20,000 steps, error < 1e-7), for
// a curved function; exact for a linear one.
TEST(CatmullRom, IntegralAndCdfAreTheSplines) {
    std::vector<float> f, linear;
    for (float x : kNodes) {
        f.push_back(std::exp(-2.0f * x) + x * x);
        linear.push_back(2.0f * x + 1.0f);
    }
    std::vector<float> cdf(kNodes.size());
    EXPECT_NEAR(integrate_catmull_rom(kNodes, linear, cdf), 2.0f * 2.0f + 2.0f * 1.0f, 1e-5f);
    EXPECT_NEAR(cdf[3], 0.4f * 0.4f + 0.4f, 1e-6f);
    const float total = integrate_catmull_rom(kNodes, f, cdf);
    double sum = 0.0, running = 0.0;
    const int n = 20000;
    size_t next_node = 1;
    for (int i = 0; i < n; ++i) {
        const double x = 2.0 * (i + 0.5) / n;
        running += static_cast<double>(spline_at(kNodes, f, static_cast<float>(x))) * (2.0 / n);
        const double right = 2.0 * (i + 1) / n;
        if (next_node < kNodes.size() && std::abs(right - static_cast<double>(kNodes[next_node])) < 1e-9) {
            EXPECT_NEAR(cdf[next_node], running, 2e-5) << "node " << next_node;
            ++next_node;
        }
    }
    sum = running;
    EXPECT_NEAR(total, sum, 2e-5);
    EXPECT_EQ(cdf[0], 0.0f);
    EXPECT_EQ(cdf.back(), total);
}

TEST(CatmullRom, InversionFindsWhereTheSplineTakesTheValue) {
    std::vector<float> f;
    for (float x : kNodes) f.push_back(x * x + 0.5f * x);  // increasing
    for (int i = 1; i < 100; ++i) {
        const float u = f.back() * static_cast<float>(i) / 100.0f;
        const float x = invert_catmull_rom(kNodes, f, u);
        EXPECT_NEAR(spline_at(kNodes, f, x), u, 2e-5f) << "u " << u;
    }
    EXPECT_EQ(invert_catmull_rom(kNodes, f, -1.0f), 0.0f);
    EXPECT_EQ(invert_catmull_rom(kNodes, f, 100.0f), 2.0f);
}

// Sampling the second parameter of a two-row table at alpha between the rows: the sample x is
// where the interpolated cdf reaches u of its total, and fval / pdf are the interpolated
// function's value and density there.
TEST(CatmullRom, Sampling2DInvertsTheInterpolatedCdf) {
    const std::vector<float> nodes1 = {0.0f, 1.0f};
    std::vector<float> values, cdf(2 * kNodes.size());
    for (int row = 0; row < 2; ++row)
        for (float x : kNodes) values.push_back(row == 0 ? 1.0f + x : std::exp(-x));
    const size_t n = kNodes.size();
    const float total0 = integrate_catmull_rom(kNodes, std::span<const float>(values.data(), n),
                                               std::span<float>(cdf.data(), n));
    const float total1 = integrate_catmull_rom(kNodes, std::span<const float>(values.data() + n, n),
                                               std::span<float>(cdf.data() + n, n));
    const float alpha = 0.3f;  // linear weights across two rows: 0.7 and 0.3
    const float total = 0.7f * total0 + 0.3f * total1;
    std::vector<float> row(n), row_cdf(n);
    for (size_t j = 0; j < n; ++j) row[j] = 0.7f * values[j] + 0.3f * values[n + j];
    for (int i = 1; i < 50; ++i) {
        const float u = static_cast<float>(i) / 50.0f;
        float fval, pdf;
        const float x = sample_catmull_rom_2d(nodes1, kNodes, values, cdf, alpha, u, &fval, &pdf);
        // The interpolated row's integral up to x, by the midpoint rule on its spline.
        double integral = 0.0;
        const int steps = 4000;
        for (int k = 0; k < steps; ++k) {
            const float xk = x * (static_cast<float>(k) + 0.5f) / steps;
            integral += static_cast<double>(spline_at(kNodes, row, xk) * x) / steps;
        }
        EXPECT_NEAR(integral / static_cast<double>(total), static_cast<double>(u), 1e-4) << "u " << u;
        EXPECT_NEAR(fval, spline_at(kNodes, row, x), 1e-4f) << "u " << u;
        EXPECT_NEAR(pdf, fval / total, 1e-5f) << "u " << u;
    }
    EXPECT_EQ(sample_catmull_rom_2d(nodes1, kNodes, values, cdf, 1.5f, 0.5f), 0.0f);
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela
