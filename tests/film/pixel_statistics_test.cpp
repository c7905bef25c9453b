// The per-pixel error estimates of a film with statistics (film/pixel_statistics.h) on synthetic
// pixels whose samples have a known distribution: f(u) = u^2 of the sampler's first number, with
// mean 1/3 and variance 4/45; both estimates (from the squares and from the halves). Bounds are 4 standard deviations of the estimator, derived below,
// with fixed seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/sampling/sampler.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSide = 64;  // 4096 pixels
constexpr uint32_t kSpp = 16;
constexpr double kMean = 1.0 / 3.0;
constexpr double kVariance = 1.0 / 5.0 - 1.0 / 9.0;  // E[u^4] - E[u^2]^2
// The central fourth moment of u^2: E[(X - m)^4] from E[X^k] = 1/(2k + 1).
constexpr double kFourthMoment =
    1.0 / 9.0 - 4.0 * kMean / 7.0 + 6.0 * kMean * kMean / 5.0 - 3.0 * kMean * kMean * kMean * kMean;

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
                film.prefix_sums(x, y).after_sample(s, film.sum(x, y), film.count(x, y));
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

// The per-pixel estimates from the halves (channel g), one per pixel.
std::vector<double> halves_estimates(const Film& film) {
    std::vector<double> e;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) e.push_back(variance_of_mean_from_halves(film, x, y)[1]);
    return e;
}

double average(const std::vector<double>& v) {
    double total = 0.0;
    for (double x : v) total += x;
    return total / double(v.size());
}

// The means of the first halves' samples (kSpp / 2 of them) across pixels.
std::vector<double> first_half_means(const Film& film) {
    std::vector<double> m;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) m.push_back(double(film.prefix_sums(x, y).sum[0][1]) / (kSpp / 2));
    return m;
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

// The estimate from the halves, (A - B)^2 / 4 with A and B the means of samples [0, 8) and
// [8, 16): for independent samples E[(A - B)^2] / 4 = (sigma^2 / 8) / 2 = sigma^2 / 16, unbiased.
// Its sd over the pixels: with D = (A - B) / 2, Var(D^2) = 2 V^2 + kappa4(D), V = sigma^2 / 16 and
// kappa4(D) = kappa4(f) / 16^3 (D is a sum of 16 samples over 16).
TEST(PixelStatistics, IndependentSamplesGiveAnUnbiasedVarianceOfTheMeanFromTheHalves) {
    std::vector<double> means;
    const Film film = synthetic_film(SamplerType::kIndependent, 11, means);
    const double truth = kVariance / kSpp;
    const double kappa4 = kFourthMoment - 3.0 * kVariance * kVariance;
    const double sd = std::sqrt((2.0 * truth * truth + kappa4 / (kSpp * kSpp * kSpp)) / double(kSide * kSide));
    EXPECT_NEAR(average(halves_estimates(film)), truth, 4.0 * sd);
}

// For Owen-scrambled Sobol samples each half is a scrambled 8-point net, as good as the first
// (in the first dimension both put one point in each eighth), so Var(A) = Var(B) = V8, and
// V16 = (2 V8 + 2 Cov(A, B)) / 4; then E[(A - B)^2] / 4 = V8 - V16, exactly. V8 and V16 are
// measured from the spread of the first halves' and the whole means across pixels. With the
// net's fast convergence that is far below the squares' estimate (which stays at Monte Carlo's
// sigma^2 / 16) and above V16 (conservative): the reason the image's estimate uses the halves.
TEST(PixelStatistics, SobolSamplesGiveACloseConservativeVarianceOfTheMeanFromTheHalves) {
    std::vector<double> means;
    const Film film = synthetic_film(SamplerType::kSobol, 11, means);
    const double v16 = spread_of_means(means), v8 = spread_of_means(first_half_means(film));
    const std::vector<double> e = halves_estimates(film);
    const double estimate = average(e);
    // Bound: 4 sd of the estimate's average (its spread across pixels over sqrt(pixels)) and of
    // the two spreads (relative sd about sqrt(2 / pixels) each, as for near-normal means).
    double spread = 0.0;
    for (double x : e) spread += (x - estimate) * (x - estimate);
    const double pixels = double(kSide * kSide);
    const double se = std::sqrt(spread / (pixels - 1.0) / pixels);
    const double bound = 4.0 * std::sqrt(se * se + 2.0 / pixels * (v8 * v8 + v16 * v16));
    EXPECT_NEAR(estimate, v8 - v16, bound);
    EXPECT_GT(estimate, v16);
    EXPECT_LT(estimate, 0.2 * mean_estimate(film));
}

