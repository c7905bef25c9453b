#pragma once
// c ? a : b without a branch. Where c is random (which wedge of the concentric disk, which
// triangle half) a branch is mispredicted half the time, about 15 cycles each, and GCC turns
// float ternaries into branches; bit masks keep the selection in the data path.
#include <bit>
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

CANDELA_HD inline float select(bool c, float a, float b) {
    const uint32_t mask = 0u - static_cast<uint32_t>(c);  // all ones when c
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & mask) | (std::bit_cast<uint32_t>(b) & ~mask));
}

}  // namespace candela
