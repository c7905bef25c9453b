#pragma once
// Glass, smooth or rough (pbrt-v4's DielectricBxDF). The front (wo.z > 0) is outside and eta is
// the index inside over the index outside.
//
// Rough: microfacet reflection and refraction over a Trowbridge-Reitz distribution (Walter et
// al. 2007, "Microfacet Models for Refraction through Rough Surfaces"). A pair (wo, wi) defines
// the generalized half vector wm = normalize(wo + eta' wi), eta' the index ratio crossed (1 for
// reflection; eq. 16), turned to the upper hemisphere; microfacets facing away from wo or wi
// contribute nothing. With F = F_dielectric(wo.wm):
//   reflection    f_r = D G F / (4 |cos_o cos_i|)                                     (eq. 20)
//   transmission  f_t = D G (1 - F) |wi.wm wo.wm| / (|cos_o cos_i| (wi.wm + wo.wm / eta')^2)
//                 (eq. 21 with the index ratio divided out), times 1 / eta'^2 for radiance.
// Sampling draws a visible normal from wo, then reflects with probability F and refracts
// otherwise, so pdf = D_wo(wm) |dwm/dwi| times that probability, |dwm/dwi| being 1 / (4 |wo.wm|)
// for reflection (eq. 14) and |wi.wm| / (wi.wm + wo.wm / eta')^2 for refraction (eq. 17).
//
// Smooth (effectively smooth alpha, or eta = 1): FresnelSpecularLobe with the exact Fresnel term.
//
// with_multiscatter() adds Kulla & Conty's compensation for the light lost between microfacets,
// by reflection and transmission (microfacet_multiscatter.h).
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"
#include "candela/materials/fresnel_specular.h"
#include "candela/materials/microfacet_multiscatter.h"
#include "candela/materials/trowbridge_reitz.h"
#include "candela/sampling/warps.h"

namespace candela {

struct DielectricLobe {
    Color tint{1.0f};  // multiplies reflected and refracted light alike
    float eta = 1.5f;
    TrowbridgeReitz distribution;
    bool multiscatter = false;  // add the multiple-scattering compensation lobes
    float fresnel_avg = 0.0f;   // the smooth interface's 2 integral F mu dmu from its rarer side

    CANDELA_HD bool is_smooth() const { return eta == 1.0f || distribution.effectively_smooth(); }

    // This lobe with the compensation lobes added (none when smooth: smooth glass loses nothing).
    CANDELA_HD DielectricLobe with_multiscatter() const {
        DielectricLobe lobe = *this;
        lobe.multiscatter = !is_smooth();
        const float eta_big = eta >= 1.0f ? eta : 1.0f / eta;
        lobe.fresnel_avg =
            hemispherical_average<float>([&](float mu) { return fresnel_dielectric(mu, eta_big); });
        return lobe;
    }
    CANDELA_HD DielectricMultiscatter multiscatter_lobes(bool wo_outside) const {
        return DielectricMultiscatter(multiscatter_alpha(distribution), eta, fresnel_avg, wo_outside);
    }

