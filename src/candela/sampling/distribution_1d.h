#pragma once
// A distribution over n indices (or over n equal bins of [0, 1)) proportional to non-negative
// weights: light selection by power, triangles by area, later environment map rows and columns.
// Sampling inverts the cumulative distribution by binary search (pbrt's PiecewiseConstant1D)
// rather than an alias table, because inversion is monotone in u: it keeps the stratification of
// u, and the continuous variant needs it.
//
// Robustness: weights that are negative, NaN or infinite count as 0; a zero-weight index is never
// returned; a distribution whose weights are all 0 (or that has none) is empty() and must not be
// sampled. Prefix sums run in double, so millions of weights (10M triangles) keep their relative
// sizes; the CDF is then stored in float (4 bytes per entry).
//
// Precision limit: u is a float with 24 random bits, so an index whose probability is far below
// 2^-24 is selected with a frequency that differs from probability() by up to 2^-24 (pbrt-v4's
// light samplers share this). The u left over after a choice (u_remapped) keeps about
// 24 - log2(1 / probability) bits.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "candela/core/check.h"
#include "candela/core/platform.h"
#include "candela/math/constants.h"

namespace candela {

// An index drawn from a Distribution1D.
struct DiscreteSample {
    uint32_t index = 0;
    float probability = 0.0f;  // of that index: probability(index)
    float u_remapped = 0.0f;   // u rescaled to [0, 1) within the index's CDF interval, for reuse
};

// A point of [0, 1) drawn from the piecewise-constant density of a Distribution1D.
struct ContinuousSample {
    float x = 0.0f;      // in [0, 1)
    float pdf = 0.0f;    // per unit length of [0, 1)
    uint32_t index = 0;  // the bin x lies in: floor(x * size())
};

class Distribution1D {
  public:
    Distribution1D() = default;
    // The distribution proportional to `weights` (copied).
    explicit Distribution1D(std::span<const float> weights);

    // True when there is nothing to sample: no weights, or all of them 0.
    CANDELA_HD bool empty() const { return total_ <= 0.0; }
    // The number of indices (bins), zero-weight ones included.
    CANDELA_HD size_t size() const { return weights_.size(); }
    // The sum of the (sanitised) weights, in double.
    CANDELA_HD double total() const { return total_; }

    // Index i with probability weight_i / total, by inversion of u in [0, 1). Requires !empty().
    CANDELA_HD DiscreteSample sample_discrete(float u) const;
    // weight_i / total; 0 out of range or for an empty distribution.
    CANDELA_HD float probability(size_t i) const;

    // A point x of [0, 1) with density weight_bin * size() / total (the piecewise-constant
    // function whose bins are the weights), by inversion. Requires !empty().
    CANDELA_HD ContinuousSample sample_continuous(float u) const;
    // The density of sample_continuous at x per unit length; 0 outside [0, 1).
    CANDELA_HD float pdf_continuous(float x) const;

  private:
    // The bin of x in [0, 1): x * n is exact in double for float x and n < 2^29.
    CANDELA_HD size_t bin_of(float x) const {
        auto bin = static_cast<size_t>(static_cast<double>(x) * static_cast<double>(size()));
        return bin < size() ? bin : size() - 1;
    }

    std::vector<float> weights_;  // sanitised: finite and >= 0
    std::vector<float> cdf_;      // size() + 1 entries: cdf_[0] = 0, exactly 1 from the end of
                                  // the last positive weight's interval on
    double total_ = 0.0;
    uint32_t first_positive_ = 0;
    uint32_t last_positive_ = 0;
};

CANDELA_HD inline DiscreteSample Distribution1D::sample_discrete(float u) const {
    CANDELA_DCHECK(!empty());
    const size_t n = size();
    // The interval [cdf_[i], cdf_[i+1]) that holds u: the first j >= 1 with cdf_[j] > u, minus one.
    // Such an interval is never empty, so its weight is positive (equal prefix sums round to equal
    // floats). u outside [0, 1), or NaN, falls back to the first or last positive weight.
    size_t i;
    if (!(u >= 0.0f)) {
        i = first_positive_;
    } else {
        // Branch-free binary search (Khuong and Morin 2017, "Array Layouts for Comparison-Based
        // Searching"): u is random, so the branches of the textbook search would be mispredicted
        // half the time. `base` ends on the last of cdf_[1..n] that is <= u (or before the first).
        const float* first = cdf_.data() + 1;
        const float* base = first;
        for (size_t len = n; len > 1;) {
            size_t half = len / 2;
            base = base[half - 1] <= u ? base + half : base;
            len -= half;
        }
        size_t j = size_t(base - first) + (*base <= u ? 1 : 0);  // cdf_[1 + j] is the first > u
        i = j < n ? j : last_positive_;
    }
    DiscreteSample s;
    s.index = static_cast<uint32_t>(i);
    s.probability = probability(i);
    float width = cdf_[i + 1] - cdf_[i];
    float r = width > 0.0f ? (u - cdf_[i]) / width : 0.0f;
    // min and max rather than clamp(): compiled to minss/maxss, no branch on the random r.
    s.u_remapped = std::min(std::max(r, 0.0f), kOneMinusEpsilon);
    if (!(s.u_remapped >= 0.0f)) s.u_remapped = 0.0f;  // a NaN u
    return s;
}

CANDELA_HD inline float Distribution1D::probability(size_t i) const {
    if (i >= size() || total_ <= 0.0) return 0.0f;
    return static_cast<float>(static_cast<double>(weights_[i]) / total_);
}

CANDELA_HD inline ContinuousSample Distribution1D::sample_continuous(float u) const {
    DiscreteSample d = sample_discrete(u);
    const double n = static_cast<double>(size());
    float x = static_cast<float>((static_cast<double>(d.index) + static_cast<double>(d.u_remapped)) / n);
    // Rounding to float may cross a bin edge (or reach 1): step back into the chosen bin, so that
    // pdf_continuous(x) is the density reported here. Bins are wider than a float step for any
    // sensible size (< 2^23), so one or two steps suffice.
    for (int step = 0; step < 4 && (x >= 1.0f || bin_of(x) > d.index); ++step)
        x = std::nextafter(x, 0.0f);
    for (int step = 0; step < 4 && bin_of(x) < d.index; ++step)
        x = std::nextafter(x, 1.0f);
    ContinuousSample s;
    s.x = x;
    s.index = d.index;
    s.pdf = pdf_continuous(x);
    return s;
}

CANDELA_HD inline float Distribution1D::pdf_continuous(float x) const {
    if (!(x >= 0.0f && x < 1.0f) || total_ <= 0.0) return 0.0f;
    return static_cast<float>(static_cast<double>(weights_[bin_of(x)]) * static_cast<double>(size()) / total_);
}

}  // namespace candela
