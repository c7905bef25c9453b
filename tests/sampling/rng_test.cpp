// PCG32 against the reference implementation, the per-sample seeding, and the float conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "candela/math/constants.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Mean and variance of n values, accumulated in double.
struct Moments {
    double mean = 0.0, variance = 0.0;
};
Moments moments(const std::vector<float>& v) {
    double sum = 0.0, sum_sq = 0.0;
    for (float x : v) {
        sum += static_cast<double>(x);
        sum_sq += static_cast<double>(x) * static_cast<double>(x);
    }
    double n = static_cast<double>(v.size());
    double mean = sum / n;
    return {mean, sum_sq / n - mean * mean};
}

// Checks that values are uniform on [0, 1) in their first two moments, within 5 sigma: the mean
// has standard deviation sqrt(1/12 / n); the variance estimate sqrt((mu4 - sigma^4) / n) with the
// uniform's fourth central moment mu4 = 1/80.
void expect_uniform_moments(const std::vector<float>& v) {
    double n = static_cast<double>(v.size());
    Moments m = moments(v);
    double exact_mean = 0.5 * (1.0 - 0x1p-24);  // the mean of k 2^-24, k < 2^24
    EXPECT_NEAR(m.mean, exact_mean, 5.0 * std::sqrt(1.0 / 12.0 / n));
    EXPECT_NEAR(m.variance, 1.0 / 12.0, 5.0 * std::sqrt((1.0 / 80.0 - 1.0 / 144.0) / n));
}

// Pearson's correlation of a[i] with b[i]; for independent values 5 sigma is 5 / sqrt(n).
double pair_correlation(const std::vector<float>& a, const std::vector<float>& b) {
    Moments ma = moments(a), mb = moments(b);
    double cov = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        cov += (static_cast<double>(a[i]) - ma.mean) * (static_cast<double>(b[i]) - mb.mean);
    cov /= static_cast<double>(a.size());
    return cov / std::sqrt(ma.variance * mb.variance);
}

TEST(Rng, MatchesPcg32ReferenceOutputs) {
    // pcg32-demo.c of the reference implementation: pcg32_srandom_r(&rng, 42, 54).
    Rng rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (uint32_t e : expected) EXPECT_EQ(rng.next_u32(), e);
}

TEST(Rng, ForSampleIsAPureFunctionOfItsTriple) {
    Rng a = Rng::for_sample(123456, 789, 42);
    Rng b = Rng::for_sample(123456, 789, 42);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_u32(), b.next_u32());
}

TEST(Rng, ForSampleDiffersInEachArgument) {
    auto first_outputs = [](Rng rng) {
        std::vector<uint32_t> out(8);
        for (auto& o : out) o = rng.next_u32();
        return out;
    };
    auto base = first_outputs(Rng::for_sample(10, 20, 30));
    for (Rng other : {Rng::for_sample(11, 20, 30), Rng::for_sample(10, 21, 30),
                      Rng::for_sample(10, 20, 31), Rng::for_sample(20, 10, 30),
                      Rng::for_sample(30, 20, 10)}) {
        auto out = first_outputs(other);
        int equal = 0;
        for (size_t i = 0; i < out.size(); ++i) equal += out[i] == base[i] ? 1 : 0;
        EXPECT_EQ(equal, 0);  // a coincidence has probability 8 / 2^32
    }
}

TEST(Rng, ForSampleHasNoCollisionsOverPixelsSamplesAndSeeds) {
    std::unordered_set<uint64_t> seen;
    for (uint64_t seed = 0; seed < 2; ++seed)
        for (uint64_t pixel = 0; pixel < 256; ++pixel)
            for (uint64_t sample = 0; sample < 256; ++sample) {
                Rng rng = Rng::for_sample(pixel, sample, seed);
                uint64_t first = (static_cast<uint64_t>(rng.next_u32()) << 32) | rng.next_u32();
                EXPECT_TRUE(seen.insert(first).second) << pixel << " " << sample << " " << seed;
            }
}

