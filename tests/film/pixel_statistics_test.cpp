// The per-pixel error estimates of a film with statistics (film/pixel_statistics.h) on synthetic
// pixels whose samples have a known distribution: f(u) = u^2 of the sampler's first number, with
// mean 1/3 and variance 4/45. Bounds are 4 standard deviations of the estimator, derived below,
// with fixed seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/sampling/sampler.h"

namespace candela {
namespace {

constexpr int kSide = 64;  // 4096 pixels
constexpr uint32_t kSpp = 16;
constexpr double kMean = 1.0 / 3.0;
constexpr double kVariance = 1.0 / 5.0 - 1.0 / 9.0;  // E[u^4] - E[u^2]^2
// The central fourth moment of u^2: E[(X - m)^4] from E[X^k] = 1/(2k + 1).
constexpr double kFourthMoment = 1.0 / 9.0 - 4.0 * kMean / 7.0 + 6.0 * kMean * kMean / 5.0 - 3.0 * kMean * kMean * kMean * kMean;

// A film whose pixel p holds kSpp samples f(u) in all three channels, u the first number of
// sample s of pixel p; also the pixel means.
Film synthetic_film(SamplerType type, uint64_t seed, std::vector<double>& means) {
    Film film(kSide, kSide, false, {}, true);
    means.clear();
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const uint64_t pixel = uint64_t(y) * kSide + uint64_t(x);
            for (uint32_t s = 0; s < kSpp; ++s) {
                const float u = Sampler(type, pixel, s, seed).next_float();
                const Rgb v(u * u, u * u, u * u);
                add_to_sum(film.sum(x, y), v);
                add_square_to_sum(film.squares(x, y), v);
                film.count(x, y) += 1.0;
            }
            means.push_back(film.sum(x, y)[0] / kSpp);
        }
    return film;
}

double mean_estimate(const Film& film) {
    double total = 0.0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) total += variance_of_mean(film, x, y)[1];
    return total / double(kSide * kSide);
}

// The variance of the pixel means across pixels: each pixel's samples are randomized
// independently, so this measures the true variance of one pixel's mean.
double spread_of_means(const std::vector<double>& means) {
    double m = 0.0;
    for (double v : means) m += v;
    m /= double(means.size());
    double s = 0.0;
    for (double v : means) s += (v - m) * (v - m);
    return s / double(means.size() - 1);
}

// The standard deviation of the average of kSide^2 per-pixel estimates s^2 / n, where s^2 is the
// unbiased sample variance of n iid samples: Var(s^2) = (mu4 - sigma^4 (n - 3) / (n - 1)) / n.
double estimate_sd() {
    const double n = kSpp;
    const double var_s2 = (kFourthMoment - kVariance * kVariance * (n - 3.0) / (n - 1.0)) / n;
    return std::sqrt(var_s2) / n / double(kSide);
}

TEST(PixelStatistics, IndependentSamplesGiveAnUnbiasedVarianceOfTheMean) {
    std::vector<double> means;
    const Film film = synthetic_film(SamplerType::kIndependent, 7, means);
    const double truth = kVariance / kSpp;
    EXPECT_NEAR(mean_estimate(film), truth, 4.0 * estimate_sd());
    // The spread of the means agrees too (its relative sd is sqrt(2 / (pixels - 1)) ~ 2.2%, and the
    // means' fourth moment adds little at 16 samples).
    EXPECT_NEAR(spread_of_means(means), truth, 4.0 * 0.025 * truth);
}

// With Owen-scrambled Sobol samples the sample variance still averages to the per-sample variance
// less the mean's (E[s^2] = n / (n - 1) (sigma^2 - V), V the true variance of the mean, measured
// from the spread of the means), so the estimate s^2 / n is an upper bound of V that does not
// shrink with the net's faster convergence: conservative, never optimistic.
TEST(PixelStatistics, SobolSamplesGiveAConservativeVarianceOfTheMean) {
    std::vector<double> means;
    const Film film = synthetic_film(SamplerType::kSobol, 7, means);
    const double v = spread_of_means(means);
    const double expected = (kVariance - v) / (kSpp - 1.0);
    // The net's samples are more even than iid ones, so the iid sd bounds the estimator's.
    EXPECT_NEAR(mean_estimate(film), expected, 4.0 * estimate_sd());
    EXPECT_LT(v, 0.1 * kVariance / kSpp);  // the net's mean is far better than Monte Carlo's
    EXPECT_GT(mean_estimate(film), 5.0 * v);
}

TEST(PixelStatistics, RelativeVarianceAndRelmseFollowTheBenchmarkDefinition) {
    Film film(2, 1, false, {}, true);
    for (const float value : {1.0f, 3.0f}) {  // pixel 0: samples 1 and 3
        add_to_sum(film.sum(0, 0), Rgb(value, value, value));
        add_square_to_sum(film.squares(0, 0), Rgb(value, value, value));
        film.count(0, 0) += 1.0;
    }
    // Mean 2, sample variance 2, variance of the mean 1; relMSE term 1 / (4 + 0.01).
    EXPECT_DOUBLE_EQ(variance_of_mean(film, 0, 0)[0], 1.0);
    EXPECT_DOUBLE_EQ(relative_variance(film, 0, 0), 1.0 / 4.01);
    EXPECT_TRUE(std::isinf(relative_variance(film, 1, 0)));  // no samples yet
    EXPECT_TRUE(std::isinf(estimated_relmse(film)));
    EXPECT_DOUBLE_EQ(estimated_relmse(film, {PixelBounds{0, 0, 1, 1}}), 1.0 / 4.01);
    const SppSummary spp = spp_summary(film);
    EXPECT_EQ(spp.min, 0.0);
    EXPECT_EQ(spp.max, 2.0);
    EXPECT_EQ(spp.mean, 1.0);
    EXPECT_EQ(spp_image(film).pixels[0].r, 2.0f);
    EXPECT_EQ(variance_image(film).pixels[0].g, 1.0f);
}

// The statistics travel with the film's values (what checkpoints, shard parts and MPI carry).
TEST(PixelStatistics, RegionsCarryTheStatistics) {
    Film film(3, 2, true, {}, true);
    EXPECT_EQ(film.values_per_pixel(), 8);
    EXPECT_EQ(Film(3, 2, false, {}, true).values_per_pixel(), 7);
    EXPECT_EQ(Film(3, 2).values_per_pixel(), 3);
    film.sum(2, 1) = {1, 2, 3};
    film.weight(2, 1) = 4;
    film.squares(2, 1) = {5, 6, 7};
    film.count(2, 1) = 8;
    std::vector<double> values(8);
    film.read_region(PixelBounds{2, 1, 3, 2}, values.data());
    EXPECT_EQ(values, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
    Film copy(3, 2, true, {}, true);
    copy.write_region(PixelBounds{2, 1, 3, 2}, values.data());
    EXPECT_EQ(copy.squares(2, 1), film.squares(2, 1));
    EXPECT_EQ(copy.count(2, 1), 8.0);
}

}  // namespace
}  // namespace candela
