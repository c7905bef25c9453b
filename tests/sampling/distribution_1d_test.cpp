// Deterministic properties of Distribution1D: probabilities proportional to the weights, zero
// weights never drawn (whatever u, even out of range), empty when nothing can be drawn, the
// remapped u, the continuous variant, and ten million weights. The frequencies are tested by
// chi-square in distribution_1d_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "candela/math/constants.h"
#include "candela/sampling/distribution_1d.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Every float in [0, 1) that is a multiple of 1/n, plus 0, the largest float below 1, and the
// floats just around each CDF edge of `d` (where an off-by-one would show).
std::vector<float> probe_us(const Distribution1D& d, int n) {
    std::vector<float> us{0.0f, kOneMinusEpsilon};
    for (int i = 0; i < n; ++i) us.push_back(static_cast<float>(i) / static_cast<float>(n));
    double cumulative = 0.0;
    for (size_t i = 0; i < d.size(); ++i) {
        cumulative += static_cast<double>(d.probability(i));
        auto edge = static_cast<float>(cumulative);
        for (float u : {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 1.0f)})
            if (u >= 0.0f && u < 1.0f) us.push_back(u);
    }
    return us;
}

TEST(Distribution1D, ProbabilitiesAreProportionalToWeights) {
    std::vector<float> w{1.0f, 3.0f, 0.0f, 4.0f};
    Distribution1D d(w);
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d.size(), 4u);
    EXPECT_DOUBLE_EQ(d.total(), 8.0);
    EXPECT_FLOAT_EQ(d.probability(0), 0.125f);
    EXPECT_FLOAT_EQ(d.probability(1), 0.375f);
    EXPECT_EQ(d.probability(2), 0.0f);
    EXPECT_FLOAT_EQ(d.probability(3), 0.5f);
    EXPECT_EQ(d.probability(4), 0.0f);  // out of range
}

TEST(Distribution1D, InvertsTheCdfAndRemapsU) {
    Distribution1D d(std::vector<float>{1.0f, 3.0f, 0.0f, 4.0f});
    // CDF edges 0, 1/8, 1/2, 1/2, 1.
    DiscreteSample a = d.sample_discrete(0.0625f);
    EXPECT_EQ(a.index, 0u);
    EXPECT_FLOAT_EQ(a.u_remapped, 0.5f);
    EXPECT_FLOAT_EQ(a.probability, 0.125f);
    DiscreteSample b = d.sample_discrete(0.125f);  // an edge belongs to the interval it starts
    EXPECT_EQ(b.index, 1u);
    EXPECT_EQ(b.u_remapped, 0.0f);
    DiscreteSample c = d.sample_discrete(0.5f);  // skips the empty interval of weight 0
    EXPECT_EQ(c.index, 3u);
    EXPECT_EQ(c.u_remapped, 0.0f);
    DiscreteSample e = d.sample_discrete(0.75f);
    EXPECT_EQ(e.index, 3u);
    EXPECT_FLOAT_EQ(e.u_remapped, 0.5f);
    EXPECT_FLOAT_EQ(e.probability, 0.5f);
}

TEST(Distribution1D, BranchFreeSearchMatchesALinearScanForEverySize) {
    // The CDF rebuilt as the constructor documents it (double prefix sums over the total, 1 from
    // the end of the last positive weight on), searched by a plain scan for the first edge > u.
    Rng rng(3, 4);
    for (size_t n = 1; n <= 40; ++n) {
        std::vector<float> w(n);
        for (float& x : w) x = rng.next_float() < 0.3f ? 0.0f : rng.next_float();
        w[rng.next_u32() % n] = 1.0f;  // at least one positive weight
        Distribution1D d(w);
        std::vector<double> prefix(n + 1, 0.0);
        size_t last_positive = 0;
        for (size_t i = 0; i < n; ++i) {
            prefix[i + 1] = prefix[i] + double(w[i]);
            if (w[i] > 0.0f) last_positive = i;
        }
        std::vector<float> cdf(n + 1, 0.0f);
        for (size_t i = 1; i <= n; ++i) cdf[i] = i > last_positive ? 1.0f : float(prefix[i] / prefix[n]);
        for (int k = 0; k < 2000; ++k) {
            // Random u, and u exactly on the CDF's edges below 1 (where the comparisons decide).
            float u = k % 2 == 0 ? rng.next_float() : cdf[size_t(rng.next_u32() % n)];
            if (u >= 1.0f) u = rng.next_float();
            size_t expected = 0;
            while (expected + 1 <= n && cdf[expected + 1] <= u) ++expected;
            ASSERT_EQ(d.sample_discrete(u).index, expected) << "n = " << n << ", u = " << u;
        }
    }
}

