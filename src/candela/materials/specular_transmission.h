#pragma once
// Refraction only through a smooth dielectric interface, weighted by the transmitted fraction
// 1 - F (pbrt-v3 SpecularTransmission): the reflected part is simply lost, so this lobe alone is
// not energy conserving, and under total internal reflection it is black. The sample has pdf 1
// and f = tint (1 - F) / |cos wi|, times 1 / eta'^2 for radiance (eta' = eta_t / eta_i crossed).
// The front (wo.z > 0) is outside; eta is the index inside over the index outside.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"

namespace candela {

struct SpecularTransmissionLobe {
    Color tint{1.0f};
    float eta = 1.5f;

    // 0: a delta lobe.
    CANDELA_HD Color eval(const Vec3f&, const Vec3f&, TransportMode) const { return Color(0.0f); }
    // 0: a delta lobe.
    CANDELA_HD float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }
    // The refracted direction (uc and u unused); nullopt under total internal reflection.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float, const Vec2f&,
                                                TransportMode mode) const {
        if (wo.z == 0.0f) return std::nullopt;
        BsdfSample s;
        float eta_rel = 1.0f;
        if (!refract(wo, Vec3f(0.0f, 0.0f, 1.0f), eta, &s.wi, &eta_rel)) return std::nullopt;
        if (s.wi.z == 0.0f) return std::nullopt;
        // F is the same seen from either side of the interface (reciprocity), so wo's angle
        // serves for pbrt's F(cos wi).
        float f_t = 1.0f - fresnel_dielectric(cos_theta(wo), eta);
        if (mode == TransportMode::kRadiance) f_t /= eta_rel * eta_rel;
        s.f = tint * (f_t / abs_cos_theta(s.wi));
        s.pdf = 1.0f;
        s.is_delta = true;
        s.is_transmission = true;
        s.eta = eta_rel;
        return s;
    }
    static constexpr bool kUsesChoice = false;
    CANDELA_HD bool is_delta() const { return true; }
    CANDELA_HD Color albedo() const { return tint; }
};
static_assert(BsdfLobeType<SpecularTransmissionLobe>);

}  // namespace candela
