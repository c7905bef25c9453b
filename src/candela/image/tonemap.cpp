#include "candela/image/tonemap.h"

#include <algorithm>
#include <cmath>

#include "candela/core/check.h"

namespace candela {

namespace {

float tonemap_channel(float c, const DisplayEncoding& film) {
    c = std::max(c, 0.0f);
    switch (film.tonemap) {
        case Tonemap::kClamp:
            return std::min(c, 1.0f);
        case Tonemap::kExposure:
            // The seed's curve: exposure 0 maps radiance 1 to 1 - 1/e; larger values brighten.
            return 1.0f - std::exp(-c / (1.0f - film.exposure));
        case Tonemap::kReinhard:
            return c / (1.0f + c);
        case Tonemap::kAces: {
            // Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit of the RRT+ODT.
            constexpr float a = 2.51f, b = 0.03f, cc = 2.43f, d = 0.59f, e = 0.14f;
            return std::clamp((c * (a * c + b)) / (c * (cc * c + d) + e), 0.0f, 1.0f);
        }
    }
    return std::min(c, 1.0f);
}

// In double, so the 8-bit output matches smallpt's (double) pow(x, 1 / 2.2) rounding.
double encode_srgb_exact(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double encode_transfer_exact(double v, const DisplayEncoding& film) {
    switch (film.transfer) {
        case Transfer::kSrgb:
            return encode_srgb_exact(v);
        case Transfer::kGamma:
            return std::pow(std::max(v, 0.0), 1.0 / static_cast<double>(film.gamma));
    }
    return encode_srgb_exact(v);
}

uint8_t quantize_exact(double encoded) {
    if (!(encoded > 0.0)) return 0;  // also NaN
    return static_cast<uint8_t>(std::min(encoded, 1.0) * 255.0 + 0.5);
}

}  // namespace

Rgb tonemap(Rgb linear, const DisplayEncoding& film) {
    CANDELA_DCHECK(film.tonemap != Tonemap::kExposure || (film.exposure >= 0.0f && film.exposure < 1.0f));
    return {tonemap_channel(linear.r, film), tonemap_channel(linear.g, film),
            tonemap_channel(linear.b, film)};
}

float encode_srgb(float v) { return static_cast<float>(encode_srgb_exact(static_cast<double>(v))); }

float decode_srgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float encode_transfer(float v, const DisplayEncoding& film) {
    return static_cast<float>(encode_transfer_exact(static_cast<double>(v), film));
}

uint8_t quantize_display(float encoded) { return quantize_exact(static_cast<double>(encoded)); }

std::array<uint8_t, 3> to_display_bytes(Rgb linear, const DisplayEncoding& film) {
    const Rgb mapped = tonemap(linear, film);
    std::array<uint8_t, 3> bytes{};
    for (int i = 0; i < 3; ++i)
        bytes[size_t(i)] = quantize_exact(encode_transfer_exact(static_cast<double>(mapped[i]), film));
    return bytes;
}

}  // namespace candela
