#pragma once
// A metal: Torrance-Sparrow microfacet reflection f = D(wm) G(wo, wi) F(wo.wm) / (4 cos_o cos_i)
// over a Trowbridge-Reitz distribution (Walter et al. 2007, eq. 20), F the complex Fresnel
// reflectance of index eta + i k per colour channel, sampled by the visible normals, whose
// density for wi is D_wo(wm) / (4 |wo.wm|) (the reflection Jacobian, Walter eq. 14). When the
// distribution is effectively smooth it is the perfect mirror with weight F(cos wo) (delta), as
// pbrt-v4's ConductorBxDF. It reflects on whichever side wo lies (a two-sided surface, as
// LambertianLobe), so wo and wi below the surface mirror the configuration above it.
//
// Single scattering loses the light that microfacets send to other microfacets, so a rough
// conductor is darker than its Fresnel colour; with_multiscatter() adds Kulla & Conty's lobe that
// returns it (microfacet_multiscatter.h).
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"
#include "candela/materials/microfacet_multiscatter.h"
#include "candela/materials/trowbridge_reitz.h"
#include "candela/sampling/warps.h"

namespace candela {

struct ConductorLobe {
    TrowbridgeReitz distribution;
    Color eta{1.0f};  // real part of the metal's index relative to the outside medium
    Color k{0.0f};    // imaginary part (absorption)
    bool multiscatter = false;  // add the multiple-scattering compensation lobe
    Color fresnel_avg{0.0f};    // 2 integral F(mu) mu dmu per channel, when multiscatter

    // This lobe with the compensation lobe added (none when smooth: a mirror loses nothing).
    CANDELA_HD ConductorLobe with_multiscatter() const {
        ConductorLobe lobe = *this;
        lobe.multiscatter = !distribution.effectively_smooth();
        lobe.fresnel_avg =
            hemispherical_average<Color>([&](float mu) { return fresnel_complex(mu, eta, k); });
        return lobe;
    }

    // f and pdf of one pair of directions, computed together: sample() returns exactly what
    // eval() and pdf() give for its wi, and both share the half vector and D.
    struct Evaluation {
        Color f{0.0f};
        float pdf = 0.0f;
    };
    CANDELA_HD Evaluation evaluate(const Vec3f& wo, const Vec3f& wi) const {
        Evaluation e = evaluate_single(wo, wi);
        if (!multiscatter || !same_hemisphere(wo, wi)) return e;
        ConductorMultiscatter ms(multiscatter_alpha(distribution), fresnel_avg);
        float cos_o = abs_cos_theta(wo), cos_i = abs_cos_theta(wi);
        float p = ms.probability(cos_o);
        e.f += ms.f(cos_o, cos_i);
        e.pdf = (1.0f - p) * e.pdf + p * cos_i * kInvPi;
        return e;
    }
    // The single-scattering (Torrance-Sparrow) part alone.
    CANDELA_HD Evaluation evaluate_single(const Vec3f& wo, const Vec3f& wi) const {
        Evaluation e;
        if (distribution.effectively_smooth() || !same_hemisphere(wo, wi)) return e;
        Vec3f wm = wo + wi;
        float len2 = length_squared(wm);
        if (!(len2 > 0.0f)) return e;
        wm = wm * (1.0f / std::sqrt(len2));
        if (wm.z < 0.0f) wm = -wm;
        float cos_o = abs_cos_theta(wo), cos_i = abs_cos_theta(wi);
        float wo_dot_wm = abs_dot(wo, wm);
        float d = distribution.d(wm);
        float g = distribution.g(wo, wi);
        e.f = fresnel_complex(wo_dot_wm, eta, k) * (d * g / (4.0f * cos_o * cos_i));
        e.pdf = distribution.d_visible(wo, wm) / (4.0f * wo_dot_wm);
        return e;
    }

    // D G F / (4 cos_o cos_i) (+ f_ms) with wo, wi on one side; 0 otherwise and when smooth (delta).
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
        return evaluate(wo, wi).f;
    }
    // D_wo(wm) / (4 |wo.wm|) on wo's side (mixed with the cosine's |cos wi| / pi in proportions
    // 1 - p : p with multiscatter); 0 otherwise and when smooth.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const { return evaluate(wo, wi).pdf; }
    // The mirror direction of a visible normal drawn from u (uc unused); nullopt for wo in the
    // plane or a reflection through the surface (the visible normal tilted past wo's horizon).
    // With multiscatter, u.x first picks the compensation lobe with its probability p (then a
    // cosine-distributed wi from (u.x / p, u.y)) and is stretched back over [0, 1) otherwise.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float, const Vec2f& u,
                                                TransportMode) const {
        std::optional<BsdfSample> result;
        if (wo.z == 0.0f) return result;
        if (distribution.effectively_smooth()) {
            BsdfSample& s = result.emplace();
            s.wi = {-wo.x, -wo.y, wo.z};
            s.f = fresnel_complex(abs_cos_theta(wo), eta, k) / abs_cos_theta(s.wi);
            s.pdf = 1.0f;
            s.is_delta = true;
            return result;
        }
        Vec2f v = u;
        if (multiscatter) {
            ConductorMultiscatter ms(multiscatter_alpha(distribution), fresnel_avg);
            float p = ms.probability(abs_cos_theta(wo));
            if (u.x < p) {
                Vec3f wi = sample_cosine_hemisphere(Vec2f(u.x / p, u.y));
                if (wo.z < 0.0f) wi.z = -wi.z;
                return sample_at(wo, wi);
            }
            v.x = (u.x - p) / (1.0f - p);
        }
        return sample_at(wo, reflect(wo, distribution.sample_wm(wo, v)));
    }
    // The sample for wi (f and pdf of both lobes); nullopt where the pdf is 0.
    CANDELA_HD std::optional<BsdfSample> sample_at(const Vec3f& wo, const Vec3f& wi) const {
        std::optional<BsdfSample> result;
        Evaluation e = evaluate(wo, wi);
        if (!(e.pdf > 0.0f)) return result;
        BsdfSample& s = result.emplace();
        s.f = e.f;
        s.wi = wi;
        s.pdf = e.pdf;
        return result;
    }
    static constexpr bool kUsesChoice = false;
    CANDELA_HD bool is_delta() const { return distribution.effectively_smooth(); }
    // The reflectance at normal incidence: the metal's colour.
    CANDELA_HD Color albedo() const { return fresnel_complex(1.0f, eta, k); }
};
static_assert(BsdfLobeType<ConductorLobe>);

}  // namespace candela
