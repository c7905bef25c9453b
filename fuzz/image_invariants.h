#pragma once
// What every image read_image returns must satisfy: a positive size within the documented
// limits, one pixel per position, and finite values.
#include "candela/image/image.h"
#include "candela/image/image_formats.h"
#include "fuzz_support.h"

namespace candela::fuzz {

inline void require_valid_image(const Image& image) {
    require(image.width > 0 && image.height > 0, "a positive image size");
    require(image.width <= image_formats::kMaxImageSide && image.height <= image_formats::kMaxImageSide,
            "the image size within the limit per side");
    require(image.pixels.size() == size_t(image.width) * size_t(image.height), "one pixel per position");
    for (const Rgb& p : image.pixels) require(p.is_finite(), "finite pixels");
}

}  // namespace candela::fuzz
