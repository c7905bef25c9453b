// candela_side_by_side OUT.png IMAGE... [--diff] [--scale S] [--spp-map EXR]: the images (same
// size) next to each other in one PNG for the README, each multiplied by S (default 1) and clamped
// to [0, 1] in linear sRGB before the sRGB transfer; with --diff a last panel shows
// |first - second| x 4 (grey = luminance difference); with --spp-map a last panel shows the `spp`
// channel of an adaptive render's .exr (--aov spp) on a colour ramp with its legend (spp_map.h;
// not scaled), and the other panels get a black strip below to match its height. Comparison
// figures (MIS against no MIS, candela against pbrt-v4) are made with it; its commands are in
// docs/images/README.md.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "bench/spp_map.h"
#include "candela/image/image_io.h"
#include "candela/image/image_layers.h"

using candela::Image;
using candela::Rgb;

int main(int argc, char** argv) {
    std::vector<std::string> inputs;
    std::string out;
    bool diff = false;
    float scale = 1.0f;
    std::string spp_map;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--diff") diff = true;
        else if (a == "--spp-map" && i + 1 < argc) spp_map = argv[++i];
        else if (a == "--scale" && i + 1 < argc) scale = std::stof(argv[++i]);
        else if (out.empty()) out = a;
        else inputs.push_back(a);
    }
    if (out.empty() || inputs.empty() || (diff && inputs.size() < 2)) {
        fmt::print(stderr, "usage: candela_side_by_side OUT.png IMAGE... [--diff] [--scale S] [--spp-map EXR]\n");
        return 2;
    }
    try {
        std::vector<Image> images;
        for (const std::string& f : inputs) images.push_back(candela::read_image(f));
        const int w = images[0].width, h = images[0].height;
        for (size_t k = 1; k < images.size(); ++k)
            if (images[k].width != w || images[k].height != h)
                throw std::runtime_error(fmt::format("{} is {}x{}, {} is {}x{}", inputs[k], images[k].width,
                                                     images[k].height, inputs[0], w, h));
        if (diff) {
            Image d(w, h);
            for (size_t p = 0; p < d.pixels.size(); ++p) {
                float l = std::abs(images[0].pixels[p].luminance() - images[1].pixels[p].luminance());
                d.pixels[p] = Rgb(4.0f * l / scale);
            }
            images.push_back(d);
        }
        std::vector<float> scales(images.size(), scale);
        if (!spp_map.empty()) {
            const Image spp = candela::read_exr_channels(spp_map, {"spp"});
            if (spp.width != w || spp.height != h)
                throw std::runtime_error(fmt::format("{}'s spp channel is {}x{}, {} is {}x{}", spp_map, spp.width,
                                                     spp.height, inputs[0], w, h));
            images.push_back(candela::bench::spp_map_panel(spp));
            scales.push_back(1.0f);
        }
        const int gap = 4;
        const int n = static_cast<int>(images.size());
        int sheet_h = 0;
        for (const Image& im : images) sheet_h = std::max(sheet_h, im.height);
        Image sheet(n * w + (n - 1) * gap, sheet_h);
        for (int k = 0; k < n; ++k)
            for (int y = 0; y < images[k].height; ++y)
                for (int x = 0; x < w; ++x)
                    sheet.at(k * (w + gap) + x, y) = images[k].at(x, y) * scales[size_t(k)];
        candela::write_image(out, sheet, candela::DisplayEncoding{});
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela_side_by_side: {}\n", e.what());
        return 2;
    }
}
