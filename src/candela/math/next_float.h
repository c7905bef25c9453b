#pragma once
// The neighbouring floats of v, as std::nextafter(v, +-infinity) gives them, but inline: the
// library call costs more than the bit step, and ray spawning does three per ray (pbrt-v4's
// NextFloatUp / NextFloatDown).
#include <bit>
#include <cmath>
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

// The smallest float greater than v (+inf and NaN stay as they are; -0 and +0 go to the smallest
// positive denormal).
CANDELA_HD inline float next_float_up(float v) {
    if (std::isinf(v) && v > 0.0f) return v;
    if (std::isnan(v)) return v;
    if (v == 0.0f) v = 0.0f;  // -0 -> +0, so the step below goes up
    auto bits = std::bit_cast<uint32_t>(v);
    bits = v >= 0.0f ? bits + 1u : bits - 1u;
    return std::bit_cast<float>(bits);
}

// The largest float less than v (-inf and NaN stay as they are).
CANDELA_HD inline float next_float_down(float v) {
    if (std::isinf(v) && v < 0.0f) return v;
    if (std::isnan(v)) return v;
    if (v == 0.0f) v = -0.0f;  // +0 -> -0, so the step below goes down
    auto bits = std::bit_cast<uint32_t>(v);
    bits = v > 0.0f ? bits - 1u : bits + 1u;
    return std::bit_cast<float>(bits);
}

}  // namespace candela
