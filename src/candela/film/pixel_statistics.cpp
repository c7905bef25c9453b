#include "candela/film/pixel_statistics.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "candela/core/check.h"

namespace candela {

namespace {

// Calls f(region) for each of `regions`, or for the whole film when there are none.
template <class F>
void for_each_region(const Film& film, const std::vector<PixelBounds>& regions, F&& f) {
    if (regions.empty())
        f(PixelBounds{0, 0, film.width(), film.height()});
    else
        for (const PixelBounds& r : regions) f(r);
}

// Calls f(x, y) for every pixel of `regions`, or of the whole film when there are none.
template <class F>
void for_each_pixel(const Film& film, const std::vector<PixelBounds>& regions, F&& f) {
    for_each_region(film, regions, [&](const PixelBounds& r) {
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) f(x, y);
    });
}

// The factor from the mean of the summed values to the pixel's image value: 1, or the count over
// the weight sum for a weighted film.
double value_scale(const Film& film, int x, int y) {
    if (!film.weighted()) return 1.0;
    const double w = film.weight(x, y);
    return w != 0.0 ? film.count(x, y) / w : 0.0;
}

}  // namespace

PixelSum variance_of_mean(const Film& film, int x, int y) {
    CANDELA_CHECK(film.has_statistics());
    const double n = film.count(x, y);
    if (n < 2.0) return {0.0, 0.0, 0.0};
    const PixelSum& sum = film.sum(x, y);
    const PixelSum& squares = film.squares(x, y);
    const double scale = value_scale(film, x, y);
    PixelSum v{};
    for (size_t c = 0; c < 3; ++c) {
        // The unbiased sample variance, (sum of squares - sum^2 / n) / (n - 1), then over n for
        // the mean; clamped at 0 against rounding when every sample is the same.
        const double sample_variance = std::max(0.0, (squares[c] - sum[c] * sum[c] / n) / (n - 1.0));
        v[c] = sample_variance / n * scale * scale;
    }
    return v;
}

namespace {

// The means A and B of the halves of pixel (x, y)'s last power of two of samples (above), per
// channel; false when a half has no weight (a weighted pixel whose samples there all had weight 0).
bool half_means(const Film& film, int x, int y, PixelSum& a, PixelSum& b) {
    const PrefixSums& p = film.prefix_sums(x, y);
    const double first_weight = double(p.weight[0]), second_weight = double(p.weight[1]) - double(p.weight[0]);
    if (!(first_weight > 0.0 && second_weight > 0.0)) return false;
    for (size_t c = 0; c < 3; ++c) {
        a[c] = double(p.sum[0][c]) / first_weight;
        b[c] = (double(p.sum[1][c]) - double(p.sum[0][c])) / second_weight;
    }
    return true;
}

// Pixel (x, y)'s value, per channel, in the units of the resolved image (0 without samples).
PixelSum pixel_mean(const Film& film, int x, int y) {
    const double n = film.count(x, y);
    if (!(n > 0.0)) return {0.0, 0.0, 0.0};
    const double to_value = value_scale(film, x, y) / n;
    const PixelSum& sum = film.sum(x, y);
    return {sum[0] * to_value, sum[1] * to_value, sum[2] * to_value};
}

// variance_of_mean_from_halves of a pixel with at least two samples, from its halves' means.
PixelSum halves_variance(const Film& film, int x, int y, const PixelSum& a, const PixelSum& b) {
    // The mean is M over the last power of two's weight w (its halves A and B) and T over the
    // samples after it (weight u < w); the pixel's mean is (w M + u T) / (w + u), its variance
    // (w / (w + u))^2 var(M) + (u / (w + u))^2 var(T), with var(M) estimated by (A - B)^2 / 4 and
    // var(T) by (T - M)^2 - var(M) (T and M are independent): unbiased for independent samples,
    // and never negative since w > u. Without the tail's term a rare bright sample taken after
    // the power of two was invisible until the next one, and the blocks that --target-error
    // stopped in between kept it unseen: veach-bidir at --target-error 0.1 (independent samples)
    // ended 3.3x above the target, and 0.88x with it (bench/RESULTS.md, issue 28).
    const PrefixSums& p = film.prefix_sums(x, y);
    const double w = double(p.weight[1]), total = film.weighted() ? film.weight(x, y) : film.count(x, y);
    const double u = total - w;
    PixelSum v{};
    for (size_t c = 0; c < 3; ++c) {
        const double of_m = (a[c] - b[c]) * (a[c] - b[c]) / 4.0;
        double of_t = 0.0;
        if (u > 0.0) {
            const double m = 0.5 * (a[c] + b[c]), t = (film.sum(x, y)[c] - double(p.sum[1][c])) / u;
            of_t = (t - m) * (t - m) - of_m;
        }
        v[c] = (w / total) * (w / total) * of_m + (u / total) * (u / total) * of_t;
    }
    return v;
}

}  // namespace

