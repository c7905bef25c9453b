#include "candela/render/error_allocation.h"

#include <cmath>
#include <limits>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/adaptive_sampling.h"

namespace candela {

namespace {

// A block's W (relative variance per sample, summed over its pixels) and C (work per sample,
// summed over its pixels), and its current error (sum of its pixels' relative variance of the mean).
struct BlockError {
    double per_sample = 0.0;
    double work = 0.0;
    double error = 0.0;
};

BlockError block_error(const Film& film, const PixelBounds& block) {
    BlockError b;
    std::vector<double> relative;
    relative_variances(film, block, VarianceEstimate::kHalves, relative);
    size_t i = 0;
    for (int y = block.y0; y < block.y1; ++y)
        for (int x = block.x0; x < block.x1; ++x) {
            const double n = film.count(x, y);
            const double r = relative[i++];
            b.error += r;
            b.per_sample += r * n;
            b.work += (n > 0.0 ? film.rays(x, y) / n : 0.0) + kSampleOverheadRays;
        }
    return b;
}

}  // namespace

double target_allocation_scale(const Film& film, const std::vector<Tile>& tiles, uint32_t samples, double target) {
    double stopped_error = 0.0, active_sum = 0.0;
    uint64_t pixels = 0;
    for (const Tile& tile : tiles)
        for (const PixelBounds& block : tile_blocks(tile)) {
            pixels += uint64_t(block.width()) * uint64_t(block.height());
            const BlockError b = block_error(film, block);
            if (film.count(block.x0, block.y0) == double(samples))
                active_sum += std::sqrt(b.per_sample * b.work);
            else
                stopped_error += b.error;
        }
    const double budget = double(pixels) * target - stopped_error;
    if (!(budget > 0.0)) return std::numeric_limits<double>::infinity();
    return active_sum / budget;
}

bool block_wants_samples(const Film& film, const PixelBounds& block, uint32_t samples, double scale) {
    const BlockError b = block_error(film, block);
    if (!(b.per_sample > 0.0)) return false;
    return std::sqrt(b.per_sample / b.work) * scale > double(samples);
}

}  // namespace candela
