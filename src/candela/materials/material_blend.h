#pragma once
// A blend of two materials (pbrt-v4's `mix` material, MixMaterial::ChooseMaterial; Mitsuba's
// `blendbsdf` in expectation): at each shading point it is ONE of its two parts, part 1 with
// probability `amount` and part 0 otherwise. The choice is not a sampler dimension but a hash of
// the point and the outgoing direction (as pbrt-v4's HashFloat(p, wo, m0, m1)): a vertex needs no
// random number for it, the sampler's dimensions stay where they were, and the same (point,
// direction) always gets the same part. Averaged over points the blend scatters as
// (1 - amount) f0 + amount f1, what Mitsuba's blendbsdf evaluates exactly.
//
// candela's `mix` material (material.h, make_mix) is different: it adds its parts' lobes.
#include <array>
#include <bit>
#include <cstdint>

#include "candela/core/mix_bits.h"
#include "candela/core/platform.h"
#include "candela/math/vec.h"
#include "candela/textures/texture_param.h"
#include "candela/textures/texture_set.h"

namespace candela {

struct MaterialBlend {
    std::array<uint32_t, 2> parts{};  // indices into the scene's materials
    // The probability of part 1; a texture's value is clamped to [0, 1] (pbrt-v4 compares it
    // with 0 and 1 instead, which chooses the same parts).
    FloatParam amount{0.5f, kNoTexture, 0.0f, 1.0f};
};

// A number in [0, 1) from the shading point p, the outgoing direction wo (world space, towards
// where the path came from) and the blend's material index: every input bit flips each output bit
// with probability about 1/2 (mix_bits after each 64-bit word, as alpha_hash). The
// index keeps nested blends' choices independent at the same point (pbrt-v4 hashes its two
// parts' addresses).
CANDELA_HD inline float blend_hash(const Vec3f& p, const Vec3f& wo, uint32_t blend) {
    auto word = [](float a, float b) { return uint64_t(std::bit_cast<uint32_t>(a)) << 32 | std::bit_cast<uint32_t>(b); };
    uint64_t h = mix_bits(word(p.x, p.y) ^ (uint64_t(blend) * 0xd6e8feb86659fd93ull));
    h = mix_bits(h ^ word(p.z, wo.x));
    h = mix_bits(h ^ word(wo.y, wo.z));
    return float(h >> 40) * 0x1p-24f;  // 24 bits: every value exact, the largest 1 - 2^-24
}

// The part of blend `b` (material index `self`) that shades at ctx seen from wo: part 0 at
// amount <= 0, part 1 at amount >= 1 (no hash needed), otherwise part 1 when the hash falls below
// amount (pbrt-v4: `amt < u ? m0 : m1`, part 1 with probability amount).
CANDELA_HD inline uint32_t choose_blend_part(const MaterialBlend& b, uint32_t self, const TextureSet& textures,
                                             const TextureContext& ctx, const Vec3f& wo) {
    const float amount = textures.eval(b.amount, ctx);
    if (amount <= 0.0f) return b.parts[0];
    if (amount >= 1.0f) return b.parts[1];
    return amount < blend_hash(ctx.p, wo, self) ? b.parts[0] : b.parts[1];
}

}  // namespace candela
