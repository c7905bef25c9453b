#pragma once
// From linear radiance to display values: a tone map squeezes [0, inf) into [0, 1], a transfer
// curve encodes the result for an 8-bit display file. PNG and PPM output both go through
// to_display_bytes, so the two formats agree byte for byte.
#include <array>
#include <cstdint>

#include "candela/image/display_encoding.h"
#include "candela/math/rgb.h"

namespace candela {

// Tone maps each channel (negative values count as 0). kClamp: min(c, 1); kExposure: the seed's
// 1 - exp(-c / (1 - exposure)), exposure in [0, 1); kReinhard: c / (1 + c); kAces: Narkowicz's
// 2015 fit of the ACES filmic curve, clamped to [0, 1]. The result is in [0, 1].
Rgb tonemap(Rgb linear, const DisplayEncoding& film);

// The sRGB OETF (IEC 61966-2-1, piecewise: linear below 0.0031308), for v in [0, 1].
float encode_srgb(float v);

// The inverse of encode_srgb: an sRGB-encoded value in [0, 1] to linear.
float decode_srgb(float v);

// Encodes a tone-mapped value with the film's transfer: the sRGB curve, or v^(1 / gamma).
float encode_transfer(float v, const DisplayEncoding& film);

// Quantizes an encoded display value to 8 bits: round(255 * clamp(v, 0, 1)); NaN gives 0.
uint8_t quantize_display(float encoded);

// The 8-bit display value of a linear pixel: quantize_display(encode_transfer(tonemap(c))).
std::array<uint8_t, 3> to_display_bytes(Rgb linear, const DisplayEncoding& film);

}  // namespace candela
