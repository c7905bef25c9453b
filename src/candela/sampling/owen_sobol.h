#pragma once
// Owen-scrambled Sobol points, randomized by hashing (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)).
//
// Only the first two Sobol dimensions are used: together they are a (0,2)-sequence in base 2, so
// every aligned block of 2^m consecutive points is a (0,m,2)-net (each of the 2^m elementary
// rectangles of area 2^-m holds exactly one point). Higher dimensions are "padded": each request
// of a path (a 1D or 2D sample) gets its own randomly shuffled copy of the sequence, so the pairs a
// path draws are each well stratified and mutually uncorrelated. Padding gives up the joint
// stratification of, say, the light point with the BSDF direction, which high-dimensional Sobol
// points would offer; in exchange no dimension is ever of poor quality (Sobol's high dimensions
// are, for small sample counts) and the allocation is trivially well defined.
//
// Nested uniform (Owen) scrambling keeps the net property and turns the error of smooth integrands
// from the randomly-shifted O(N^-1) into O(N^-1.5) in RMSE.
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

// The 32 bits of x in reverse order.
CANDELA_HD constexpr uint32_t reverse_bits(uint32_t x) {
    x = __builtin_bswap32(x);  // the bytes in one instruction, then the bits within each byte
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// The bits of each 32-bit half of x in reverse order, the halves swapped: two reverse_bits for
// the price of one (the x and y of a 2D sample).
CANDELA_HD constexpr uint64_t reverse_bits_of_halves(uint64_t x) {
    x = __builtin_bswap64(x);
    x = ((x & 0x0f0f0f0f0f0f0f0full) << 4) | ((x & 0xf0f0f0f0f0f0f0f0ull) >> 4);
    x = ((x & 0x3333333333333333ull) << 2) | ((x & 0xccccccccccccccccull) >> 2);
    x = ((x & 0x5555555555555555ull) << 1) | ((x & 0xaaaaaaaaaaaaaaaaull) >> 1);
    return x;
}

// Laine and Karras's hash (2011, as improved by Burley 2020): a bijection on 32-bit integers in
// which bit k of the output depends only on bits 0..k of the input (additions and multiplications
// by even constants carry only upwards), randomly enough to act as an Owen scramble of the
// bit-reversed value.
CANDELA_HD constexpr uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scrambling of a 32-bit fixed-point fraction in [0, 1): each bit is flipped by a random
// function of the bits above it (more significant), so points in one dyadic interval stay
// together and every elementary interval is permuted as a whole.
CANDELA_HD constexpr uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// The 32-bit fractions of Sobol point `index` in dimensions 0 and 1. Dimension 0 is the van der
// Corput sequence (the bit-reversed index); dimension 1 uses the direction numbers of the
// primitive polynomial x + 1, v_k = v_{k-1} xor (v_{k-1} >> 1) from v_0 = 2^31.
CANDELA_HD constexpr uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

// Dimension 1 bit by bit: the xor of the direction numbers of the index's set bits.
CANDELA_HD constexpr uint32_t sobol_dimension1_reference(uint32_t index) {
    uint32_t result = 0, v = 0x80000000u;
    for (; index != 0; index >>= 1u, v ^= v >> 1u)
        if (index & 1u) result ^= v;
    return result;
}

namespace detail {
// The generator matrix of dimension 1 applied to each byte of the index on its own: the xor of
// four lookups replaces a loop over 32 bits (shuffled indices use all of them).
// Bit reversal is linear over xor, so the tables can as well hold the reversed values (what Owen
// scrambling works on) and save a reversal per sample.
struct SobolByteTables {
    uint32_t t[4][256];
};
constexpr SobolByteTables make_sobol_byte_tables(bool reversed) {
    SobolByteTables tables{};
    for (uint32_t byte = 0; byte < 4; ++byte)
        for (uint32_t value = 0; value < 256; ++value) {
            uint32_t v = sobol_dimension1_reference(value << (8u * byte));
            tables.t[byte][value] = reversed ? reverse_bits(v) : v;
        }
    return tables;
}
inline constexpr SobolByteTables kSobolByteTables = make_sobol_byte_tables(false);
inline constexpr SobolByteTables kSobolReversedByteTables = make_sobol_byte_tables(true);

CANDELA_HD constexpr uint32_t apply_byte_tables(const SobolByteTables& tables, uint32_t index) {
    const auto& t = tables.t;
    return t[0][index & 0xffu] ^ t[1][(index >> 8u) & 0xffu] ^ t[2][(index >> 16u) & 0xffu] ^ t[3][index >> 24u];
}
}  // namespace detail

CANDELA_HD constexpr uint32_t sobol_dimension1(uint32_t index) {
    return detail::apply_byte_tables(detail::kSobolByteTables, index);
}
// reverse_bits(sobol_dimension1(index)).
CANDELA_HD constexpr uint32_t sobol_dimension1_reversed(uint32_t index) {
    return detail::apply_byte_tables(detail::kSobolReversedByteTables, index);
}

}  // namespace candela
