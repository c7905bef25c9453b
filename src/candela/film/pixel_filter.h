#pragma once
// A pixel filter with its parameters, as the renderer samples it (pbrt-v4's Filter::Sample).
//
// Box and tent (pbrt-v4's triangle), and the scene file's gaussian and smallpt, are sampled exactly
// from their density (film/filter.h), so every sample has weight 1 and a pixel is the mean of its
// samples. pbrt-v4's Gaussian (minus its value at the radius), Mitchell and Lanczos filters are
// tabulated (pbrt-v4's FilterSampler: 32 cells per pixel of radius, each the filter's value at the
// cell centre) and a position is drawn from the piecewise-constant density proportional to the
// table's |f|; its weight is f / pdf, which is the table's integral of |f| with f's sign (Mitchell
// and Lanczos have negative lobes). The film then divides each pixel's weighted sum by its sum of
// weights (pbrt-v4's RGBFilm), so the image is the filter-weighted average of radiance.
//
// The three tabulated filters are products of a function of x and one of y, so their tables are
// too: each axis is sampled on its own from a 1D table, which draws from the same density as
// pbrt-v4's 2D table of the products.
//
// Positions are in pixels relative to the pixel's top-left corner, as in film/filter.h.
#include <cstdint>
#include <vector>

#include "candela/core/platform.h"
#include "candela/film/film_settings.h"
#include "candela/math/vec.h"
#include "candela/sampling/distribution_1d.h"

namespace candela {

// A film position and the weight its sample counts with.
struct FilterSample {
    Vec2f position;
    float weight = 1.0f;
};

// One axis of a tabulated filter: the filter's value at the centres of n cells across
// [-radius, radius], and the distribution proportional to their absolute values.
class FilterTable1D {
  public:
    FilterTable1D() = default;
    FilterTable1D(const FilterSettings& settings, float radius);

    // An offset from the pixel centre in [-radius, radius] with density pdf(offset), and the
    // table's value there divided by that density.
    CANDELA_HD float sample(float u, float& weight) const;
    // The density of sample's offsets, per pixel; 0 outside [-radius, radius].
    CANDELA_HD float pdf(float offset) const;
    // The tabulated filter value at `offset` (0 outside).
    CANDELA_HD float value(float offset) const;
    // The integral of the table's |f| over [-radius, radius].
    CANDELA_HD float abs_integral() const { return abs_integral_; }

  private:
    CANDELA_HD int cell_of(float offset) const;
    float radius_ = 0.0f;
    std::vector<float> values_;  // signed, per cell
    Distribution1D distribution_;
    float abs_integral_ = 0.0f;
};

// The 1D function a tabulated filter is the product of (f(x) f(y)), at offset x from the pixel
// centre; 0 for the exactly sampled types.
CANDELA_HD float filter_function_1d(const FilterSettings& settings, float x, float radius);

class PixelFilter {
  public:
    explicit PixelFilter(const FilterSettings& settings);

    // True when samples have weights other than 1 (the tabulated filters): the film must then sum
    // the weights.
    bool weighted() const { return weighted_; }

    // The film position (relative to the pixel's top-left corner) of sample `sample_index` of a
    // pixel, from u in [0, 1)^2, and its weight (1 unless weighted()).
    CANDELA_HD FilterSample sample(uint32_t sample_index, Vec2f u) const;
    // The density of sample's positions per pixel^2 at `offset` from the top-left corner (for the
    // scene file's smallpt: averaged over its subpixels). For tests.
    CANDELA_HD float pdf(Vec2f offset) const;
    // The filter function the samples estimate, up to a constant factor: pdf for the exactly
    // sampled filters, the tabulated f(x) f(y) for the others. For tests.
    CANDELA_HD float value(Vec2f offset) const;
    // The integral of |f| of the tabulated filter (the magnitude of every sample's weight); 1 for
    // the others.
    float table_integral() const { return weighted_ ? table_x_.abs_integral() * table_y_.abs_integral() : 1.0f; }
    // Half-widths of the support around the pixel centre, in pixels.
    CANDELA_HD Vec2f radius() const { return settings_.radius; }

  private:
    FilterSettings settings_;
    bool weighted_ = false;
    FilterTable1D table_x_, table_y_;
};

// True for the tabulated filter types.
CANDELA_HD inline bool is_tabulated(FilterType type) {
    return type == FilterType::kOffsetGaussian || type == FilterType::kMitchell || type == FilterType::kLanczos;
}

}  // namespace candela