TEST(Distribution1D, SampledProbabilityEqualsProbabilityOfIndex) {
    Distribution1D d(std::vector<float>{0.3f, 0.0f, 1.7f, 2.9f, 0.01f});
    for (float u : probe_us(d, 997)) {
        DiscreteSample s = d.sample_discrete(u);
        EXPECT_EQ(s.probability, d.probability(s.index)) << "u = " << u;
        EXPECT_GE(s.u_remapped, 0.0f);
        EXPECT_LT(s.u_remapped, 1.0f);
    }
}

TEST(Distribution1D, NeverReturnsAZeroWeightIndex) {
    // Zeros first, last, in runs, and around a weight far below float resolution of the CDF.
    std::vector<float> w{0.0f, 0.0f, 2.0f, 0.0f, 0.0f, 0.0f, 1e-12f, 0.0f, 5.0f, 0.0f, 1.0f, 0.0f, 0.0f};
    Distribution1D d(w);
    for (float u : probe_us(d, 4099)) {
        DiscreteSample s = d.sample_discrete(u);
        ASSERT_LT(s.index, w.size());
        EXPECT_GT(w[s.index], 0.0f) << "u = " << u << " gave index " << s.index;
    }
}

TEST(Distribution1D, OutOfRangeUStillGivesAPositiveWeight) {
    Distribution1D d(std::vector<float>{0.0f, 1.0f, 2.0f, 0.0f});
    for (float u : {-1.0f, -0.0f, 1.0f, 2.5f, kInfinity, -kInfinity, std::numeric_limits<float>::quiet_NaN()}) {
        DiscreteSample s = d.sample_discrete(u);
        EXPECT_TRUE(s.index == 1u || s.index == 2u) << "u = " << u << " gave index " << s.index;
        EXPECT_GE(s.u_remapped, 0.0f);
        EXPECT_LT(s.u_remapped, 1.0f);
    }
    EXPECT_EQ(d.sample_discrete(-1.0f).index, 1u);  // below: the first positive weight
    EXPECT_EQ(d.sample_discrete(1.0f).index, 2u);   // above: the last positive weight
}

TEST(Distribution1D, AllZeroOrNoWeightsIsEmpty) {
    EXPECT_TRUE(Distribution1D().empty());
    EXPECT_TRUE(Distribution1D(std::vector<float>{}).empty());
    Distribution1D zeros(std::vector<float>{0.0f, 0.0f, 0.0f});
    EXPECT_TRUE(zeros.empty());
    EXPECT_EQ(zeros.size(), 3u);
    EXPECT_EQ(zeros.total(), 0.0);
    EXPECT_EQ(zeros.probability(1), 0.0f);
    EXPECT_EQ(zeros.pdf_continuous(0.5f), 0.0f);
}

TEST(Distribution1D, NegativeAndNonFiniteWeightsCountAsZero) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> w{-3.0f, 1.0f, nan, kInfinity, 3.0f, -kInfinity};
    Distribution1D d(w);
    EXPECT_DOUBLE_EQ(d.total(), 4.0);
    EXPECT_FLOAT_EQ(d.probability(1), 0.25f);
    EXPECT_FLOAT_EQ(d.probability(4), 0.75f);
    for (size_t i : {0u, 2u, 3u, 5u}) EXPECT_EQ(d.probability(i), 0.0f);
    for (float u : probe_us(d, 513)) {
        uint32_t i = d.sample_discrete(u).index;
        EXPECT_TRUE(i == 1u || i == 4u) << "u = " << u << " gave index " << i;
    }
    EXPECT_TRUE(Distribution1D(std::vector<float>{-1.0f, nan}).empty());
}

