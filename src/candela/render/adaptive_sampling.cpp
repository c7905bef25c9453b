#include "candela/render/adaptive_sampling.h"

#include <cmath>
#include <vector>

#include "candela/film/film.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/error_allocation.h"

namespace candela {

std::vector<PixelBounds> tile_blocks(const Tile& tile) {
    std::vector<PixelBounds> blocks;
    constexpr int b = kAdaptiveBlockSize;
    for (int y = tile.y0 / b * b; y < tile.y1; y += b)
        for (int x = tile.x0 / b * b; x < tile.x1; x += b)
            blocks.push_back({std::max(x, tile.x0), std::max(y, tile.y0), std::min(x + b, tile.x1),
                              std::min(y + b, tile.y1)});
    return blocks;
}

bool block_active(const Film& film, const PixelBounds& block, uint32_t begin,
                  const std::optional<AdaptiveSettings>& adaptive, std::optional<double> target_scale) {
    // Every pixel of a block has the same count: the block's decisions are its pixels'.
    if (film.count(block.x0, block.y0) != double(begin)) return false;
    const uint32_t first = first_decision_point(adaptive);
    if (begin < first || !is_decision_point(begin, first)) return true;
    if (target_scale && !block_wants_samples(film, block, begin, *target_scale)) return false;
    if (!adaptive) return true;
    // Relative error below the threshold: relative variance below its square.
    const double limit = double(adaptive->threshold) * double(adaptive->threshold);
    std::vector<double> relative;
    relative_variances(film, block, VarianceEstimate::kSquares, relative);
    for (const double r : relative)
        if (!(r < limit)) return true;
    return false;
}

std::vector<uint64_t> active_pixels_per_tile(const Film& film, const std::vector<Tile>& tiles, uint32_t begin,
                                             const std::optional<AdaptiveSettings>& adaptive,
                                             std::optional<double> target_scale) {
    std::vector<uint64_t> active(tiles.size(), 0);
    for (size_t t = 0; t < tiles.size(); ++t)
        for (const PixelBounds& block : tile_blocks(tiles[t]))
            if (block_active(film, block, begin, adaptive, target_scale))
                active[t] += uint64_t(block.width()) * uint64_t(block.height());
    return active;
}

uint64_t active_pixels(const Film& film, const std::vector<Tile>& tiles, uint32_t begin,
                       const std::optional<AdaptiveSettings>& adaptive, std::optional<double> target_scale) {
    uint64_t active = 0;
    for (uint64_t pixels : active_pixels_per_tile(film, tiles, begin, adaptive, target_scale)) active += pixels;
    return active;
}

}  // namespace candela
