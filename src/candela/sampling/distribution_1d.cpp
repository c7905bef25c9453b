#include "candela/sampling/distribution_1d.h"

#include <cmath>

namespace candela {

Distribution1D::Distribution1D(std::span<const float> weights)
    : weights_(weights.begin(), weights.end()), cdf_(weights.size() + 1, 0.0f) {
    bool any_positive = false;
    for (size_t i = 0; i < weights_.size(); ++i) {
        float& w = weights_[i];
        if (!(w > 0.0f) || !std::isfinite(w)) w = 0.0f;
        if (w > 0.0f) {
            if (!any_positive) first_positive_ = static_cast<uint32_t>(i);
            last_positive_ = static_cast<uint32_t>(i);
            any_positive = true;
        }
    }
    // Prefix sums in double: in float, adding the 10-millionth small weight to a large running sum
    // would lose most of its bits (or all of them).
    std::vector<double> prefix(weights_.size() + 1, 0.0);
    for (size_t i = 0; i < weights_.size(); ++i) prefix[i + 1] = prefix[i] + static_cast<double>(weights_[i]);
    total_ = prefix.back();
    if (!(total_ > 0.0)) return;  // all weights 0: nothing can be sampled
    // Rounding is monotone, so equal prefix sums (zero weights) stay equal floats and their
    // intervals empty. The last positive weight's interval ends at exactly 1, so every u < 1 lands
    // in an interval of positive weight.
    for (size_t i = 1; i <= weights_.size(); ++i)
        cdf_[i] = i > last_positive_ ? 1.0f : static_cast<float>(prefix[i] / total_);
}

}  // namespace candela