TEST(Rng, NeighbouringPixelsAndSamplesAreUncorrelated) {
    constexpr int kN = 200000;
    std::vector<float> pixel_a(kN), pixel_b(kN), sample_a(kN), sample_b(kN), all_first(kN);
    for (int i = 0; i < kN; ++i) {
        auto k = static_cast<uint64_t>(i);
        pixel_a[i] = Rng::for_sample(2 * k, 0, 7).next_float();
        pixel_b[i] = Rng::for_sample(2 * k + 1, 0, 7).next_float();
        sample_a[i] = Rng::for_sample(5, 2 * k, 7).next_float();
        sample_b[i] = Rng::for_sample(5, 2 * k + 1, 7).next_float();
        all_first[i] = Rng::for_sample(k, 3, 0).next_float();
    }
    double bound = 5.0 / std::sqrt(static_cast<double>(kN));
    EXPECT_LT(std::abs(pair_correlation(pixel_a, pixel_b)), bound);
    EXPECT_LT(std::abs(pair_correlation(sample_a, sample_b)), bound);
    expect_uniform_moments(all_first);  // the first number over many seeds is uniform too
}

TEST(Rng, UnitFloatConversionStaysBelowOne) {
    EXPECT_EQ(u32_to_unit_float(0u), 0.0f);
    EXPECT_EQ(u32_to_unit_float(0xffffffffu), kOneMinusEpsilon);
    EXPECT_LT(u32_to_unit_float(0xffffffffu), 1.0f);
    EXPECT_EQ(u32_to_unit_float(0x80000000u), 0.5f);
}

// A raw PCG state whose next output is 0xffffffff: the output's bits are bits 27..58 of
// state ^ (state >> 18), so set each bit k to 1 ^ bit k+18, from the top down. The 5 rotation
// bits and the 27 low bits are free.
uint64_t state_with_max_output(uint64_t rotation, uint64_t low_bits) {
    uint64_t s = (rotation << 59) | (low_bits & ((1ull << 27) - 1));
    for (int k = 58; k >= 27; --k) {
        uint64_t partner = k + 18 < 64 ? (s >> (k + 18)) & 1u : 0u;
        s |= (1u ^ partner) << k;
    }
    return s;
}

TEST(Rng, NextFloatNeverReturnsOneEvenFromExtremeStates) {
    for (uint64_t rotation = 0; rotation < 32; ++rotation) {
        Rng rng = Rng::from_raw_state(state_with_max_output(rotation, rotation * 977), 12345);
        Rng copy = rng;
        ASSERT_EQ(copy.next_u32(), 0xffffffffu);
        float f = rng.next_float();
        EXPECT_EQ(f, kOneMinusEpsilon);
        EXPECT_LT(f, 1.0f);
    }
    for (uint64_t state : {uint64_t{0}, ~uint64_t{0}, uint64_t{1} << 63})
        for (uint64_t inc : {uint64_t{1}, ~uint64_t{0}}) {
            Rng rng = Rng::from_raw_state(state, inc);
            for (int i = 0; i < 10000; ++i) {
                float f = rng.next_float();
                ASSERT_GE(f, 0.0f);
                ASSERT_LT(f, 1.0f);
            }
        }
}

TEST(Rng, NextFloatMeanAndVarianceMatchUniformWithinFiveSigma) {
    Rng rng(2024u, 1u);
    std::vector<float> v(1000000);
    for (float& x : v) x = rng.next_float();
    expect_uniform_moments(v);
    // Successive draws are uncorrelated too.
    std::vector<float> even(v.size() / 2), odd(v.size() / 2);
    for (size_t i = 0; i < even.size(); ++i) {
        even[i] = v[2 * i];
        odd[i] = v[2 * i + 1];
    }
    double bound = 5.0 / std::sqrt(static_cast<double>(even.size()));
    EXPECT_LT(std::abs(pair_correlation(even, odd)), bound);
}

TEST(Rng, NextVec2fDrawsXThenY) {
    Rng a(9u, 4u), b(9u, 4u);
    Vec2f v = a.next_vec2f();
    EXPECT_EQ(v.x, b.next_float());
    EXPECT_EQ(v.y, b.next_float());
}

TEST(Rng, AdvanceSkipsExactlyThatManyOutputs) {
    Rng stepped(77u, 5u), jumped(77u, 5u);
    for (int i = 0; i < 1000; ++i) stepped.next_u32();
    jumped.advance(1000);
    EXPECT_EQ(stepped, jumped);
    EXPECT_EQ(stepped.next_u32(), jumped.next_u32());
    jumped.advance(-1001);
    EXPECT_EQ(jumped, Rng(77u, 5u));
}

TEST(Rng, StreamsFromTheSameStateDiffer) {
    Rng a(1u, 1u), b(1u, 2u);
    int equal = 0;
    for (int i = 0; i < 100; ++i) equal += a.next_u32() == b.next_u32() ? 1 : 0;
    EXPECT_LE(equal, 1);
}

}  // namespace
}  // namespace candela
