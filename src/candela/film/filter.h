#pragma once
// Pixel filters by importance sampling (pbrt-v4's approach): a camera sample's film position is
// drawn from the filter's density, and every sample counts with weight 1 into its own pixel. So
// pixels never write to their neighbours (no locks, tiles stay independent) and the pixel value is
// the filter-weighted average of radiance in expectation.
//
// These functions are the scene file's named filters (box, tent, gaussian, smallpt) with their fixed
// radii; film/pixel_filter.h adds the radius parameters and pbrt-v4's tabulated filters.
//
// Positions are in pixels relative to the pixel's top-left corner, x right and y down; the pixel
// centre is (0.5, 0.5). Filters may reach past the pixel (the tent covers [-0.5, 1.5]^2).
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/film/film_settings.h"
#include "candela/math/vec.h"

namespace candela {

// The film position of sample `sample_index` of a pixel, from u in [0, 1)^2. Only kSmallpt uses
// the index (to cycle through its four subpixels).
CANDELA_HD Vec2f sample_filter(FilterType type, uint32_t sample_index, Vec2f u);

// The density of sample_filter's positions per unit film area (pixels^-2), for a uniformly random
// sample index (for kSmallpt: averaged over its four subpixels), at `offset` from the top-left
// corner; 0 outside the support. For tests.
CANDELA_HD float filter_pdf(FilterType type, Vec2f offset);

// Half-width of the filter's support around the pixel centre, in pixels.
CANDELA_HD float filter_radius(FilterType type);

}  // namespace candela
