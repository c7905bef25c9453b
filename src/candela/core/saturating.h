#pragma once
// Unsigned arithmetic that saturates at UINT64_MAX instead of wrapping: for sizes computed from
// counts a file claims (a header may claim any count), which must compare as "too large", never
// wrap to small.
#include <cstdint>

namespace candela {

inline uint64_t saturating_product(uint64_t a, uint64_t b) {
    uint64_t r = 0;
    return __builtin_mul_overflow(a, b, &r) ? UINT64_MAX : r;
}

inline uint64_t saturating_sum(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

}  // namespace candela
