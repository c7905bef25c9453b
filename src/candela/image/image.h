#pragma once
// A linear RGB float image, row-major, (0, 0) the top-left pixel.
#include <array>
#include <string>
#include <vector>

#include "candela/math/rgb.h"

namespace candela {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Rgb> pixels;

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h)) {}
    Rgb& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const Rgb& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// A named layer written beside an image's RGB (an AOV, film/aov_layers.h): 1 to 3 channels, the
// first in each pixel's r, the second in g, the third in b.
struct ImageLayer {
    std::string name;                     // e.g. "albedo": the side file's infix
    int channels = 3;
    std::array<std::string, 3> channel_names;  // OpenEXR channel names, e.g. "albedo.R"
    Image image;
};

}  // namespace candela