TEST(PixelStatistics, RelativeVarianceAndRelmseFollowTheBenchmarkDefinitionWithARobustValue) {
    Film film(2, 1, false, {}, true);
    for (const float value : {1.0f, 3.0f}) {  // pixel 0: samples 1 and 3
        add_to_sum(film.sum(0, 0), Rgb(value, value, value));
        add_square_to_sum(film.squares(0, 0), Rgb(value, value, value));
        film.count(0, 0) += 1.0;
        film.prefix_sums(0, 0).after_sample(uint32_t(film.count(0, 0)) - 1, film.sum(0, 0), film.count(0, 0));
    }
    // Mean 2, sample variance 2, variance of the mean 1. From the halves (1 and 3): (1 - 3)^2 / 4 = 1
    // too. The relative error's value: the median of the neighbourhood's means (2 and pixel 1's 0)
    // is 1, the smaller half's mean 1, so the relMSE term is 1 / (1 + 0.01).
    EXPECT_DOUBLE_EQ(variance_of_mean(film, 0, 0)[0], 1.0);
    EXPECT_DOUBLE_EQ(variance_of_mean_from_halves(film, 0, 0)[0], 1.0);
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 0, 0)[0], 1.0);
    EXPECT_DOUBLE_EQ(relative_variance(film, 0, 0), 1.0 / 1.01);
    EXPECT_DOUBLE_EQ(relative_variance_from_halves(film, 0, 0), 1.0 / 1.01);
    // A third sample, 2: the halves are still those of the first two (the last power of two, mean
    // M = 2, var(M) = 1); the tail T = 2 adds (T - M)^2 - var(M) = -1 for its own variance:
    // (2/3)^2 * 1 + (1/3)^2 * (-1) = 1/3, here the squares' estimate too.
    add_to_sum(film.sum(0, 0), Rgb(2.0f, 2.0f, 2.0f));
    add_square_to_sum(film.squares(0, 0), Rgb(2.0f, 2.0f, 2.0f));
    film.count(0, 0) += 1.0;
    film.prefix_sums(0, 0).after_sample(2, film.sum(0, 0), film.count(0, 0));
    EXPECT_DOUBLE_EQ(variance_of_mean_from_halves(film, 0, 0)[0], 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(variance_of_mean(film, 0, 0)[0], 1.0 / 3.0);  // sample variance 1, over 3
    EXPECT_TRUE(std::isinf(relative_variance(film, 1, 0)));        // no samples yet
    EXPECT_TRUE(std::isinf(estimated_relmse(film)));
    EXPECT_DOUBLE_EQ(estimated_relmse(film, {PixelBounds{0, 0, 1, 1}}), 1.0 / 3.0 / 1.01);  // from the halves
    const SppSummary spp = spp_summary(film);
    EXPECT_EQ(spp.min, 0.0);
    EXPECT_EQ(spp.max, 3.0);
    EXPECT_EQ(spp.mean, 1.5);
    EXPECT_EQ(spp_image(film).pixels[0].r, 3.0f);
    EXPECT_EQ(variance_image(film).pixels[0].g, float(1.0 / 3.0));
}

// The statistics travel with the film's values (what checkpoints, shard parts and MPI carry).
// Adds `samples` (the same value in r, g and b, or `colour` times it) to pixel (x, y).
void add_samples(Film& film, int x, int y, const std::vector<float>& samples, Rgb colour = Rgb(1.0f, 1.0f, 1.0f)) {
    for (const float value : samples) {
        const Rgb v(colour.r * value, colour.g * value, colour.b * value);
        add_to_sum(film.sum(x, y), v);
        add_square_to_sum(film.squares(x, y), v);
        film.count(x, y) += 1.0;
        film.prefix_sums(x, y).after_sample(uint32_t(film.count(x, y)) - 1, film.sum(x, y), film.count(x, y));
    }
}

// A film whose pixels all hold `count` samples of `value`.
Film uniform_film(int width, int height, int count, float value) {
    Film film(width, height, false, {}, true);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) add_samples(film, x, y, std::vector<float>(size_t(count), value));
    return film;
}