    // f and pdf of one pair of directions, computed together (as ConductorLobe::evaluate), and
    // the index ratio eta' crossed (1 for reflection).
    struct Evaluation {
        Color f{0.0f};
        float pdf = 0.0f;
        float eta_rel = 1.0f;
    };
    CANDELA_HD Evaluation evaluate(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
        Evaluation e = evaluate_single(wo, wi, mode);
        float cos_o = cos_theta(wo), cos_i = cos_theta(wi);
        if (!multiscatter || cos_o == 0.0f || cos_i == 0.0f) return e;
        DielectricMultiscatter ms = multiscatter_lobes(cos_o > 0.0f);
        bool transmission = cos_o * cos_i < 0.0f;
        float f = ms.f(std::abs(cos_o), std::abs(cos_i), transmission);
        if (transmission) {
            e.eta_rel = cos_o > 0.0f ? eta : 1.0f / eta;
            if (mode == TransportMode::kRadiance) f /= e.eta_rel * e.eta_rel;
        }
        float p = ms.probability(std::abs(cos_o));
        e.f += tint * f;
        e.pdf = (1.0f - p) * e.pdf + p * ms.pdf(std::abs(cos_i), transmission);
        return e;
    }
    // The single-scattering (Walter et al.) part alone.
    CANDELA_HD Evaluation evaluate_single(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
        Evaluation e;
        float cos_o = cos_theta(wo), cos_i = cos_theta(wi);
        if (is_smooth() || cos_o == 0.0f || cos_i == 0.0f) return e;
        bool reflection = cos_o * cos_i > 0.0f;
        if (!reflection) e.eta_rel = cos_o > 0.0f ? eta : 1.0f / eta;
        Vec3f wm = wo + wi * e.eta_rel;
        float len2 = length_squared(wm);
        if (!(len2 > 0.0f)) return e;
        wm = wm * (1.0f / std::sqrt(len2));
        if (wm.z < 0.0f) wm = -wm;
        float wo_dot_wm = dot(wo, wm), wi_dot_wm = dot(wi, wm);
        // Microfacets seen from behind by wo or wi (possible for a half vector of two arbitrary
        // directions) neither reflect nor refract between them.
        if (wo_dot_wm * cos_o <= 0.0f || wi_dot_wm * cos_i <= 0.0f) return e;
        // F is the same from either side. From the denser side near the critical angle, its
        // refracted cosine sqrt(1 - sin^2 eta'^2) cancels to a few bits: a refraction takes
        // the cosine on the rarer side (outside when eta > 1).
        bool wo_rarer = reflection || (cos_o > 0.0f) == (eta > 1.0f);
        float fresnel = fresnel_dielectric(wo_rarer ? wo_dot_wm : wi_dot_wm, eta);
        float d = distribution.d(wm);
        float g = distribution.g(wo, wi);
        float pdf_wm = distribution.pdf(wo, wm);
        if (reflection) {
            e.f = tint * (d * g * fresnel / (4.0f * std::abs(cos_o * cos_i)));
            e.pdf = pdf_wm / (4.0f * std::abs(wo_dot_wm)) * fresnel;
            return e;
        }
        float denom = sqr(wi_dot_wm + wo_dot_wm / e.eta_rel);
        float transmitted = 1.0f - fresnel;
        float f_t = d * g * transmitted * std::abs(wi_dot_wm * wo_dot_wm / (cos_o * cos_i * denom));
        if (mode == TransportMode::kRadiance) f_t /= e.eta_rel * e.eta_rel;
        e.f = tint * f_t;
        e.pdf = pdf_wm * std::abs(wi_dot_wm) / denom * transmitted;
        return e;
    }

    // f_r or f_t for the side wi is on; 0 when smooth (delta).
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
        return evaluate(wo, wi, mode).f;
    }
    // The density of sample() at wi, the reflect/refract choice included; 0 when smooth.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const {
        return evaluate(wo, wi, TransportMode::kImportance).pdf;
    }
    // A visible normal from u, then reflection when uc < F at that normal, refraction otherwise;
    // nullopt for wo in the plane or a direction that ends on the wrong side. With multiscatter,
    // uc first picks the compensation lobes with their probability p, then (stretched over
    // [0, 1)) transmission or reflection by their shares, and u a cosine-distributed wi on that
    // side; otherwise uc is stretched back over [0, 1) for the choice above.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                TransportMode mode) const {
        if (is_smooth()) return FresnelSpecularLobe{tint, eta, false}.sample(wo, uc, u, mode);
        if (wo.z == 0.0f) return std::nullopt;
        if (multiscatter) {
            DielectricMultiscatter ms = multiscatter_lobes(wo.z > 0.0f);
            float p = ms.probability(std::abs(wo.z));
            if (uc < p) {
                Vec3f wi = sample_cosine_hemisphere(u);
                bool transmission = uc / p < ms.transmit_fraction;
                if ((wo.z < 0.0f) != transmission) wi.z = -wi.z;
                return sample_at(wo, wi, mode);
            }
            uc = (uc - p) / (1.0f - p);
        }
        std::optional<BsdfSample> result;
        Vec3f wm = distribution.sample_wm(wo, u);
        Vec3f wi;
        if (uc < fresnel_dielectric(dot(wo, wm), eta)) {
            wi = reflect(wo, wm);
            if (!same_hemisphere(wo, wi)) return result;
        } else {
            // Total internal reflection makes F = 1, so uc < F above; refract fails only by
            // rounding at the critical angle.
            if (!refract(wo, wm, eta, &wi) || !(wi.z * wo.z < 0.0f)) return result;
        }
        return sample_at(wo, wi, mode);
    }
    // The sample for wi (f and pdf of all lobes); nullopt where the pdf is 0.
    CANDELA_HD std::optional<BsdfSample> sample_at(const Vec3f& wo, const Vec3f& wi,
                                                   TransportMode mode) const {
        std::optional<BsdfSample> result;
        Evaluation e = evaluate(wo, wi, mode);
        if (!(e.pdf > 0.0f)) return result;
        BsdfSample& s = result.emplace();
        s.f = e.f;
        s.wi = wi;
        s.pdf = e.pdf;
        s.is_transmission = wi.z * wo.z < 0.0f;
        s.eta = e.eta_rel;
        return result;
    }
    static constexpr bool kUsesChoice = true;
    CANDELA_HD bool is_delta() const { return is_smooth(); }
    CANDELA_HD Color albedo() const { return tint; }
};
static_assert(BsdfLobeType<DielectricLobe>);

}  // namespace candela
