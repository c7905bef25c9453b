#include "candela/film/pixel_statistics.h"

#include <algorithm>
#include <bit>
#include <limits>

#include "candela/core/check.h"

namespace candela {

namespace {

// Calls f(x, y) for every pixel of `regions`, or of the whole film when there are none.
template <class F>
void for_each_pixel(const Film& film, const std::vector<PixelBounds>& regions, F&& f) {
    auto visit_region = [&](const PixelBounds& r) {
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) f(x, y);
    };
    if (regions.empty())
        visit_region(PixelBounds{0, 0, film.width(), film.height()});
    else
        for (const PixelBounds& r : regions) visit_region(r);
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

PixelSum variance_of_mean_from_halves(const Film& film, int x, int y) {
    CANDELA_CHECK(film.has_statistics());
    const double n = film.count(x, y);
    if (n < 2.0) return {0.0, 0.0, 0.0};
    const PrefixSums& p = film.prefix_sums(x, y);
    const double first_weight = double(p.weight[0]), second_weight = double(p.weight[1]) - double(p.weight[0]);
    // A weighted pixel whose samples in one half all had weight 0 has no mean there.
    if (!(first_weight > 0.0 && second_weight > 0.0)) return {0.0, 0.0, 0.0};
    const double power = std::bit_floor(uint64_t(n));
    PixelSum v{};
    for (size_t c = 0; c < 3; ++c) {
        const double a = double(p.sum[0][c]) / first_weight;
        const double b = (double(p.sum[1][c]) - double(p.sum[0][c])) / second_weight;
        v[c] = (a - b) * (a - b) / 4.0 * (power / n);
    }
    return v;
}

namespace {

// The mean over r, g, b of a variance of the mean over (value^2 + kRelativeErrorEpsilon).
double relative(const Film& film, int x, int y, const PixelSum& v) {
    const double n = film.count(x, y);
    const PixelSum& sum = film.sum(x, y);
    const double to_value = value_scale(film, x, y) / n;
    double r = 0.0;
    for (size_t c = 0; c < 3; ++c) {
        const double mean = sum[c] * to_value;
        r += v[c] / (mean * mean + kRelativeErrorEpsilon);
    }
    return r / 3.0;
}

}  // namespace

double relative_variance(const Film& film, int x, int y) {
    if (film.count(x, y) < 2.0) return std::numeric_limits<double>::infinity();
    return relative(film, x, y, variance_of_mean(film, x, y));
}

double relative_variance_from_halves(const Film& film, int x, int y) {
    if (film.count(x, y) < 2.0) return std::numeric_limits<double>::infinity();
    return relative(film, x, y, variance_of_mean_from_halves(film, x, y));
}

double estimated_relmse(const Film& film, const std::vector<PixelBounds>& regions) {
    double total = 0.0;
    uint64_t pixels = 0;
    for_each_pixel(film, regions, [&](int x, int y) {
        total += relative_variance_from_halves(film, x, y);
        ++pixels;
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
