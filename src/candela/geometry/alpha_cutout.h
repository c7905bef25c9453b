#pragma once
// Alpha cutouts (leaves, fences): a surface whose material has alpha < 1 stops a ray only with
// probability alpha, and lets it through otherwise, for every kind of ray (camera, bounce,
// shadow). The choice is a hash of the ray and the primitive (pbrt-v4's HashFloat of the ray's
// origin and direction, GeometricPrimitive::Intersect), not a sampler dimension: a query then
// needs no random numbers, the same ray always gets the same answer (so intersect() and
// occluded() agree), and images stay the same for any thread count. The accelerator tests it in
// Embree filter functions, installed only on shapes that are cut out.
#include <bit>
#include <cstdint>
#include <vector>

#include "candela/core/mix_bits.h"
#include "candela/core/platform.h"
#include "candela/math/vec.h"
#include "candela/textures/texture_param.h"
#include "candela/textures/texture_set.h"

namespace candela {

// What the accelerator needs to cut shapes out: each shape's alpha (its material's), and the
// textures an alpha may read. Shapes whose alpha is the constant 1 are opaque and cost nothing.
struct AlphaCutouts {
    std::vector<FloatParam> shape_alpha;  // one per shape, or empty: every shape opaque
    const TextureSet* textures = nullptr;  // must outlive the accelerator; needed when any is textured

    // Whether shape `id` may let rays through.
    bool cuts(size_t id) const {
        return id < shape_alpha.size() && (shape_alpha[id].is_textured() || shape_alpha[id].value < 1.0f);
    }
};

// A number in [0, 1) from the ray (o, d) and the primitive it meets: each input bit flips each
// output bit with probability about 1/2 (mix_bits after each 64-bit word).
CANDELA_HD inline float alpha_hash(const Vec3f& o, const Vec3f& d, uint32_t geometry, uint32_t primitive) {
    auto word = [](float a, float b) { return uint64_t(std::bit_cast<uint32_t>(a)) << 32 | std::bit_cast<uint32_t>(b); };
    uint64_t h = mix_bits(word(o.x, o.y));
    h = mix_bits(h ^ word(o.z, d.x));
    h = mix_bits(h ^ word(d.y, d.z));
    h = mix_bits(h ^ (uint64_t(geometry) << 32 | primitive));
    return float(h >> 40) * 0x1p-24f;  // 24 bits: every value exact, the largest 1 - 2^-24
}

// Whether a ray stops at a surface of alpha `alpha` given its hash `u` (alpha_hash): always at
// alpha >= 1, never at alpha <= 0, otherwise with probability alpha.
CANDELA_HD inline bool alpha_stops(float alpha, float u) { return u < alpha; }

}  // namespace candela
