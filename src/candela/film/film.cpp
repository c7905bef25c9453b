#include "candela/film/film.h"

#include "candela/core/check.h"

namespace candela {

Film::Film(int width, int height)
    : width_(width), height_(height), sums_(size_t(width) * size_t(height), {0.0, 0.0, 0.0}) {}

Film::Film(int width, int height, std::vector<PixelSum> sums)
    : width_(width), height_(height), sums_(std::move(sums)) {
    CANDELA_CHECK(sums_.size() == size_t(width) * size_t(height));
}

Image Film::resolve(uint32_t samples_per_pixel) const {
    Image img(width_, height_);
    double inv = samples_per_pixel > 0 ? 1.0 / double(samples_per_pixel) : 0.0;
    for (size_t i = 0; i < sums_.size(); ++i)
        img.pixels[i] = Rgb(float(sums_[i][0] * inv), float(sums_[i][1] * inv), float(sums_[i][2] * inv));
    return img;
}

}  // namespace candela
