#pragma once
// What a film with statistics (film.h) says about its own error: per pixel, the variance of the
// mean of its samples, estimated from the sum and the sum of squares (the unbiased sample variance
// divided by the count); over the image, the estimated relMSE, the benchmark's error measure
// (bench/relmse.cpp: mean over pixels and channels of error^2 / (value^2 + 0.01)).
//
// Two estimates of the variance of a pixel's mean:
//
// From the squares: the unbiased sample variance over the count. Unbiased for independent samples,
// with as many degrees of freedom as samples, so it is steady pixel by pixel: adaptive sampling's
// per-pixel threshold and the variance layer use it. For Owen-scrambled Sobol samples the sample
// variance still estimates the per-sample variance without bias, but the mean's true variance is
// smaller than that over the count (a scrambled net's variance is at most e times Monte Carlo's and
// usually far below it; Owen 1997), so this estimate is an upper bound, by 1.4x (bunny-sky) to 2.3x
// (Cornell box) over an image (bench/RESULTS.md, issue 17).
//
// From the halves: with 2^m the largest power of two at most the count, the means A and B of
// samples [0, 2^(m-1)) and [2^(m-1), 2^m) (film.h's PrefixSums), (A - B)^2 / 4 estimates the
// variance of the 2^m-sample mean, scaled by 2^m / count to the whole count. Each half of a
// scrambled Sobol net is itself a scrambled net of the pixel, so the two estimate the same integral
// as the whole does, and their difference carries Sobol's own convergence: with a variance falling
// as n^-a the estimate is (2^a - 1) times the truth, exact for a = 1 (independent samples, and the
// edges and fine detail that dominate rendering error), 1.8x for a = 1.5; the squares' estimate is
// n^(a-1) times it. One degree of freedom per channel, so it is noisy pixel by pixel and meant for
// sums over many pixels: the image's estimated relMSE (--target-error, the progress bar, the
// summary) and --target-error's allocation over 8x8 blocks (render/error_allocation.h). (Cycles'
// even and odd half buffers fail with these samples: the pair (2k, 2k+1) of a scrambled Sobol
// sequence lies in opposite halves of the first dimension, so those two half means estimate
// different integrals and their difference never goes to zero.)
//
// For a weighted film (tabulated filters) the values summed are value * weight and the pixel's
// image value is their sum over the weight sum; the estimate treats the weight sum as exact.
#include <cstdint>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/film_settings.h"
#include "candela/image/image.h"

namespace candela {

// The constant in the denominator of the relative error: keeps black pixels from dominating.
inline constexpr double kRelativeErrorEpsilon = 0.01;

// Pixel (x, y)'s estimated variance of the mean, per channel, in the units of the resolved image;
// 0 with fewer than two samples. Films with statistics only.
PixelSum variance_of_mean(const Film& film, int x, int y);

// The same from the halves (above); 0 with fewer than two samples.
PixelSum variance_of_mean_from_halves(const Film& film, int x, int y);

// Pixel (x, y)'s estimated relative mean squared error: the mean over r, g, b of
// variance_of_mean / (value^2 + kRelativeErrorEpsilon); infinite with fewer than two samples.
double relative_variance(const Film& film, int x, int y);
// The same from the halves.
double relative_variance_from_halves(const Film& film, int x, int y);

// The mean of relative_variance_from_halves over the pixels of `regions` (the whole film when
// empty), summed in a fixed order: the estimated relMSE of the image. Infinite while a pixel has
// fewer than two samples.
double estimated_relmse(const Film& film, const std::vector<PixelBounds>& regions = {});

// Samples per pixel over the pixels of `regions` (the whole film when empty).
struct SppSummary {
    double mean = 0;
    double min = 0, max = 0;
    double total = 0;  // their sum: the samples taken
};
SppSummary spp_summary(const Film& film, const std::vector<PixelBounds>& regions = {});

// Whole-film layers for AOV outputs (variance, spp): the variance of the mean per channel, and the
// sample count per pixel in the r, g and b of an image.
Image variance_image(const Film& film);
Image spp_image(const Film& film);

}  // namespace candela