TEST(Distribution1D, ContinuousSampleStaysInItsBinWithItsDensity) {
    // 37 bins (not a power of two, so bin edges are not floats) with zero bins among them.
    std::vector<float> w(37);
    for (size_t i = 0; i < w.size(); ++i) w[i] = i % 5 == 2 ? 0.0f : 1.0f + static_cast<float>(i % 7);
    Distribution1D d(w);
    float previous = -1.0f;
    for (int k = 0; k < 20000; ++k) {
        float u = static_cast<float>(k) / 20000.0f;
        ContinuousSample s = d.sample_continuous(u);
        ASSERT_GE(s.x, 0.0f);
        ASSERT_LT(s.x, 1.0f);
        EXPECT_EQ(static_cast<size_t>(static_cast<double>(s.x) * 37.0), s.index) << "u = " << u;
        EXPECT_GT(w[s.index], 0.0f);
        EXPECT_EQ(s.pdf, d.pdf_continuous(s.x));
        EXPECT_FLOAT_EQ(s.pdf, static_cast<float>(static_cast<double>(w[s.index]) * 37.0 / d.total()));
        EXPECT_GE(s.x, previous) << "inversion is monotone in u";
        previous = s.x;
    }
    EXPECT_EQ(d.pdf_continuous(-0.1f), 0.0f);
    EXPECT_EQ(d.pdf_continuous(1.0f), 0.0f);
}

TEST(Distribution1D, ContinuousDensityIntegratesToOne) {
    Distribution1D d(std::vector<float>{0.5f, 0.0f, 2.0f, 1.25f, 0.0f, 3.0f});
    // Midpoint rule on a grid that refines every bin: exact for a piecewise-constant density.
    constexpr int kSteps = 6000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i)
        sum += static_cast<double>(d.pdf_continuous(static_cast<float>((i + 0.5) / kSteps))) / kSteps;
    EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(Distribution1D, TenMillionWeightsKeepTheirProportions) {
    // Mesh-like areas spanning six decades, with a zero-area triangle every 1000.
    constexpr size_t kN = 10'000'000;
    std::vector<float> w(kN);
    Rng rng(7, 1);
    for (size_t i = 0; i < kN; ++i) w[i] = i % 1000 == 999 ? 0.0f : std::pow(10.0f, -6.0f * rng.next_float());
    double exact_total = 0.0;
    for (float x : w) exact_total += static_cast<double>(x);

    Distribution1D d(w);
    EXPECT_NEAR(d.total(), exact_total, 1e-9 * exact_total);
    // The last weight's probability is still weight / total (a float running sum would have
    // stopped growing long before).
    EXPECT_FLOAT_EQ(d.probability(kN - 2), static_cast<float>(static_cast<double>(w[kN - 2]) / exact_total));

    // A region's share of the samples follows its share of the weight: the first tenth of the
    // indices, by inversion of a stratified u.
    constexpr int kSamples = 200'000;
    double first_tenth = 0.0;
    for (size_t i = 0; i < kN / 10; ++i) first_tenth += static_cast<double>(w[i]);
    int in_first_tenth = 0;
    for (int k = 0; k < kSamples; ++k) {
        float u = (static_cast<float>(k) + 0.5f) / static_cast<float>(kSamples);
        DiscreteSample s = d.sample_discrete(u);
        ASSERT_GT(w[s.index], 0.0f) << "u = " << u;
        if (s.index < kN / 10) ++in_first_tenth;
    }
    // Stratified u: the count is off by at most the strata cut by the region's two CDF edges.
    EXPECT_NEAR(static_cast<double>(in_first_tenth) / kSamples, first_tenth / exact_total, 2.0 / kSamples);
}

}  // namespace
}  // namespace candela