PixelSum variance_of_mean_from_halves(const Film& film, int x, int y) {
    CANDELA_CHECK(film.has_statistics());
    PixelSum a{}, b{};
    if (film.count(x, y) < 2.0 || !half_means(film, x, y, a, b)) return {0.0, 0.0, 0.0};
    return halves_variance(film, x, y, a, b);
}

PixelBounds error_block(const Film& film, int x, int y) {
    constexpr int size = kErrorBlockSize;
    const int x0 = x / size * size, y0 = y / size * size;
    return {x0, y0, std::min(x0 + size, film.width()), std::min(y0 + size, film.height())};
}

namespace {

// The means of the pixels of `bounds` grown to whole error blocks (clipped to the film), each
// computed once: the neighbourhoods of relative_error_scale read each pixel's mean up to nine times.
class BlockMeans {
  public:
    BlockMeans(const Film& film, const PixelBounds& bounds) {
        constexpr int size = kErrorBlockSize;
        cover_ = {bounds.x0 / size * size, bounds.y0 / size * size,
                  std::min((bounds.x1 + size - 1) / size * size, film.width()),
                  std::min((bounds.y1 + size - 1) / size * size, film.height())};
        means_.resize(size_t(cover_.width()) * size_t(cover_.height()));
        for (int y = cover_.y0; y < cover_.y1; ++y)
            for (int x = cover_.x0; x < cover_.x1; ++x) means_[index(x, y)] = pixel_mean(film, x, y);
    }
    const PixelSum& operator()(int x, int y) const { return means_[index(x, y)]; }

  private:
    size_t index(int x, int y) const { return size_t(y - cover_.y0) * size_t(cover_.width()) + size_t(x - cover_.x0); }
    PixelBounds cover_;
    std::vector<PixelSum> means_;
};

// Orders a and b.
void order(double& a, double& b) {
    const double low = std::min(a, b);
    b = std::max(a, b);
    a = low;
}

// The median of nine values by a fixed network of 19 compare-exchanges (Paeth, Graphics Gems,
// 1990): branch-free, several times faster than a selection, and every interior pixel needs three.
double median_of_nine(double* p) {
    order(p[1], p[2]), order(p[4], p[5]), order(p[7], p[8]);
    order(p[0], p[1]), order(p[3], p[4]), order(p[6], p[7]);
    order(p[1], p[2]), order(p[4], p[5]), order(p[7], p[8]);
    order(p[0], p[3]), order(p[5], p[8]), order(p[4], p[7]);
    order(p[3], p[6]), order(p[1], p[4]), order(p[2], p[5]);
    order(p[4], p[7]), order(p[4], p[2]), order(p[6], p[4]);
    order(p[4], p[2]);
    return p[4];
}

// The median of values[0, count), count in 1..9; reorders them.
double median(double* values, int count) {
    if (count == 9) return median_of_nine(values);
    const int middle = count / 2;
    std::nth_element(values, values + middle, values + count);
    if (count % 2) return values[middle];
    return 0.5 * (*std::max_element(values, values + middle) + values[middle]);
}

// relative_error_scale, with the pixels' means read from `means` (a BlockMeans covering the pixel's
// error block) and the halves' means `a` and `b` (null when the pixel has none).
PixelSum scale_from(const Film& film, int x, int y, const BlockMeans& means, const PixelSum* a, const PixelSum* b) {
    const PixelBounds block = error_block(film, x, y);
    std::array<std::array<double, 9>, 3> around;
    int count = 0;
    for (int v = std::max(y - 1, block.y0); v <= std::min(y + 1, block.y1 - 1); ++v)
        for (int u = std::max(x - 1, block.x0); u <= std::min(x + 1, block.x1 - 1); ++u) {
            const PixelSum& mean = means(u, v);
            for (size_t c = 0; c < 3; ++c) around[c][size_t(count)] = mean[c];
            ++count;
        }
    PixelSum scale{};
    for (size_t c = 0; c < 3; ++c) {
        // Magnitudes: in spectral mode a channel's value can be negative (a wavelength outside the
        // colour space's gamut), and the relative error's denominator is its square.
        scale[c] = std::abs(median(around[c].data(), count));
        if (a) scale[c] = std::max(scale[c], std::min(std::abs((*a)[c]), std::abs((*b)[c])));
    }
    return scale;
}

// The mean over r, g, b of a variance of the mean over (scale^2 + kRelativeErrorEpsilon).
double relative(const PixelSum& v, const PixelSum& scale) {
    double r = 0.0;
    for (size_t c = 0; c < 3; ++c) r += v[c] / (scale[c] * scale[c] + kRelativeErrorEpsilon);
    return r / 3.0;
}

// Pixel (x, y)'s relative variance from the squares or the halves, its neighbours' means from `means`.
double relative_variance_from(const Film& film, int x, int y, VarianceEstimate estimate, const BlockMeans& means) {
    if (film.count(x, y) < 2.0) return std::numeric_limits<double>::infinity();
    PixelSum a{}, b{};
    const bool halves = half_means(film, x, y, a, b);
    const PixelSum v = estimate == VarianceEstimate::kSquares ? variance_of_mean(film, x, y)
                       : halves                               ? halves_variance(film, x, y, a, b)
                                                              : PixelSum{0.0, 0.0, 0.0};
    return relative(v,
                    halves ? scale_from(film, x, y, means, &a, &b) : scale_from(film, x, y, means, nullptr, nullptr));
}

}  // namespace

