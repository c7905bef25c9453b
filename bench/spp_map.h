#pragma once
// The samples-per-pixel map of an adaptive render as a figure panel (candela_side_by_side
// --spp-map): each pixel's spp on a logarithmic colour ramp (viridis: dark blue few, yellow many,
// readable in grey and by most colour-blind readers), above a legend strip: the ramp from the
// fewest to the most samples any pixel took, with those two counts written at its ends.
#include "candela/image/image.h"

namespace candela::bench {

// `spp`: a layer whose r holds each pixel's sample count (the `spp` channel of an .exr). The
// panel is spp's width and kSppLegendHeight rows taller; its values are linear sRGB in [0, 1].
inline constexpr int kSppLegendHeight = 16;
Image spp_map_panel(const Image& spp);

}  // namespace candela::bench
