// --target-error's allocation (render/error_allocation.h) on synthetic films whose pixels' errors
// and work are set directly: the scale K is sum sqrt(W C) over the budget N E - F, a block goes on
// while sqrt(W / C) K exceeds its count, and the counts it asks for spend the budget exactly.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/error_allocation.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Sets every pixel of `block` to `n` samples whose halves' means are 1 + d and 1 - d (so mean 1
// and, from the halves, variance of the mean d^2 times 2^m / n) and that traced `rays` rays.
void set_block(Film& film, const PixelBounds& block, uint32_t n, double d, double rays) {
    const double half = double(std::bit_floor(n)) / 2.0;
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x) {
            film.count(x, y) = double(n);
            film.sum(x, y) = {double(n), double(n), double(n)};
            film.squares(x, y) = {double(n), double(n), double(n)};
            film.rays(x, y) = rays;
            PrefixSums& p = film.prefix_sums(x, y);
            const auto a = float((1.0 + d) * half), ab = float((1.0 + d) * half + (1.0 - d) * half);
            p.sum = {{{a, a, a}, {ab, ab, ab}}};
            p.weight = {float(half), float(2.0 * half)};
        }
}

constexpr PixelBounds kLeft{0, 0, 8, 8}, kRight{8, 0, 16, 8};
const std::vector<Tile> kTiles = {Tile{0, 0, 16, 8}};

// Block values as the allocation defines them: W = sum of relative variance times count, C = sum
// of rays per sample plus the overhead, error = sum of relative variance.
struct Expected {
    double w, c, error;
};
Expected expected(const Film& film, const PixelBounds& block) {
    Expected e{0, 0, 0};
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x) {
            const double r = relative_variance_from_halves(film, x, y), n = film.count(x, y);
            e.w += r * n;
            e.c += film.rays(x, y) / n + kSampleOverheadRays;
            e.error += r;
        }
    return e;
}

TEST(ErrorAllocation, ScaleAndDecisionsFollowTheSquareRootRule) {
    Film film(16, 8, false, {}, true);
    set_block(film, kLeft, 16, 0.01, 16 * 2.0);    // quiet, cheap: 2 rays a sample
    set_block(film, kRight, 16, 0.4, 16 * 30.0);   // noisy, expensive: 30 rays a sample
    const double target = 0.02;
    const Expected l = expected(film, kLeft), r = expected(film, kRight);
    const double k = (std::sqrt(l.w * l.c) + std::sqrt(r.w * r.c)) / (128.0 * target);
    EXPECT_NEAR(target_allocation_scale(film, kTiles, 16, target), k, 1e-12 * k);
    // The counts asked for spend the budget exactly: sum W / n = N E.
    const double nl = std::sqrt(l.w / l.c) * k, nr = std::sqrt(r.w / r.c) * k;
    EXPECT_NEAR(l.w / nl + r.w / nr, 128.0 * target, 1e-9 * target);
    // This target asks for more than 16 samples in the noisy block only.
    ASSERT_LT(nl, 16.0);
    ASSERT_GT(nr, 16.0);
    EXPECT_FALSE(block_wants_samples(film, kLeft, 16, k));
    EXPECT_TRUE(block_wants_samples(film, kRight, 16, k));
    // block_active applies it at decision points only (16 is the first without adaptive sampling).
    EXPECT_FALSE(block_active(film, kLeft, 16, std::nullopt, k));
    EXPECT_TRUE(block_active(film, kRight, 16, std::nullopt, k));
    EXPECT_TRUE(block_active(film, kLeft, 16, std::nullopt));  // no target: uniform
    // Costlier samples in the noisy block move samples away from it, as sqrt(W / C) says.
    Film dearer = film;
    set_block(dearer, kRight, 16, 0.4, 16 * 300.0);
    const double k2 = target_allocation_scale(dearer, kTiles, 16, target);
    const Expected r2 = expected(dearer, kRight);
    EXPECT_LT(std::sqrt(r2.w / r2.c) * k2, nr);
}

TEST(ErrorAllocation, StoppedBlocksSpendTheirPartOfTheBudget) {
    Film film(16, 8, false, {}, true);
    set_block(film, kLeft, 16, 0.01, 16 * 2.0);   // stopped at 16
    set_block(film, kRight, 20, 0.4, 20 * 30.0);  // active at 20
    const double target = 0.02;
    const Expected l = expected(film, kLeft), r = expected(film, kRight);
    const double k = std::sqrt(r.w * r.c) / (128.0 * target - l.error);
    EXPECT_NEAR(target_allocation_scale(film, kTiles, 20, target), k, 1e-12 * k);
    // A block whose count is not the pass's start stopped earlier and stays stopped.
    EXPECT_FALSE(block_active(film, kLeft, 20, std::nullopt, k));
    // When the stopped blocks alone spent the budget, nothing with an error stops.
    const double spent = 0.9 * l.error / 128.0;
    EXPECT_EQ(target_allocation_scale(film, kTiles, 20, spent), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(block_wants_samples(film, kRight, 20, std::numeric_limits<double>::infinity()));
}

TEST(ErrorAllocation, ABlockWithoutErrorWantsNoSamples) {
    Film film(16, 8, false, {}, true);
    set_block(film, kLeft, 16, 0.0, 16.0);
    set_block(film, kRight, 16, 0.3, 16 * 5.0);
    const double k = target_allocation_scale(film, kTiles, 16, 1e-3);
    EXPECT_GT(k, 0.0);
    EXPECT_FALSE(block_wants_samples(film, kLeft, 16, k));
    EXPECT_FALSE(block_wants_samples(film, kLeft, 16, std::numeric_limits<double>::infinity()));
}

}  // namespace
}  // namespace candela
