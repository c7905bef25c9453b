#pragma once
// The dielectric coat of a layered lobe (layered.h): DielectricLobe's smooth or rough interface
// (pbrt-v4's DielectricBxDF, no tint) whose sampling and density can be restricted to reflection
// or to transmission, as the random walk between the layers needs (pbrt-v4's
// BxDFReflTransFlags). Restricted to one side, the interface chooses that side with probability
// 1 instead of F or 1 - F: the value f is unchanged, the density is divided by the probability
// of the choice. The front (wo.z > 0) is outside the coat and eta is the coat's index over the
// outside's.
#include <cstdint>
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/dielectric.h"
#include "candela/materials/fresnel.h"
#include "candela/materials/trowbridge_reitz.h"

namespace candela {

// Which of reflection and transmission a restricted sample or density may use.
enum class ReflTrans : uint8_t { kReflection = 1, kTransmission = 2, kAll = 3 };

CANDELA_HD inline bool allows(ReflTrans flags, ReflTrans side) {
    return (static_cast<uint8_t>(flags) & static_cast<uint8_t>(side)) != 0;
}

// The other transport mode: the walk from wi towards the layers carries importance when the
// lobe is evaluated for radiance, and the other way round (pbrt-v4's !mode).
CANDELA_HD inline TransportMode reversed(TransportMode mode) {
    return mode == TransportMode::kRadiance ? TransportMode::kImportance : TransportMode::kRadiance;
}

struct CoatInterface {
    float eta = 1.5f;
    TrowbridgeReitz distribution;

    // Perfectly smooth (or index-matched): it scatters into isolated directions only.
    CANDELA_HD bool is_specular() const { return eta == 1.0f || distribution.effectively_smooth(); }

    // f(wo, wi) without the cosine, as DielectricLobe; 0 when specular.
    CANDELA_HD Color f(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
        return DielectricLobe{Color(1.0f), eta, distribution}.eval(wo, wi, mode);
    }

    // The probability that a sample restricted by `flags` reflects, given Fresnel reflectance
    // `fresnel` (pbrt-v4's pr / (pr + pt)); negative when `flags` leaves nothing to choose.
    CANDELA_HD static float reflect_probability(float fresnel, ReflTrans flags) {
        float pr = allows(flags, ReflTrans::kReflection) ? fresnel : 0.0f;
        float pt = allows(flags, ReflTrans::kTransmission) ? 1.0f - fresnel : 0.0f;
        if (pr == 0.0f && pt == 0.0f) return -1.0f;
        return pr / (pr + pt);
    }

    // The density of sample(wo, ., ., ., flags) at wi per solid angle; 0 when specular.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi, ReflTrans flags = ReflTrans::kAll) const {
        if (is_specular()) return 0.0f;
        float cos_o = cos_theta(wo), cos_i = cos_theta(wi);
        if (cos_o == 0.0f || cos_i == 0.0f) return 0.0f;
        bool reflection = cos_o * cos_i > 0.0f;
        float eta_rel = reflection ? 1.0f : (cos_o > 0.0f ? eta : 1.0f / eta);
        Vec3f wm = wo + wi * eta_rel;
        float len2 = length_squared(wm);
        if (!(len2 > 0.0f)) return 0.0f;
        wm = wm * (1.0f / std::sqrt(len2));
        if (wm.z < 0.0f) wm = -wm;
        float wo_dot_wm = dot(wo, wm), wi_dot_wm = dot(wi, wm);
        if (wo_dot_wm * cos_o <= 0.0f || wi_dot_wm * cos_i <= 0.0f) return 0.0f;
        // The Fresnel term as DielectricLobe takes it: for a refraction, from the cosine on the
        // optically thinner side (the same value, without the cancellation near the critical
        // angle on the denser side).
        bool wo_rarer = reflection || (cos_o > 0.0f) == (eta > 1.0f);
        float fresnel = fresnel_dielectric(wo_rarer ? wo_dot_wm : wi_dot_wm, eta);
        float p_reflect = reflect_probability(fresnel, flags);
        if (p_reflect < 0.0f) return 0.0f;
        float pdf_wm = distribution.pdf(wo, wm);
        if (reflection) return pdf_wm / (4.0f * std::abs(wo_dot_wm)) * p_reflect;
        float denom = sqr(wi_dot_wm + wo_dot_wm / eta_rel);
        return pdf_wm * std::abs(wi_dot_wm) / denom * (1.0f - p_reflect);
    }

    // A direction for wo restricted by `flags`: a visible normal from u (rough) or the surface
    // normal (smooth), then reflection when uc < the restricted reflection probability and
    // refraction otherwise. nullopt for wo in the plane, when `flags` allows nothing, under total
    // internal reflection when only transmission is allowed, or for a direction that ends on the
    // wrong side. For a specular interface pdf is the probability of the choice (is_delta).
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                TransportMode mode, ReflTrans flags = ReflTrans::kAll) const {
        std::optional<BsdfSample> result;
        if (wo.z == 0.0f) return result;
        bool specular = is_specular();
        Vec3f wm = specular ? Vec3f(0.0f, 0.0f, 1.0f) : distribution.sample_wm(wo, u);
        float fresnel = fresnel_dielectric(dot(wo, wm), eta);
        float p_reflect = reflect_probability(fresnel, flags);
        if (p_reflect < 0.0f) return result;
        if (uc < p_reflect) {
            Vec3f wi = reflect(wo, wm);
            if (!same_hemisphere(wo, wi)) return result;
            BsdfSample& s = result.emplace();
            s.wi = wi;
            if (specular) {
                s.f = Color(fresnel / abs_cos_theta(s.wi));
                s.pdf = p_reflect;
                s.is_delta = true;
                return result;
            }
            s.f = f(wo, wi, mode);
            s.pdf = distribution.pdf(wo, wm) / (4.0f * std::abs(dot(wo, wm))) * p_reflect;
            return result;
        }
        Vec3f wi;
        float eta_rel = 1.0f;
        if (!refract(wo, wm, eta, &wi, &eta_rel) || !(wi.z * wo.z < 0.0f)) return result;
        BsdfSample& s = result.emplace();
        s.wi = wi;
        s.is_transmission = true;
        s.eta = eta_rel;
        if (specular) {
            float f_t = (1.0f - fresnel) / abs_cos_theta(wi);
            if (mode == TransportMode::kRadiance) f_t /= eta_rel * eta_rel;
            s.f = Color(f_t);
            s.pdf = 1.0f - p_reflect;
            s.is_delta = true;
            return result;
        }
        float denom = sqr(dot(wi, wm) + dot(wo, wm) / eta_rel);
        s.f = f(wo, wi, mode);
        s.pdf = distribution.pdf(wo, wm) * std::abs(dot(wi, wm)) / denom * (1.0f - p_reflect);
        return result;
    }
};

}  // namespace candela