PixelSum relative_error_scale(const Film& film, int x, int y) {
    CANDELA_CHECK(film.has_statistics());
    PixelSum a{}, b{};
    const bool halves = film.count(x, y) >= 2.0 && half_means(film, x, y, a, b);
    return scale_from(film, x, y, BlockMeans(film, PixelBounds{x, y, x + 1, y + 1}), halves ? &a : nullptr,
                      halves ? &b : nullptr);
}

double relative_variance(const Film& film, int x, int y) {
    return relative_variance_from(film, x, y, VarianceEstimate::kSquares, BlockMeans(film, {x, y, x + 1, y + 1}));
}

double relative_variance_from_halves(const Film& film, int x, int y) {
    return relative_variance_from(film, x, y, VarianceEstimate::kHalves, BlockMeans(film, {x, y, x + 1, y + 1}));
}

void relative_variances(const Film& film, const PixelBounds& bounds, VarianceEstimate estimate,
                        std::vector<double>& out) {
    CANDELA_CHECK(film.has_statistics());
    out.clear();
    const BlockMeans means(film, bounds);
    for (int y = bounds.y0; y < bounds.y1; ++y)
        for (int x = bounds.x0; x < bounds.x1; ++x) out.push_back(relative_variance_from(film, x, y, estimate, means));
}

double estimated_relmse(const Film& film, const std::vector<PixelBounds>& regions) {
    double total = 0.0;
    uint64_t pixels = 0;
    std::vector<double> band;
    for_each_region(film, regions, [&](const PixelBounds& r) {
        // A band of block rows at a time: its means are computed once and stay in cache.
        for (int y0 = r.y0; y0 < r.y1; y0 = (y0 / kErrorBlockSize + 1) * kErrorBlockSize) {
            const int y1 = std::min(r.y1, (y0 / kErrorBlockSize + 1) * kErrorBlockSize);
            relative_variances(film, {r.x0, y0, r.x1, y1}, VarianceEstimate::kHalves, band);
            for (const double relative : band) total += relative;  // row-major, as the pixels
            pixels += band.size();
        }
    });
    return pixels > 0 ? total / double(pixels) : 0.0;
}

SppSummary spp_summary(const Film& film, const std::vector<PixelBounds>& regions) {
    CANDELA_CHECK(film.has_statistics());
    SppSummary s;
    s.min = std::numeric_limits<double>::infinity();
    uint64_t pixels = 0;
    for_each_pixel(film, regions, [&](int x, int y) {
        const double n = film.count(x, y);
        s.total += n;
        s.min = std::min(s.min, n);
        s.max = std::max(s.max, n);
        ++pixels;
    });
    if (pixels == 0) return SppSummary{};
    s.mean = s.total / double(pixels);
    return s;
}

Image variance_image(const Film& film) {
    Image img(film.width(), film.height());
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const PixelSum v = variance_of_mean(film, x, y);
            img.pixels[size_t(y) * size_t(film.width()) + size_t(x)] = Rgb(float(v[0]), float(v[1]), float(v[2]));
        }
    return img;
}

Image spp_image(const Film& film) {
    CANDELA_CHECK(film.has_statistics());
    Image img(film.width(), film.height());
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const float n = float(film.count(x, y));
            img.pixels[size_t(y) * size_t(film.width()) + size_t(x)] = Rgb(n, n, n);
        }
    return img;
}

}  // namespace candela
