// The comparison with pbrt-v4's references (bench/block_compare.h) on tiny synthetic images whose
// answers are known by hand: per-channel mean ratios, block luminance differences and their
// quantiles, the dark-block rule, partial blocks, the bounds and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bench/block_compare.h"

namespace candela::bench {
namespace CANDELA_UNITY_ID {

constexpr double kTol = 1e-6;  // float pixels, double arithmetic

// A w x h image whose 16x16 block (bx, by) is the grey block_value(bx, by).
template <class F>
Image grey_blocks(int w, int h, F block_value) {
    Image im(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) im.at(x, y) = Rgb(block_value(x / 16, y / 16));
    return im;
}

// Multiplies every pixel of block (bx, by) by s.
void scale_block(Image& im, int bx, int by, float s) {
    for (int y = by * 16; y < by * 16 + 16; ++y)
        for (int x = bx * 16; x < bx * 16 + 16; ++x) im.at(x, y) *= s;
}

TEST(Quantile, InterpolatesLinearlyBetweenOrderStatisticsAsNumpy) {
    EXPECT_DOUBLE_EQ(quantile({3, 1, 4, 2}, 0.5), 2.5);     // position 1.5
    EXPECT_DOUBLE_EQ(quantile({5, 1, 2, 3, 4}, 0.95), 4.8);  // position 3.8
    EXPECT_DOUBLE_EQ(quantile({5, 1, 2, 3, 4}, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(quantile({5, 1, 2, 3, 4}, 1.0), 5.0);
    EXPECT_DOUBLE_EQ(quantile({7}, 0.95), 7.0);
    EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0.0);
}

TEST(BlockCompare, MeanRatioIsEachChannelsSumOverTheReferencesSum) {
    Image ref(16, 16), test(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            ref.at(x, y) = Rgb(float(x + 1), float(y + 1), 1.0f);
            test.at(x, y) = Rgb(2.0f * float(x + 1), float(y + 1), x < 8 ? 1.0f : 0.5f);
        }
    const BlockComparison c = compare_blocks(test, ref);
    EXPECT_NEAR(c.mean_ratio[0], 2.0, kTol);
    EXPECT_NEAR(c.mean_ratio[1], 1.0, kTol);
    EXPECT_NEAR(c.mean_ratio[2], 0.75, kTol);
}

TEST(BlockCompare, BlockDifferencesAreRelativeToTheReferenceAndSummarizedByQuantiles) {
    // Four blocks of luminance 1, 2, 4, 8, off by +10%, -20%, +30% and 0%.
    const Image ref = grey_blocks(32, 32, [](int bx, int by) { return float(1 << (bx + 2 * by)); });
    Image test = ref;
    scale_block(test, 0, 0, 1.1f);
    scale_block(test, 1, 0, 0.8f);
    scale_block(test, 0, 1, 1.3f);
    const BlockComparison c = compare_blocks(test, ref);
    EXPECT_EQ(c.blocks_total, 4);
    EXPECT_EQ(c.blocks_compared, 4);
    EXPECT_NEAR(c.p50, 0.15, kTol);                   // sorted 0, 0.1, 0.2, 0.3 at 1.5
    EXPECT_NEAR(c.p95, 0.2 + 0.85 * 0.1, kTol);       // at 2.85
    EXPECT_NEAR(c.max, 0.3, kTol);
}

TEST(BlockCompare, BlocksCompareByRec709LuminanceNotPerChannel) {
    const Image ref = grey_blocks(16, 16, [](int, int) { return 1.0f; });
    // Red up by 0.1 and green down so that luminance stays 1: no block difference, though the
    // channel means differ.
    Image balanced = ref;
    for (Rgb& p : balanced.pixels) p = Rgb(1.1f, 1.0f - 0.1f * 0.2126f / 0.7152f, 1.0f);
    const BlockComparison same = compare_blocks(balanced, ref);
    EXPECT_NEAR(same.max, 0.0, kTol);
    EXPECT_NEAR(same.mean_ratio[0], 1.1, kTol);
    // Blue up by 1 moves luminance by its weight.
    Image bluer = ref;
    for (Rgb& p : bluer.pixels) p = Rgb(1.0f, 1.0f, 2.0f);
    EXPECT_NEAR(compare_blocks(bluer, ref).max, 0.0722, kTol);
}

TEST(BlockCompare, BlocksDarkerThanFivePercentOfTheMedianAreLeftOut) {
    // Reference blocks 1, 1, 1, 0.06 and 0.04: the median is 1, so the cut is 0.05; the block of
    // 0.06 is kept and the one of 0.04 left out.
    const float values[5] = {1.0f, 1.0f, 1.0f, 0.06f, 0.04f};
    const Image ref = grey_blocks(80, 16, [&](int bx, int) { return values[bx]; });
    Image test = ref;
    scale_block(test, 3, 0, 1.5f);   // kept: a 50% difference
    scale_block(test, 4, 0, 10.0f);  // left out, though 900% off
    const BlockComparison c = compare_blocks(test, ref);
    EXPECT_EQ(c.blocks_total, 5);
    EXPECT_EQ(c.blocks_compared, 4);
    EXPECT_NEAR(c.max, 0.5, kTol);
    // The dark fraction is a parameter: at 1% the darkest block counts too.
    EXPECT_NEAR(compare_blocks(test, ref, 16, 0.01).max, 9.0, 1e-5);
}

TEST(BlockCompare, PartialBlocksAtTheEdgesCountInTheMeansOnly) {
    // 40x20: two whole blocks; the last 8 columns and 4 rows are partial.
    const Image ref = grey_blocks(40, 20, [](int, int) { return 1.0f; });
    Image test = ref;
    for (int y = 0; y < 20; ++y)
        for (int x = 32; x < 40; ++x) test.at(x, y) = Rgb(3.0f);
    for (int x = 0; x < 32; ++x) test.at(x, 17) = Rgb(3.0f);
    const BlockComparison c = compare_blocks(test, ref);
    EXPECT_EQ(c.blocks_total, 2);
    EXPECT_NEAR(c.max, 0.0, kTol);
    const double changed = 8.0 * 20.0 + 32.0;  // pixels set to 3 instead of 1
    EXPECT_NEAR(c.mean_ratio[1], (800.0 + 2.0 * changed) / 800.0, kTol);
}

TEST(BlockCompare, BoundsHoldOnEveryChannelsBiasAndTheP95) {
    BlockComparison c;
    c.mean_ratio = {1.009, 0.991, 1.0};
    c.p95 = 0.019;
    EXPECT_TRUE(within_bounds(c, 0.01, 0.02));
    c.mean_ratio[2] = 1.011;
    EXPECT_FALSE(within_bounds(c, 0.01, 0.02));
    c.mean_ratio[2] = 0.989;
    EXPECT_FALSE(within_bounds(c, 0.01, 0.02));
    c.mean_ratio[2] = 1.0;
    c.p95 = 0.021;
    EXPECT_FALSE(within_bounds(c, 0.01, 0.02));
    c.p95 = 0.0;
    c.mean_ratio[0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(within_bounds(c, 0.01, 0.02));
}

TEST(BlockCompare, RefusesImagesOfDifferentSizesOrABlackReferenceChannel) {
    EXPECT_THROW(compare_blocks(Image(32, 16), Image(16, 32)), std::runtime_error);
    EXPECT_THROW(compare_blocks(Image(8, 8), Image(8, 8)), std::runtime_error);  // a block larger than the image
    Image ref = grey_blocks(16, 16, [](int, int) { return 1.0f; });
    for (Rgb& p : ref.pixels) p.b = 0.0f;
    EXPECT_THROW(compare_blocks(ref, ref), std::runtime_error);
}

}  // namespace
}  // namespace candela::bench

namespace candela::bench {
namespace CANDELA_UNITY_ID {

// block_means keeps what compare_blocks reads: comparing the means with block 1 gives the same
// figures as comparing the images with block 16.
TEST(BlockMeans, ComparisonOfMeansEqualsComparisonOfImages) {
    Image a(32, 48), b(32, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 32; ++x) {
            a.at(x, y) = Rgb(0.1f + 0.01f * float(x), 0.2f + 0.003f * float(y), 0.5f);
            b.at(x, y) = Rgb(0.1f + 0.011f * float(x), 0.2f + 0.0031f * float(y), 0.45f + 0.001f * float(x + y));
        }
    const BlockComparison full = compare_blocks(a, b, 16);
    const BlockComparison means = compare_blocks(block_means(a, 16), block_means(b, 16), 1);
    EXPECT_EQ(means.blocks_total, full.blocks_total);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(means.mean_ratio[size_t(c)], full.mean_ratio[size_t(c)], 1e-6);
    EXPECT_NEAR(means.p95, full.p95, 1e-6);
    EXPECT_NEAR(means.max, full.max, 1e-6);
    EXPECT_EQ(block_means(a, 16).width, 2);
    EXPECT_EQ(block_means(a, 16).height, 3);
}

}  // namespace
}  // namespace candela::bench
