#include "bench/spp_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace candela::bench {

namespace {

// sRGB-encoded to linear (IEC 61966-2-1): the panel is written through the sRGB transfer.
float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// Viridis at 0, 1/4, 1/2, 3/4, 1 (matplotlib's table), interpolated linearly in sRGB.
Rgb ramp(float t) {
    static constexpr std::array<std::array<float, 3>, 5> kStops = {{
        {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};
    t = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(int(t), 3);
    const float f = t - float(i);
    Rgb c;
    float* out[3] = {&c.r, &c.g, &c.b};
    for (int k = 0; k < 3; ++k)
        *out[k] = srgb_to_linear(((1.0f - f) * kStops[size_t(i)][size_t(k)] + f * kStops[size_t(i + 1)][size_t(k)]) /
                                 255.0f);
    return c;
}

// Digits 0-9 in a 3x5 pixel font, one row per 3 bits (high bit left).
constexpr std::array<std::array<int, 5>, 10> kDigits = {{{7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7},
                                                         {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7},
                                                         {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7},
                                                         {7, 5, 7, 1, 7}}};
constexpr int kGlyphScale = 2;  // font pixels per image pixel, each way
constexpr int kGlyphAdvance = 4 * kGlyphScale;

// Writes `text` (digits) with its top left at (x, y), in `color`.
void draw_number(Image& image, const std::string& text, int x, int y, Rgb color) {
    for (char ch : text) {
        const auto& glyph = kDigits[size_t(ch - '0')];
        for (int row = 0; row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if ((glyph[size_t(row)] >> (2 - col)) & 1)
                    for (int dy = 0; dy < kGlyphScale; ++dy)
                        for (int dx = 0; dx < kGlyphScale; ++dx) {
                            const int px = x + col * kGlyphScale + dx, py = y + row * kGlyphScale + dy;
                            if (px >= 0 && px < image.width && py >= 0 && py < image.height) image.at(px, py) = color;
                        }
        x += kGlyphAdvance;
    }
}

}  // namespace

Image spp_map_panel(const Image& spp) {
    float lo = INFINITY, hi = 0.0f;
    for (const Rgb& p : spp.pixels) {
        lo = std::min(lo, p.r);
        hi = std::max(hi, p.r);
    }
    lo = std::max(lo, 1.0f);
    hi = std::max(hi, lo);
    // Logarithmic: adaptive counts span decades, and their decision points are geometric.
    const float span = std::log(hi / lo);
    auto t_of = [&](float n) { return span > 0.0f ? std::log(std::max(n, lo) / lo) / span : 1.0f; };
    Image panel(spp.width, spp.height + kSppLegendHeight);
    for (int y = 0; y < spp.height; ++y)
        for (int x = 0; x < spp.width; ++x) panel.at(x, y) = ramp(t_of(spp.at(x, y).r));
    // The legend: the ramp across the width, the counts at its ends in the contrasting colour.
    for (int y = spp.height; y < panel.height; ++y)
        for (int x = 0; x < panel.width; ++x)
            panel.at(x, y) = ramp(panel.width > 1 ? float(x) / float(panel.width - 1) : 1.0f);
    const int text_y = spp.height + (kSppLegendHeight - 5 * kGlyphScale) / 2;
    const std::string low = std::to_string(int(std::lround(lo))), high = std::to_string(int(std::lround(hi)));
    draw_number(panel, low, 3, text_y, Rgb(1.0f, 1.0f, 1.0f));
    draw_number(panel, high, panel.width - 3 - int(high.size()) * kGlyphAdvance + kGlyphScale, text_y,
                Rgb(0.0f, 0.0f, 0.0f));
    return panel;
}

}  // namespace candela::bench
