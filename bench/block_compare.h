#pragma once
// Comparison of a render with another renderer's reference image, as
// ../shared/refs/pbrt-v4/README.md defines it for candela against pbrt-v4:
// - the mean ratio per channel: the sum of the test image's channel over the sum of the
//   reference's (a bias over the whole image shows here, undiluted by per-pixel noise);
// - per 16x16-pixel block, the relative difference of the blocks' mean luminance (Rec. 709,
//   0.2126 R + 0.7152 G + 0.0722 B), |Y_test - Y_ref| / Y_ref, over the blocks whose reference
//   luminance is at least 5% of the median reference block's (darker blocks are all noise);
//   summarized by its 50th and 95th percentiles and its maximum.
// Blocks are whole: where a side is not a multiple of the block size, the last partial row or
// column of pixels is left out of the block statistics (the means use every pixel).
#include <array>
#include <string>
#include <vector>

#include "candela/image/image.h"

namespace candela::bench {

struct BlockComparison {
    std::array<double, 3> mean_ratio{};  // sum(test) / sum(ref) per channel, R, G, B
    double p50 = 0.0, p95 = 0.0, max = 0.0;  // of the blocks' relative luminance differences
    int blocks_compared = 0;  // blocks at least dark_fraction of the median block
    int blocks_total = 0;
};

// The q-quantile (q in [0, 1]) of `values` by linear interpolation between order statistics at
// position q (n - 1) (numpy's default); 0 for an empty list.
double quantile(std::vector<double> values, double q);

// Compares `test` with `ref` (the same size) in blocks of block x block pixels, ignoring blocks
// whose reference luminance is below dark_fraction times the median block's. Throws
// std::runtime_error for images of different sizes, a block larger than the image, or a
// reference whose sum in a channel is 0.
BlockComparison compare_blocks(const Image& test, const Image& ref, int block = 16, double dark_fraction = 0.05);

// The image of `block` x `block` pixel means (whole blocks only): what compare_blocks reads of a
// reference, so a reference can be stored this small (tests/data/refs/) and compared with
// compare_blocks(block_means(test, block), stored, 1).
Image block_means(const Image& image, int block);

// Whether every channel's |mean_ratio - 1| is at most max_mean_bias and p95 at most max_p95.
bool within_bounds(const BlockComparison& c, double max_mean_bias, double max_p95);

// "mean ratio R G B, block p50 P, p95 P, max M": the numbers the reference tests print.
std::string describe(const BlockComparison& c);

}  // namespace candela::bench
