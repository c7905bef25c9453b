#include "candela/film/film.h"

#include "candela/core/check.h"

namespace candela {

Film::Film(int width, int height, bool weighted)
    : width_(width), height_(height), sums_(size_t(width) * size_t(height), {0.0, 0.0, 0.0}),
      weights_(weighted ? sums_.size() : 0, 0.0), weighted_(weighted) {}

Film::Film(int width, int height, std::vector<PixelSum> sums, std::vector<double> weights)
    : width_(width), height_(height), sums_(std::move(sums)), weights_(std::move(weights)), weighted_(!weights_.empty()) {
    CANDELA_CHECK(sums_.size() == size_t(width) * size_t(height));
    CANDELA_CHECK(weights_.empty() || weights_.size() == sums_.size());
}

void Film::read_region(const PixelBounds& region, double* out) const {
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
            const size_t i = index(x, y);
            for (double v : sums_[i]) *out++ = v;
            if (weighted_) *out++ = weights_[i];
        }
}

void Film::write_region(const PixelBounds& region, const double* in) {
    for (int y = region.y0; y < region.y1; ++y)
        for (int x = region.x0; x < region.x1; ++x) {
            const size_t i = index(x, y);
            for (double& v : sums_[i]) v = *in++;
            if (weighted_) weights_[i] = *in++;
        }
}

Image Film::resolve(uint32_t samples_per_pixel) const {
    Image img(width_, height_);
    if (weighted_) {
        for (size_t i = 0; i < sums_.size(); ++i) {
            const double inv_weight = weights_[i] != 0.0 ? 1.0 / weights_[i] : 0.0;
            img.pixels[i] = Rgb(float(sums_[i][0] * inv_weight), float(sums_[i][1] * inv_weight),
                                float(sums_[i][2] * inv_weight));
        }
        return img;
    }
    double inv = samples_per_pixel > 0 ? 1.0 / double(samples_per_pixel) : 0.0;
    for (size_t i = 0; i < sums_.size(); ++i)
        img.pixels[i] = Rgb(float(sums_[i][0] * inv), float(sums_[i][1] * inv), float(sums_[i][2] * inv));
    return img;
}

}  // namespace candela
