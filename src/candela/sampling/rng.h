#pragma once
// The random number generator behind every sample: PCG32 (O'Neill 2014, "PCG: A Family of Simple
// Fast Space-Efficient Statistically Good Algorithms for Random Number Generation"), 64 bits of
// state, 2^63 selectable streams, 32-bit outputs (XSH RR).
//
// Determinism (DESIGN.md): a renderer draws every number of a camera sample from
// Rng::for_sample(pixel_index, sample_index, scene_seed), in a fixed order. The image is then a
// pure function of those three integers per sample, whatever the thread count, tile order or
// interruption, because no generator state is shared between samples.
#include <cstdint>

#include "candela/core/mix_bits.h"
#include "candela/core/platform.h"
#include "candela/math/vec.h"

namespace candela {

// The 24 high bits of `bits` as a float in [0, 1): multiples of 2^-24, at most 1 - 2^-24, so the
// result is exact and never rounds up to 1.0.
CANDELA_HD constexpr float u32_to_unit_float(uint32_t bits) {
    return static_cast<float>(bits >> 8) * 0x1p-24f;
}

class Rng {
public:
    // The generator for one camera sample: the triple is hashed into both the initial state and
    // the stream, so neighbouring pixels and samples get unrelated sequences.
    CANDELA_HD static constexpr Rng for_sample(uint64_t pixel_index, uint64_t sample_index,
                                               uint64_t seed) {
        // Each step xors one input into a mixed value and mixes again: for fixed other inputs the
        // map from each input to `key` is a bijection, so distinct triples collide only by chance.
        uint64_t key = mix_bits(mix_bits(mix_bits(seed) ^ pixel_index) ^ sample_index);
        return Rng(mix_bits(key), mix_bits(key ^ 0x5851f42d4c957f2dull));
    }

    // O'Neill's pcg32_srandom_r: start `stream` (only its low 63 bits count) at `init_state`.
    CANDELA_HD constexpr Rng(uint64_t init_state, uint64_t stream) : inc_((stream << 1u) | 1u) {
        next_u32();
        state_ += init_state;
        next_u32();
    }
    // pcg32's default generator (the reference implementation's PCG32_INITIALIZER).
    CANDELA_HD constexpr Rng() : state_(0x853c49e6748fea9bull), inc_(0xda3e39cb94b95bdbull) {}

    // A generator in exactly this raw state (increment forced odd), for tests that need outputs
    // from chosen states.
    CANDELA_HD static constexpr Rng from_raw_state(uint64_t state, uint64_t increment) {
        Rng r;
        r.state_ = state;
        r.inc_ = increment | 1u;
        return r;
    }

    // Uniform over all 32-bit integers.
    CANDELA_HD constexpr uint32_t next_u32() {
        uint64_t old = state_;
        state_ = old * kMultiplier + inc_;
        auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1), never 1.0 (see u32_to_unit_float).
    CANDELA_HD constexpr float next_float() { return u32_to_unit_float(next_u32()); }
    // Two uniforms in [0, 1)^2, x drawn first.
    CANDELA_HD constexpr Vec2f next_vec2f() {
        float x = next_float();
        float y = next_float();
        return {x, y};
    }

    // Skips `delta` outputs (negative goes back) in O(log delta) (Brown 1994, "Random Number
    // Generation with Arbitrary Strides": the LCG's affine step raised to the delta-th power).
    CANDELA_HD constexpr void advance(int64_t delta) {
        uint64_t cur_mult = kMultiplier, cur_plus = inc_, acc_mult = 1u, acc_plus = 0u;
        auto d = static_cast<uint64_t>(delta);  // two's complement: -1 is a full period minus one
        while (d > 0) {
            if (d & 1u) {
                acc_mult *= cur_mult;
                acc_plus = acc_plus * cur_mult + cur_plus;
            }
            cur_plus = (cur_mult + 1u) * cur_plus;
            cur_mult *= cur_mult;
            d >>= 1u;
        }
        state_ = acc_mult * state_ + acc_plus;
    }

    CANDELA_HD constexpr bool operator==(const Rng&) const = default;

private:
    static constexpr uint64_t kMultiplier = 0x5851f42d4c957f2dull;
    uint64_t state_ = 0;
    uint64_t inc_ = 1;
};

}  // namespace candela
