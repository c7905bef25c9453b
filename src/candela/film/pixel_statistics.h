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
// variance of the 2^m-sample mean M; the samples after 2^m, whose mean T the film's sums give,
// add their own variance, estimated by (T - M)^2 less M's (variance_of_mean_from_halves), so
// that a rare sample taken between powers of two is seen at once. Each half of a
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
// The denominator: relative error divides a pixel's variance by its value squared, and the value the
// pixel's own samples give is raised by the very samples that make its error. A pixel with one rare
// bright sample (a caustic's first find, a firefly in a dark corner) has a variance about its own
// mean squared, so over its own mean its relative error is at most about 1 whatever the sample's
// size, while over the true value (what bench/ and the user's reference divide by) it can be
// thousands: the image estimate was 18x below the truth on cornell-glass at 16 spp, 260x on the
// prism at 4 spp and 5900x on veach-bidir at 16 spp (bench/RESULTS.md, issue 28). So the value
// squared is the larger of two estimates of it that one rare sample does not raise: the median of
// the means of the pixel and its eight neighbours (a pixel's firefly is one of nine, and a smooth
// region's median is its value), and the smaller of the two halves' means (a bright thin line one
// pixel wide, whose neighbours are dark, has both halves bright once it is found). Neighbours are
// read only inside the pixel's aligned kErrorBlockSize block, so that an 8x8 block's estimate
// needs only its own pixels: any renderer holding a tile (a thread, an MPI rank, a shard) makes the
// same decisions, and nothing about the film's layout or the statistics kept per pixel changed.
// Measured against converged references (64x64, seed 5): true / estimate at 4 to 2048 spp is
// 0.58-1.02 on cornell-glass, 0.007-0.75 on the prism (spectral; the estimate is conservative
// where few samples leave the channels' medians near 0) and 0.35-1.35 on veach-bidir; on scenes
// without rare paths the two denominators agree once a pixel's noise is below its value.
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

// The side of the aligned square blocks of pixels inside which a pixel's neighbours are read
// (above); render/adaptive_sampling.h's blocks are these.
inline constexpr int kErrorBlockSize = 8;

// The aligned block of kErrorBlockSize pixels holding pixel (x, y), clipped to the film.
PixelBounds error_block(const Film& film, int x, int y);

// Pixel (x, y)'s value as the relative error sees it, per channel (above): the larger of the
// magnitudes of the median of its 3x3 neighbourhood's means (within its error_block) and of the
// smaller of its two halves' means. Films with statistics only.
PixelSum relative_error_scale(const Film& film, int x, int y);

// Pixel (x, y)'s estimated relative mean squared error: the mean over r, g, b of
// variance_of_mean / (relative_error_scale^2 + kRelativeErrorEpsilon); infinite with fewer than two
// samples.
double relative_variance(const Film& film, int x, int y);
// The same from the halves.
double relative_variance_from_halves(const Film& film, int x, int y);

// Which estimate of the variance of the mean a relative variance is made from (above).
enum class VarianceEstimate { kSquares, kHalves };

// relative_variance (kSquares) or relative_variance_from_halves (kHalves) of every pixel of
// `bounds`, row-major, into `out`: the neighbours' means computed once, for whole blocks and images.
void relative_variances(const Film& film, const PixelBounds& bounds, VarianceEstimate estimate,
                        std::vector<double>& out);

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