// One rare bright sample (a caustic's first find, a firefly) in a pixel of a dim region: over the
// pixel's own mean its relative error would be below 1 whatever the sample; over the region's value
// (what a converged reference has there) it is the large error the pixel really has.
TEST(PixelStatistics, AFireflyDoesNotRaiseTheValueItsErrorIsRelativeTo) {
    Film film(3, 3, false, {}, true);
    std::vector<float> dim(16, 0.25f), firefly = dim;
    firefly[9] = 48.0f;  // in the second half of the 16 samples
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) add_samples(film, x, y, x == 1 && y == 1 ? firefly : dim);
    // Neighbourhood medians: 0.25 (eight of nine means); halves 0.25 and (7 * 0.25 + 48) / 8.
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 1, 1)[1], 0.25);
    const double b = (7.0 * 0.25 + 48.0) / 8.0, v = (b - 0.25) * (b - 0.25) / 4.0;
    EXPECT_DOUBLE_EQ(variance_of_mean_from_halves(film, 1, 1)[0], v);
    EXPECT_DOUBLE_EQ(relative_variance_from_halves(film, 1, 1), v / (0.25 * 0.25 + kRelativeErrorEpsilon));
    // Control: over the pixel's own mean the same variance is a relative error below 1.
    const double own_mean = (15.0 * 0.25 + 48.0) / 16.0;
    EXPECT_LT(v / (own_mean * own_mean + kRelativeErrorEpsilon), 1.0);
    EXPECT_GT(relative_variance_from_halves(film, 1, 1), 100.0);
    // The neighbours' own values are unmoved: their medians hold 0.25 (and one 3.2).
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 0, 0)[0], 0.25);
}

// A bright line one pixel wide between dark rows: the neighbourhood's median is dark, but both
// halves of the line's pixels are bright, so the line keeps its own value.
TEST(PixelStatistics, AThinBrightLineKeepsItsOwnValue) {
    Film film(3, 5, false, {}, true);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 3; ++x) add_samples(film, x, y, std::vector<float>(8, y == 2 ? 5.0f : 0.0f));
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 1, 2)[2], 5.0);
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 1, 0)[2], 0.0);  // dark rows stay dark
    // Next to the line: six dark means of nine, so the median is dark.
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 1, 1)[2], 0.0);
}

// A block's relative errors read only its own pixels, so every renderer holding a tile decides alike.
TEST(PixelStatistics, NeighboursAreReadOnlyInsideTheErrorBlock) {
    Film film = uniform_film(16, 8, 4, 1.0f);
    for (int y = 0; y < 8; ++y)
        for (int x = 8; x < 16; ++x) add_samples(film, x, y, std::vector<float>(4, 99.0f));  // mean 50
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 7, 3)[0], 1.0);
    EXPECT_DOUBLE_EQ(relative_error_scale(film, 8, 3)[0], 50.0);
    const PixelBounds block = error_block(film, 7, 3);
    EXPECT_EQ(block.x0, 0);
    EXPECT_EQ(block.x1, 8);
    EXPECT_EQ(block.y1, 8);
    const Film odd(20, 10, false, {}, true);
    const PixelBounds edge = error_block(odd, 17, 9);  // clipped to the film
    EXPECT_EQ(edge.x0, 16);
    EXPECT_EQ(edge.y0, 8);
    EXPECT_EQ(edge.x1, 20);
    EXPECT_EQ(edge.y1, 10);
}

// Spectral renders give negative channel values (wavelengths outside the gamut): the value's
// magnitude is what is squared.
TEST(PixelStatistics, NegativeChannelValuesCountByTheirMagnitude) {
    Film film(2, 2, false, {}, true);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) add_samples(film, x, y, std::vector<float>(4, 1.0f), Rgb(-0.5f, 0.5f, 2.0f));
    const PixelSum scale = relative_error_scale(film, 0, 1);
    EXPECT_DOUBLE_EQ(scale[0], 0.5);
    EXPECT_DOUBLE_EQ(scale[1], 0.5);
    EXPECT_DOUBLE_EQ(scale[2], 2.0);
}

