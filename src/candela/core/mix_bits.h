#pragma once
// The one 64-bit mixing function candela hashes with: the random number generator's seeding
// (sampling/rng.h), the sampler's per-pixel keys, blend and alpha-cutout choices, the layered
// BSDF's seeds, the shard's tile order and the streaming hash (core/hash64.h).
#include <cstdint>

#include "candela/core/platform.h"

namespace candela {

// splitmix64's output function (Steele, Lea, Flood 2014; Stafford's "Mix13" constants): a
// bijection on 64-bit integers where each input bit flips each output bit with probability ~1/2.
// The added golden-ratio increment keeps 0 from mapping to 0.
CANDELA_HD constexpr uint64_t mix_bits(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

}  // namespace candela
