#pragma once
// The texels of an image texture and their lookup at texture coordinates (s, t).
//
// Coordinates: (0, 0) is the image's bottom-left corner and t grows upward (OBJ's and pbrt's
// convention); rows are stored from the top, as in the file, so row y = (1 - t) height. Texel
// (x, y) covers [x, x + 1) x [y, y + 1) in those units and its centre is at (x + 1/2, y + 1/2):
// bilinear filtering is exact there (pbrt-v4's Image::Bilerp, which subtracts the half texel).
//
// Storage is compact: an 8-bit image keeps its bytes and decodes them through a 256-entry table
// at lookup (the sRGB curve or v / 255; a quarter of the memory of floats for one table load per
// channel); 16-bit and float images are decoded once, at load, to floats (a table of 65536
// entries per image, or the sRGB power per lookup, would cost more than it saves).
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "candela/core/check.h"
#include "candela/core/platform.h"
#include "candela/math/rgb.h"
#include "candela/math/vec.h"

namespace candela {

// What a lookup outside [0, 1) sees: the image repeated, its edge texels extended, or black
// (alpha 0 too). pbrt-v4's WrapMode repeat, clamp, black.
enum class TextureWrap : uint8_t { kRepeat, kClamp, kBlack };
// Bilinear interpolation of the four nearest texel centres, or the texel the point is in.
enum class TextureFilter : uint8_t { kBilinear, kPoint };

// A filtered texel: its colour (grey replicated) and its alpha (1 where the image has none).
struct RgbAlpha {
    Rgb rgb;
    float alpha = 1.0f;
};

struct TextureImage {
    int width = 0;
    int height = 0;
    // Values per texel: grey (1), grey and alpha (2), RGB (3) or RGBA (4). An alpha channel that
    // is 1 everywhere is dropped at load (pbrt-v4's MIPMap does the same).
    int channels = 3;
    std::vector<uint8_t> bytes;            // 8-bit images, row-major from the top
    std::array<float, 256> byte_values{};  // a colour byte's value (alpha is always byte / 255)
    std::vector<float> floats;             // 16-bit and float images, decoded

    CANDELA_HD bool has_alpha() const { return channels == 2 || channels == 4; }

    // Texel (x, y), 0 <= x < width, 0 <= y < height (y from the top).
    CANDELA_HD RgbAlpha texel(int x, int y) const {
        CANDELA_DCHECK(x >= 0 && x < width && y >= 0 && y < height);
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
        if (!bytes.empty())
            return unpack(bytes.data() + i, [this](uint8_t v) { return byte_values[v]; },
                          [](uint8_t v) { return float(v) / 255.0f; });
        auto same = [](float v) { return v; };
        return unpack(floats.data() + i, same, same);
    }

    // The texel (x, y) names under `wrap`: black (alpha 0) outside the image for kBlack.
    CANDELA_HD RgbAlpha fetch(int x, int y, TextureWrap wrap) const {
        if (!wrap_index(x, width, wrap) || !wrap_index(y, height, wrap)) return {Rgb(0.0f), 0.0f};
        return texel(x, y);
    }

    // The image at texture coordinates st ((0, 0) the bottom-left corner, (1, 1) the top-right).
    CANDELA_HD RgbAlpha lookup(Vec2f st, TextureWrap wrap, TextureFilter filter) const {
        const float x = finite_coordinate(st.x * float(width));
        const float y = finite_coordinate((1.0f - st.y) * float(height));
        if (filter == TextureFilter::kPoint) return fetch(floor_to_int(x), floor_to_int(y), wrap);
        // Bilinear between the centres around (x, y), in units where texel i's centre is i.
        const float xc = x - 0.5f, yc = y - 0.5f;
        const float fx = std::floor(xc), fy = std::floor(yc);
        const float dx = xc - fx, dy = yc - fy;
        const int x0 = floor_to_int(fx), y0 = floor_to_int(fy);
        return blend(blend(fetch(x0, y0, wrap), fetch(x0 + 1, y0, wrap), dx),
                     blend(fetch(x0, y0 + 1, wrap), fetch(x0 + 1, y0 + 1, wrap), dx), dy);
    }

    // A filtered texel read as one number (pbrt-v4's MIPMap::Bilerp<Float>): a grey image's
    // value, the alpha of an image with alpha, the average of an RGB image's channels.
    CANDELA_HD float number(const RgbAlpha& v) const {
        if (has_alpha()) return v.alpha;
        return channels == 1 ? v.rgb.r : v.rgb.average();
    }

    // The bytes the texels take (what the scene's memory budget is charged).
    uint64_t memory_bytes() const {
        return uint64_t(bytes.size()) + uint64_t(floats.size()) * sizeof(float) + sizeof(byte_values);
    }

  private:
    template <class T, class Colour, class Alpha>
    CANDELA_HD RgbAlpha unpack(const T* p, Colour colour, Alpha alpha) const {
        switch (channels) {
            case 1: return {Rgb(colour(p[0])), 1.0f};
            case 2: return {Rgb(colour(p[0])), alpha(p[1])};
            case 3: return {Rgb(colour(p[0]), colour(p[1]), colour(p[2])), 1.0f};
            default: return {Rgb(colour(p[0]), colour(p[1]), colour(p[2])), alpha(p[3])};
        }
    }

    CANDELA_HD static RgbAlpha blend(const RgbAlpha& a, const RgbAlpha& b, float t) {
        return {a.rgb * (1.0f - t) + b.rgb * t, a.alpha * (1.0f - t) + b.alpha * t};
    }

    // Moves i into [0, n) as `wrap` says; false when it lies outside and wrap is kBlack.
    CANDELA_HD static bool wrap_index(int& i, int n, TextureWrap wrap) {
        if (i >= 0 && i < n) return true;
        if (wrap == TextureWrap::kBlack) return false;
        if (wrap == TextureWrap::kClamp) {
            i = i < 0 ? 0 : n - 1;
        } else {
            i %= n;
            if (i < 0) i += n;
        }
        return true;
    }

    // v moved into [-2^24, 2^24], NaN to 0: uv may be anything a mesh file holds, and beyond
    // float range a conversion to int is undefined and bilinear weights are NaN. That far out,
    // floats are integers anyway: repeat and clamp land on some texel, black is black.
    CANDELA_HD static float finite_coordinate(float v) {
        constexpr float kLimit = 16777216.0f;
        if (v > -kLimit) return v < kLimit ? v : kLimit;
        return v <= -kLimit ? -kLimit : 0.0f;
    }

    CANDELA_HD static int floor_to_int(float v) { return int(std::floor(v)); }
};

}  // namespace candela
