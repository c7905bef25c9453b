#pragma once
// --target-error's allocation of samples: which blocks of pixels go on sampling so that the
// image reaches the target relMSE in the least work.
//
// The image's relMSE is the mean over its N pixels of w_p / n_p, where w_p is pixel p's relative
// variance per sample and n_p its sample count; its work is the sum of c_p n_p, with c_p the work
// of one of its samples. Minimizing the work for relMSE E (a Lagrange multiplier) gives
// n_p = sqrt(w_p / c_p) * sum_q sqrt(w_q c_q) / (N E): samples go where the error is high and the
// samples are cheap, in proportion to square roots. Against uniform sampling, which needs
// N mean(c) mean(w) / E, this saves the factor mean(c) mean(w) / mean(sqrt(w c))^2 (>= 1 by
// Cauchy-Schwarz). A per-pixel threshold (sampler.adaptive) gives n_p proportional to w_p
// instead: it makes every pixel's error equal, which is what a threshold promises, but for the
// mean error it costs, with equal c_p, exactly what uniform sampling costs; with expensive noisy
// pixels (glass under a sky) more (bench/RESULTS.md, issue 17).
//
// Applied per block of adaptive_sampling.h at its decision points, from the film's statistics:
// W_b = sum over the block's pixels of w_p (relative_variance times the count), C_b = sum of their
// rays per sample plus kSampleOverheadRays. Blocks that stopped earlier keep their error F (the
// sum of their pixels' relative_variance); the active ones share the rest of the budget,
// N E - F, so a block goes on while sqrt(W_b / C_b) * K exceeds its count, with
// K = sum over active blocks of sqrt(W_b C_b) / (N E - F). A block that stops contributes at most
// its share, so while the estimate is above E some block stays active. Work is counted in rays,
// not seconds, so that decisions (and images) are deterministic.
#include <cstdint>
#include <vector>

#include "candela/film/film_settings.h"
#include "candela/render/tile.h"

namespace candela {

class Film;

// A camera sample's work besides its rays (sampler, filter, film), in rays: also what a block
// whose samples all miss the scene costs per sample beside its camera rays.
inline constexpr double kSampleOverheadRays = 1.0;

// K, above, at a decision point where the active blocks of `tiles` have `samples` samples each, for
// the target relMSE `target` (> 0). Infinite when the stopped blocks alone spent the budget (then
// no block with any error stops).
double target_allocation_scale(const Film& film, const std::vector<Tile>& tiles, uint32_t samples, double target);

// Whether the allocation with scale K (target_allocation_scale) wants more than `samples` samples
// in the block, whose pixels have `samples` samples each. A block without error wants none.
bool block_wants_samples(const Film& film, const PixelBounds& block, uint32_t samples, double scale);

}  // namespace candela
