#pragma once
// c ? a : b without a branch. Where c is random (which wedge of the concentric disk, which
// triangle half) a branch is mispredicted half the time, about 15 cycles each, and GCC turns
// float ternaries into branches. The condition is a comparison of two floats, kept as a lane
// mask in an SSE register (cmpltps, then and/andnot/or): the selection never leaves the vector
// registers. (An integer mask made from a bool did the same without branches, but each select
// moved its operands to integer registers and back, about 7 cycles on the path's critical
// chain; bench/RESULTS.md.) Without SSE, the integer form.
#include <bit>
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

#if defined(__SSE2__)
namespace detail {
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));
}  // namespace detail

// The outcome of x > y, for select().
struct SelectMask {
    detail::Int4 lanes;
};

CANDELA_HD inline SelectMask greater(float x, float y) {
    detail::Float4 xs = {x, x, x, x}, ys = {y, y, y, y};
    return {xs > ys};
}

// The mask's condition ? a : b.
CANDELA_HD inline float select(SelectMask m, float a, float b) {
    detail::Float4 as = {a, a, a, a}, bs = {b, b, b, b};
    return (m.lanes ? as : bs)[0];
}
#else
struct SelectMask {
    uint32_t bits;  // all ones when the condition holds
};

CANDELA_HD inline SelectMask greater(float x, float y) { return {0u - static_cast<uint32_t>(x > y)}; }

CANDELA_HD inline float select(SelectMask m, float a, float b) {
    return std::bit_cast<float>((std::bit_cast<uint32_t>(a) & m.bits) | (std::bit_cast<uint32_t>(b) & ~m.bits));
}
#endif

}  // namespace candela
