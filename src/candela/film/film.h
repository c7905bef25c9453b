#pragma once
// The accumulation buffer: per pixel, the sum of its samples in double. Each pixel is written by
// one thread only, in sample-index order, so the sums (and the image) do not depend on how many
// threads render or how tiles are scheduled (DESIGN.md, "Determinism"). Checkpoints save and
// restore the sums exactly, so a resumed render goes on adding to the same doubles.
#include <array>
#include <cstdint>
#include <vector>

#include "candela/image/image.h"
#include "candela/math/rgb.h"

namespace candela {

// One pixel's running sum of sample values, r, g, b.
using PixelSum = std::array<double, 3>;

// Adds one sample's value to a running sum: the only arithmetic a sample value goes through.
inline void add_to_sum(PixelSum& sum, const Rgb& value) {
    sum[0] += double(value.r);
    sum[1] += double(value.g);
    sum[2] += double(value.b);
}

class Film {
  public:
    Film() = default;  // 0 x 0
    Film(int width, int height);
    // A film holding these sums (row-major, width * height of them), e.g. read from a checkpoint.
    Film(int width, int height, std::vector<PixelSum> sums);

    // Adds one sample's radiance to pixel (x, y). Not thread-safe for the same pixel.
    void add_sample(int x, int y, const Rgb& value) { add_to_sum(sums_[index(x, y)], value); }

    PixelSum& sum(int x, int y) { return sums_[index(x, y)]; }
    const PixelSum& sum(int x, int y) const { return sums_[index(x, y)]; }
    // All sums, row-major.
    const std::vector<PixelSum>& sums() const { return sums_; }

    // The mean over `samples_per_pixel` samples, as floats.
    Image resolve(uint32_t samples_per_pixel) const;

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }
    int width_ = 0, height_ = 0;
    std::vector<PixelSum> sums_;
};

}  // namespace candela
