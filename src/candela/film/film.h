#pragma once
// The accumulation buffer: per pixel, the sum of its samples in double. Each pixel is written by
// one thread only, in sample-index order, so the sums (and the image) do not depend on how many
// threads render or how tiles are scheduled (DESIGN.md, "Determinism").
#include <array>
#include <cstdint>
#include <vector>

#include "candela/image/image.h"
#include "candela/math/rgb.h"

namespace candela {

class Film {
  public:
    Film(int width, int height);

    // Adds one sample's radiance to pixel (x, y). Not thread-safe for the same pixel.
    void add_sample(int x, int y, const Rgb& value) {
        auto& s = sums_[index(x, y)];
        s[0] += double(value.r);
        s[1] += double(value.g);
        s[2] += double(value.b);
    }

    // The mean over `samples_per_pixel` samples, as floats.
    Image resolve(uint32_t samples_per_pixel) const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }
    int width_, height_;
    std::vector<std::array<double, 3>> sums_;
};

}  // namespace candela
