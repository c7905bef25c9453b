#pragma once
// Smooth glass: reflection and refraction at a dielectric interface, chosen in proportion to the
// Fresnel reflectance F (pbrt-v3 FresnelSpecular). The reflected sample has f = tint F / |cos wi|
// and probability F, the refracted one f = tint (1 - F) / |cos wi| and probability 1 - F, so each
// carries the weight f |cos| / pdf = tint, times 1 / eta'^2 for refraction of radiance (eta' the
// index ratio eta_t / eta_i crossed; Veach's thesis 5.2). Under total internal reflection F = 1.
//
// The front (wo.z > 0) is outside, and eta is the index inside over the index outside. With
// `schlick`, F is Schlick's approximation with r0 = ((eta - 1) / (eta + 1))^2 taken at the larger
// of the incident and refracted angles (the one on the optically thinner side), which is what
// smallpt does for glass in air; otherwise F is the exact unpolarized Fresnel reflectance.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"

namespace candela {

struct FresnelSpecularLobe {
    Color tint{1.0f};  // multiplies reflected and refracted light alike
    float eta = 1.5f;
    bool schlick = false;

    // The fraction reflected for light arriving along wo (1 under total internal reflection).
    CANDELA_HD float reflectance(const Vec3f& wo) const {
        if (!schlick) return fresnel_dielectric(cos_theta(wo), eta);
        Vec3f wt;
        if (!refract(wo, Vec3f(0.0f, 0.0f, 1.0f), eta, &wt)) return 1.0f;
        float cos_i = abs_cos_theta(wo), cos_t = abs_cos_theta(wt);
        return fresnel_schlick(fresnel_r0(eta), cos_i < cos_t ? cos_i : cos_t);
    }

    // 0: a delta lobe.
    CANDELA_HD Color eval(const Vec3f&, const Vec3f&, TransportMode) const { return Color(0.0f); }
    // 0: a delta lobe.
    CANDELA_HD float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }
    // Reflects when uc < F, else refracts (u unused); nullopt for wo in the plane.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f&,
                                                TransportMode mode) const {
        if (wo.z == 0.0f) return std::nullopt;
        float f_r = reflectance(wo);
        BsdfSample s;
        s.is_delta = true;
        if (uc < f_r) {
            s.wi = {-wo.x, -wo.y, wo.z};
            s.f = tint * (f_r / abs_cos_theta(s.wi));
            s.pdf = f_r;
            return s;
        }
        // uc >= F implies F < 1, so no total internal reflection: refract cannot fail here
        // except by rounding at the critical angle, where F's own test decided otherwise.
        float eta_rel = 1.0f;
        if (!refract(wo, Vec3f(0.0f, 0.0f, 1.0f), eta, &s.wi, &eta_rel)) return std::nullopt;
        if (s.wi.z == 0.0f) return std::nullopt;
        float f_t = 1.0f - f_r;
        if (mode == TransportMode::kRadiance) f_t /= eta_rel * eta_rel;
        s.f = tint * (f_t / abs_cos_theta(s.wi));
        s.pdf = 1.0f - f_r;
        s.is_transmission = true;
        s.eta = eta_rel;
        return s;
    }
    static constexpr bool kUsesChoice = true;
    CANDELA_HD bool is_delta() const { return true; }
    CANDELA_HD Color albedo() const { return tint; }
};
static_assert(BsdfLobeType<FresnelSpecularLobe>);

}  // namespace candela