// The neighbourhood's median, by its fixed network for nine values and by selection at the edges:
// one sample per pixel (no halves yet), the means a permutation of 1..9, so the centre's value is 5
// whatever the order; at a corner, four pixels, the mean of the middle two.
TEST(PixelStatistics, TheNeighbourhoodMedianIsTheMiddleValueInAnyOrder) {
    std::array<int, 9> values{1, 2, 3, 4, 5, 6, 7, 8, 9};
    int checked = 0;
    for (int step = 0; std::next_permutation(values.begin(), values.end()); ++step) {
        if (step % 997 != 0) continue;  // 364 of the 362880 orders
        Film film(3, 3, false, {}, true);
        for (int i = 0; i < 9; ++i) add_samples(film, i % 3, i / 3, {float(values[size_t(i)])});
        ASSERT_DOUBLE_EQ(relative_error_scale(film, 1, 1)[0], 5.0) << "order " << step;
        const double corner[] = {double(values[0]), double(values[1]), double(values[3]), double(values[4])};
        std::vector<double> sorted(std::begin(corner), std::end(corner));
        std::sort(sorted.begin(), sorted.end());
        ASSERT_DOUBLE_EQ(relative_error_scale(film, 0, 0)[0], 0.5 * (sorted[1] + sorted[2])) << "order " << step;
        ++checked;
    }
    EXPECT_EQ(checked, 364);
}

// A rare bright sample after the last power of two (sample 17 of 17): the halves of samples [0, 16)
// cannot see it, the tail's term does: (1/17)^2 (T - M)^2 with T = 100, M = 1.
TEST(PixelStatistics, ASampleAfterThePowerOfTwoIsSeenAtOnce) {
    Film film(1, 1, false, {}, true);
    std::vector<float> samples(16, 1.0f);
    samples.push_back(100.0f);
    add_samples(film, 0, 0, samples);
    EXPECT_DOUBLE_EQ(variance_of_mean_from_halves(film, 0, 0)[0], 99.0 * 99.0 / (17.0 * 17.0));
}

// Between powers of two the estimate stays unbiased for independent samples: 24 samples of
// f(u) = u^2 per pixel (16 in the halves, 8 in the tail), the average over 4096 pixels against
// sigma^2 / 24, within 4 standard deviations of that average (measured from the pixels' spread).
TEST(PixelStatistics, IndependentSamplesBetweenPowersOfTwoGiveAnUnbiasedEstimate) {
    constexpr uint32_t kCount = 24;
    Film film(kSide, kSide, false, {}, true);
    std::vector<double> estimates;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const uint64_t pixel = uint64_t(y) * kSide + uint64_t(x);
            std::vector<float> samples;
            for (uint32_t s = 0; s < kCount; ++s) {
                const float u = Sampler(SamplerType::kIndependent, pixel, s, 13).next_float();
                samples.push_back(u * u);
            }
            add_samples(film, x, y, samples);
            estimates.push_back(variance_of_mean_from_halves(film, x, y)[1]);
        }
    const double mean = average(estimates);
    double spread = 0.0;
    for (const double e : estimates) spread += (e - mean) * (e - mean);
    const double sd = std::sqrt(spread / double(estimates.size() - 1) / double(estimates.size()));
    EXPECT_NEAR(mean, kVariance / kCount, 4.0 * sd);
}

TEST(PixelStatistics, RegionsCarryTheStatistics) {
    Film film(3, 2, true, {}, true);
    EXPECT_EQ(film.values_per_pixel(), 17);
    EXPECT_EQ(Film(3, 2, false, {}, true).values_per_pixel(), 16);
    EXPECT_EQ(Film(3, 2).values_per_pixel(), 3);
    film.sum(2, 1) = {1, 2, 3};
    film.weight(2, 1) = 4;
    film.squares(2, 1) = {5, 6, 7};
    film.count(2, 1) = 8;
    film.rays(2, 1) = 9;
    film.prefix_sums(2, 1) = PrefixSums{{{{10, 11, 12}, {13, 14, 15}}}, {16, 17}};
    std::vector<double> values(17);
    film.read_region(PixelBounds{2, 1, 3, 2}, values.data());
    EXPECT_EQ(values, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17}));
    Film copy(3, 2, true, {}, true);
    copy.write_region(PixelBounds{2, 1, 3, 2}, values.data());
    EXPECT_EQ(copy.squares(2, 1), film.squares(2, 1));
    EXPECT_EQ(copy.count(2, 1), 8.0);
    EXPECT_EQ(copy.rays(2, 1), 9.0);
    EXPECT_EQ(copy.prefix_sums(2, 1).sum[1], film.prefix_sums(2, 1).sum[1]);
    EXPECT_EQ(copy.prefix_sums(2, 1).weight[1], 17.0f);
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela
