#include "candela/film/pixel_filter.h"

#include <algorithm>
#include <cmath>

#include "candela/film/filter.h"
#include "candela/math/constants.h"
#include "candela/sampling/warps.h"

namespace candela {

namespace {

// pbrt-v4's FilterSampler: 32 table cells per pixel of radius (at least one).
constexpr float kCellsPerPixel = 32.0f;

CANDELA_HD float gaussian(float x, float sigma) {
    return std::exp(-(x * x) / (2.0f * sigma * sigma)) / (std::sqrt(2.0f * kPi) * sigma);
}

// Mitchell and Netravali, "Reconstruction filters in computer graphics" (1988), eq. 8: a cubic on
// |x| < 1 and one on 1 <= |x| < 2, 0 beyond; x is in units of half the radius.
CANDELA_HD float mitchell_1d(float x, float b, float c) {
    x = std::abs(x);
    if (x <= 1.0f)
        return ((12.0f - 9.0f * b - 6.0f * c) * x * x * x + (-18.0f + 12.0f * b + 6.0f * c) * x * x + (6.0f - 2.0f * b)) /
               6.0f;
    if (x <= 2.0f)
        return ((-b - 6.0f * c) * x * x * x + (6.0f * b + 30.0f * c) * x * x + (-12.0f * b - 48.0f * c) * x +
                (8.0f * b + 24.0f * c)) /
               6.0f;
    return 0.0f;
}

// sin(pi x) / (pi x), 1 at 0.
CANDELA_HD float sinc(float x) {
    const float px = kPi * x;
    return std::abs(px) < 1e-5f ? 1.0f : std::sin(px) / px;
}

}  // namespace

CANDELA_HD float filter_function_1d(const FilterSettings& settings, float x, float radius) {
    if (std::abs(x) > radius) return 0.0f;
    switch (settings.type) {
        case FilterType::kOffsetGaussian:
            // pbrt-v4's GaussianFilter: the Gaussian less its value at the radius, so that the
            // filter falls to 0 there instead of stepping down.
            return std::max(0.0f, gaussian(x, settings.sigma) - gaussian(radius, settings.sigma));
        case FilterType::kMitchell:
            return mitchell_1d(2.0f * x / radius, settings.b, settings.c);
        case FilterType::kLanczos:
            // The sinc windowed by a sinc stretched tau times (pbrt-v4's WindowedSinc).
            return sinc(x) * sinc(x / settings.tau);
        default:
            return 0.0f;
    }
}

FilterTable1D::FilterTable1D(const FilterSettings& settings, float radius) : radius_(radius) {
    const int n = std::max(1, int(kCellsPerPixel * radius));
    values_.resize(size_t(n));
    std::vector<float> magnitudes(values_.size());
    for (int i = 0; i < n; ++i) {
        const float t = (float(i) + 0.5f) / float(n);
        const float x = (1.0f - t) * -radius + t * radius;
        values_[size_t(i)] = filter_function_1d(settings, x, radius);
        magnitudes[size_t(i)] = std::abs(values_[size_t(i)]);
    }
    distribution_ = Distribution1D(magnitudes);
    abs_integral_ = float(distribution_.total() * (2.0 * double(radius) / double(n)));
}

CANDELA_HD int FilterTable1D::cell_of(float offset) const {
    const float t = (offset + radius_) / (2.0f * radius_);
    const int n = int(values_.size());
    return std::clamp(int(t * float(n)), 0, n - 1);
}

CANDELA_HD float FilterTable1D::sample(float u, float& weight) const {
    const ContinuousSample s = distribution_.sample_continuous(u);
    // f / pdf with pdf = |f| n / (total 2 radius): the sign of f times the table's |f| integral.
    weight = values_[s.index] < 0.0f ? -abs_integral_ : abs_integral_;
    return std::clamp(-radius_ + s.x * (2.0f * radius_), -radius_, radius_);
}

CANDELA_HD float FilterTable1D::pdf(float offset) const {
    if (!(std::abs(offset) <= radius_) || abs_integral_ <= 0.0f) return 0.0f;
    return std::abs(values_[size_t(cell_of(offset))]) / abs_integral_;
}

CANDELA_HD float FilterTable1D::value(float offset) const {
    if (!(std::abs(offset) <= radius_)) return 0.0f;
    return values_[size_t(cell_of(offset))];
}

PixelFilter::PixelFilter(const FilterSettings& settings)
    : settings_(settings), weighted_(is_tabulated(settings.type)) {
    if (weighted_) {
        table_x_ = FilterTable1D(settings, settings.radius.x);
        table_y_ = FilterTable1D(settings, settings.radius.y);
    }
}

CANDELA_HD FilterSample PixelFilter::sample(uint32_t sample_index, Vec2f u) const {
    const Vec2f r = settings_.radius;
    switch (settings_.type) {
        case FilterType::kBox:
            // The scene file's box (radius 0.5) is u itself, as it always was.
            if (r == Vec2f(0.5f, 0.5f)) return {u, 1.0f};
            return {{0.5f + r.x * (2.0f * u.x - 1.0f), 0.5f + r.y * (2.0f * u.y - 1.0f)}, 1.0f};
        case FilterType::kTent:
            return {{0.5f + sample_tent(u.x, r.x), 0.5f + sample_tent(u.y, r.y)}, 1.0f};
        case FilterType::kGaussian:
        case FilterType::kSmallpt:
            return {sample_filter(settings_.type, sample_index, u), 1.0f};
        default: {
            float wx = 0.0f, wy = 0.0f;
            const float x = table_x_.sample(u.x, wx);
            const float y = table_y_.sample(u.y, wy);
            return {{0.5f + x, 0.5f + y}, wx * wy};
        }
    }
}

CANDELA_HD float PixelFilter::pdf(Vec2f offset) const {
    const Vec2f r = settings_.radius;
    const Vec2f d = offset - Vec2f(0.5f, 0.5f);
    switch (settings_.type) {
        case FilterType::kBox:
            return std::abs(d.x) <= r.x && std::abs(d.y) <= r.y ? 1.0f / (4.0f * r.x * r.y) : 0.0f;
        case FilterType::kTent:
            return tent_pdf(d.x, r.x) * tent_pdf(d.y, r.y);
        case FilterType::kGaussian:
        case FilterType::kSmallpt:
            return filter_pdf(settings_.type, offset);
        default:
            return table_x_.pdf(d.x) * table_y_.pdf(d.y);
    }
}

CANDELA_HD float PixelFilter::value(Vec2f offset) const {
    if (!weighted_) return pdf(offset);
    const Vec2f d = offset - Vec2f(0.5f, 0.5f);
    return table_x_.value(d.x) * table_y_.value(d.y);
}

}  // namespace candela
