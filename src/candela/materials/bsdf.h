#pragma once
// A BSDF: the sum of up to kMaxLobes lobes (pbrt-v3's BSDF of several BxDFs). Works in the local
// shading frame, z = shading normal pointing to the surface's front; wo and wi point away from
// the surface. f excludes the cosine. Sampling picks a lobe uniformly and, for a non-delta lobe,
// returns the sum of all lobes' f and the average of all lobes' pdfs (delta lobes' pdf being 0),
// so sample() and pdf() agree for MIS; with a coated lobe among several, whose pdf is no density,
// the chosen lobe's own weight instead (bsdf.cpp). f is not divided by the lobe count: keeping
// the sum energy-conserving is the material's job.
#include <array>
#include <cstdint>
#include <optional>

#include "candela/core/platform.h"
#include "candela/materials/bsdf_lobes.h"
#include "candela/materials/bsdf_sample.h"

namespace candela {

struct Bsdf {
    static constexpr uint32_t kMaxLobes = 4;
    // Each variant holds a default LambertianLobe (a variant always value-initializes its first
    // alternative). The constructor is user-provided so that value-initialization does not add
    // a zeroing of the whole object; GCC 12's std::variant still zero-fills each alternative's
    // storage (416 bytes in all), which is why spectral mode keeps the BSDFs of untextured
    // materials for the whole path (integrators/spectral_bsdf_cache.h) instead of building one per hit.
    std::array<BsdfLobe, kMaxLobes> lobes;
    uint32_t lobe_count = 0;

    CANDELA_HD Bsdf() {}

    // Sum of the lobes' f (delta lobes contribute 0).
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const;
    // Average over all lobes of their pdf, per solid angle (delta lobes contribute 0).
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const;
    // uc picks the lobe, u samples it. nullopt when sampling fails (e.g. below the hemisphere).
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u, TransportMode mode) const;
    // True when every lobe is a delta (light sampling is pointless then).
    CANDELA_HD bool is_delta_only() const;
    // Whether sample() reads uc: to choose among several lobes, or inside the one lobe.
    CANDELA_HD bool uses_choice() const;
    // The colour the `albedo` debug integrator shows: the sum of the lobes' reflectance/tint.
    CANDELA_HD Color albedo() const;
    // Whether some lobe's eval() and pdf() are estimates (a coated lobe, layered.h).
    CANDELA_HD bool has_estimated_lobe() const;
};

}  // namespace candela
