#include "candela/sampling/distribution_2d.h"

#include "candela/core/check.h"

namespace candela {

Distribution2D::Distribution2D(std::span<const float> weights, int width, int height)
    : width_(width), height_(height) {
    CANDELA_CHECK(width >= 0 && height >= 0);
    CANDELA_CHECK(weights.size() == static_cast<size_t>(width) * static_cast<size_t>(height));
    const auto w = static_cast<size_t>(width);
    conditional_.reserve(static_cast<size_t>(height));
    std::vector<float> row_totals(static_cast<size_t>(height));
    for (size_t y = 0; y < row_totals.size(); ++y) {
        conditional_.emplace_back(weights.subspan(y * w, w));
        row_totals[y] = static_cast<float>(conditional_.back().total());
    }
    marginal_ = Distribution1D(row_totals);
    marginal_total_ = marginal_.total();
}

Distribution2DSample Distribution2D::sample(Vec2f u) const {
    CANDELA_DCHECK(!empty());
    ContinuousSample row = marginal_.sample_continuous(u.y);
    ContinuousSample col = conditional_[row.index].sample_continuous(u.x);
    // Both densities are those of pdf() at the returned point: sample_continuous keeps x in the
    // bin it chose, so pdf(uv) finds the same row and column.
    return {Vec2f(col.x, row.x), row.pdf * col.pdf};
}

float Distribution2D::pdf(Vec2f uv) const {
    float pv = marginal_.pdf_continuous(uv.y);
    if (!(pv > 0.0f)) return 0.0f;
    auto row = static_cast<size_t>(static_cast<double>(uv.y) * static_cast<double>(height_));
    if (row >= conditional_.size()) row = conditional_.size() - 1;
    return pv * conditional_[row].pdf_continuous(uv.x);
}

size_t Distribution2D::memory_bytes() const {
    // Distribution1D holds size() weights and size() + 1 CDF entries, all float.
    auto bytes = [](const Distribution1D& d) {
        return sizeof(Distribution1D) + (d.size() == 0 ? 0 : 2 * d.size() + 1) * sizeof(float);
    };
    size_t total = bytes(marginal_);
    for (const Distribution1D& d : conditional_) total += bytes(d);
    return total;
}

}  // namespace candela
