#pragma once
// A piecewise-constant distribution over [0, 1)^2 from a W x H grid of non-negative weights (row
// y covers v in [y/H, (y+1)/H), column x covers u in [x/W, (x+1)/W)): a marginal Distribution1D
// over the rows and a conditional one per row (pbrt's PiecewiseConstant2D). Environment maps
// sample their texels with it. Weights follow Distribution1D's rules: negative, NaN or infinite
// count as 0, and a cell of weight 0 has density 0 and is never sampled.
//
// Memory: 8 bytes per cell (each row's sanitised weights and CDF, in float) plus 8 per row.
#include <cstddef>
#include <span>
#include <vector>

#include "candela/math/vec.h"
#include "candela/sampling/distribution_1d.h"

namespace candela {

// A point of [0, 1)^2 drawn from a Distribution2D.
struct Distribution2DSample {
    Vec2f uv;            // u along a row (column coordinate), v across rows (row coordinate)
    float pdf = 0.0f;    // per unit area of [0, 1)^2
};

class Distribution2D {
  public:
    Distribution2D() = default;
    // The distribution proportional to `weights`, width x height of them, row-major (row 0 first).
    Distribution2D(std::span<const float> weights, int width, int height);

    // True when there is nothing to sample: no cells, or all weights 0.
    bool empty() const { return marginal_.empty(); }
    int width() const { return width_; }
    int height() const { return height_; }
    // The sum of the (sanitised) weights, in double.
    double total() const { return marginal_total_; }

    // A point with density weight_cell * W * H / total, by inversion: u.y picks the row, u.x the
    // point within it, so the map is monotone in each coordinate. Requires !empty().
    Distribution2DSample sample(Vec2f u) const;
    // The density of sample() at uv per unit area; 0 outside [0, 1)^2 or for an empty distribution.
    float pdf(Vec2f uv) const;
    // Bytes held by the tables (for the memory budget of large environment maps).
    size_t memory_bytes() const;

  private:
    int width_ = 0;
    int height_ = 0;
    std::vector<Distribution1D> conditional_;  // one per row, over u
    Distribution1D marginal_;                  // over rows, weighted by each row's total
    double marginal_total_ = 0.0;
};

}  // namespace candela
