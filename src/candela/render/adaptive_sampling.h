#pragma once
// Adaptive sampling (sampler.adaptive, --noise-threshold): after min_spp samples, an aligned block
// of kAdaptiveBlockSize x kAdaptiveBlockSize pixels (a block, as Cycles does, so that no single
// lucky pixel leaves a hole) whose pixels' estimated relative errors (film/pixel_statistics.h)
// are all below the threshold receives no more samples.
//
// So that the image is a function of the scene and settings only, decisions are made at fixed
// sample counts, the decision points (min_spp, then steps of 1/8 of the count, at least 4), never
// at wherever a pass happens to end: passes are cut to end at decision points. A block decided
// at count c either goes on (its pixels have c samples, and take the next pass's) or stops for good
// (its values, and so the decision, never change again). A block's decision reads only its own
// pixels, so any renderer that has a tile's pixels (a thread, an MPI rank, a shard) makes it;
// tiles are multiples of the block size and aligned to it (adaptive_tile_size).
//
// --target-error uses the same points: the render stops at the first one where the image's
// estimated relMSE is at most the target, and at each one blocks stop by its allocation
// (render/error_allocation.h), whose one number, the scale K, the renderer holding the whole
// film computes and hands to every tile of the pass.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "candela/film/film_settings.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/tile.h"
#include "candela/scene/render_settings.h"

namespace candela {

class Film;

// The blocks whose pixels' relative errors read neighbours only inside them (film/pixel_statistics.h).
inline constexpr int kAdaptiveBlockSize = kErrorBlockSize;
// The first decision point when only --target-error asks for them.
inline constexpr uint32_t kFirstTargetCheck = 16;

// The first decision point: adaptive sampling's min_spp, else kFirstTargetCheck.
inline uint32_t first_decision_point(const std::optional<AdaptiveSettings>& adaptive) {
    return adaptive ? uint32_t(adaptive->min_spp) : kFirstTargetCheck;
}

// The decision point after decision point `point`: steps of an eighth of the count, at least 4,
// so at most 12.5% of a pixel's samples are taken after it could have stopped.
inline uint32_t decision_point_after(uint32_t point) { return point + std::max<uint32_t>(4u, point / 8u); }

// The first decision point after `samples` (> samples) of the schedule starting at `first`.
inline uint32_t next_decision_point(uint32_t samples, uint32_t first) {
    uint32_t p = first;
    while (p <= samples) p = decision_point_after(p);
    return p;
}

// Whether `samples` is a decision point of the schedule starting at `first`.
inline bool is_decision_point(uint32_t samples, uint32_t first) {
    uint32_t p = first;
    while (p < samples) p = decision_point_after(p);
    return p == samples;
}

// The tile size adaptive renders use: `size` rounded up to a multiple of the block size.
inline int adaptive_tile_size(int size) {
    return (std::max(1, size) + kAdaptiveBlockSize - 1) / kAdaptiveBlockSize * kAdaptiveBlockSize;
}

// The blocks of a tile: its part of each aligned block of the film.
std::vector<PixelBounds> tile_blocks(const Tile& tile);

// Whether the block (of a film with statistics) takes samples from `begin` on: its pixels have
// `begin` samples (else it stopped at an earlier decision point) and, when `begin` is a decision
// point (first_decision_point(adaptive) and after), with adaptive sampling one of its pixels'
// relative error is at or above the threshold, and with --target-error (its allocation's scale at
// this decision point, error_allocation.h) the allocation wants more samples in it.
bool block_active(const Film& film, const PixelBounds& block, uint32_t begin,
                  const std::optional<AdaptiveSettings>& adaptive, std::optional<double> target_scale = {});

// Per tile of `tiles`, its pixels that take samples from `begin` on (what the progress bar counts).
std::vector<uint64_t> active_pixels_per_tile(const Film& film, const std::vector<Tile>& tiles, uint32_t begin,
                                             const std::optional<AdaptiveSettings>& adaptive,
                                             std::optional<double> target_scale = {});

// The pixels of `tiles` that take samples from `begin` on.
uint64_t active_pixels(const Film& film, const std::vector<Tile>& tiles, uint32_t begin,
                       const std::optional<AdaptiveSettings>& adaptive, std::optional<double> target_scale = {});

}  // namespace candela
