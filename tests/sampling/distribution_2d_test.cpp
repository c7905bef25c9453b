// Distribution2D: densities proportional to the weights, samples that report the density of the
// point they return, and zero-weight cells that are never drawn.
#include <gtest/gtest.h>

#include <vector>

#include "candela/sampling/distribution_2d.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// 4 x 3 weights with a zero row (row 1) and zero cells in the others.
const std::vector<float> kWeights = {1.0f, 0.0f, 2.0f, 3.0f,   //
                                     0.0f, 0.0f, 0.0f, 0.0f,   //
                                     0.5f, 4.0f, 0.0f, 1.5f};  // total 12

TEST(Distribution2D, PdfIsTheCellWeightTimesCellCountOverTotal) {
    Distribution2D d(kWeights, 4, 3);
    EXPECT_EQ(d.width(), 4);
    EXPECT_EQ(d.height(), 3);
    EXPECT_DOUBLE_EQ(d.total(), 12.0);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            Vec2f centre((static_cast<float>(x) + 0.5f) / 4.0f, (static_cast<float>(y) + 0.5f) / 3.0f);
            float expected = kWeights[static_cast<size_t>(y * 4 + x)] * 12.0f / 12.0f;
            EXPECT_NEAR(d.pdf(centre), expected, 1e-6f) << x << ", " << y;
        }
}

TEST(Distribution2D, PdfIsZeroOutsideTheUnitSquare) {
    Distribution2D d(kWeights, 4, 3);
    EXPECT_EQ(d.pdf(Vec2f(-0.1f, 0.5f)), 0.0f);
    EXPECT_EQ(d.pdf(Vec2f(0.1f, 1.0f)), 0.0f);
    EXPECT_EQ(d.pdf(Vec2f(1.0f, 0.1f)), 0.0f);
    EXPECT_EQ(d.pdf(Vec2f(0.1f, -0.01f)), 0.0f);
}

TEST(Distribution2D, SamplesReportThePdfOfTheirPointAndAvoidZeroCells) {
    Distribution2D d(kWeights, 4, 3);
    Rng rng(7, 1);
    for (int i = 0; i < 20000; ++i) {
        Vec2f u(rng.next_float(), rng.next_float());
        Distribution2DSample s = d.sample(u);
        ASSERT_TRUE(s.uv.x >= 0.0f && s.uv.x < 1.0f && s.uv.y >= 0.0f && s.uv.y < 1.0f);
        ASSERT_EQ(s.pdf, d.pdf(s.uv));
        auto x = static_cast<size_t>(s.uv.x * 4.0f), y = static_cast<size_t>(s.uv.y * 3.0f);
        ASSERT_GT(kWeights[y * 4 + x], 0.0f) << "sampled a zero cell at " << x << ", " << y;
    }
}

TEST(Distribution2D, ExtremeUStayInsideTheSquare) {
    Distribution2D d(kWeights, 4, 3);
    for (float ux : {0.0f, 0.5f, kOneMinusEpsilon})
        for (float uy : {0.0f, 0.5f, kOneMinusEpsilon}) {
            Distribution2DSample s = d.sample(Vec2f(ux, uy));
            EXPECT_TRUE(s.uv.x >= 0.0f && s.uv.x < 1.0f && s.uv.y >= 0.0f && s.uv.y < 1.0f);
            EXPECT_GT(s.pdf, 0.0f);
            EXPECT_EQ(s.pdf, d.pdf(s.uv));
        }
}

TEST(Distribution2D, SamplingIsMonotoneInEachCoordinate) {
    Distribution2D d(kWeights, 4, 3);
    float previous_v = -1.0f;
    for (int i = 0; i < 100; ++i) {
        float v = d.sample(Vec2f(0.5f, static_cast<float>(i) / 100.0f)).uv.y;
        EXPECT_GE(v, previous_v);
        previous_v = v;
    }
    float previous_u = -1.0f;
    for (int i = 0; i < 100; ++i) {
        float u = d.sample(Vec2f(static_cast<float>(i) / 100.0f, 0.1f)).uv.x;
        EXPECT_GE(u, previous_u);
        previous_u = u;
    }
}

TEST(Distribution2D, PdfIntegratesToOne) {
    std::vector<float> w(16 * 8);
    for (size_t i = 0; i < w.size(); ++i) w[i] = static_cast<float>((i * 13) % 7);
    Distribution2D d(w, 16, 8);
    // The pdf is constant on cells, so the midpoint of each cell integrates it exactly.
    double sum = 0.0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            sum += static_cast<double>(d.pdf(Vec2f((static_cast<float>(x) + 0.5f) / 16.0f,
                                                   (static_cast<float>(y) + 0.5f) / 8.0f))) / 128.0;
    EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(Distribution2D, AllZeroOrNoWeightsIsEmpty) {
    std::vector<float> zeros(6, 0.0f);
    Distribution2D d(zeros, 3, 2);
    EXPECT_TRUE(d.empty());
    EXPECT_EQ(d.pdf(Vec2f(0.5f, 0.5f)), 0.0f);
    EXPECT_TRUE(Distribution2D().empty());
    std::vector<float> bad = {-1.0f, std::nanf(""), kInfinity, 0.0f};
    EXPECT_TRUE(Distribution2D(bad, 2, 2).empty());
}

TEST(Distribution2D, MemoryIsAboutEightBytesPerCell) {
    std::vector<float> w(64 * 32, 1.0f);
    Distribution2D d(w, 64, 32);
    EXPECT_GE(d.memory_bytes(), w.size() * 8);
    EXPECT_LE(d.memory_bytes(), w.size() * 8 + 33 * 200);
}

}  // namespace
}  // namespace candela
