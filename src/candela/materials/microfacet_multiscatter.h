#pragma once
// Energy compensation for rough microfacet lobes (Kulla & Conty 2017, "Revisiting Physically
// Based Shading at Imageworks", section "Multiple scattering"): single-scattering microfacet
// lobes lose the light that bounces between microfacets, 1 - E(mu_o) of it (E the directional
// albedo, microfacet_albedo.h). An added diffuse-like lobe returns it:
//   f_ms(wo, wi) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
// whose albedo is exactly 1 - E(mu_o) because E_avg = 2 integral E mu dmu, and which is
// reciprocal. ConductorLobe and DielectricLobe add it when their `multiscatter` flag is set:
//   - conductor: f_ms times F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = 2 integral F mu dmu
//     per channel (the paper's Fresnel term: light that leaves after k >= 2 bounces was
//     reflected k times, F_avg^k (1 - E_avg)^(k-1) E_avg of it, summed and divided by f_ms's
//     average albedo 1 - E_avg). A white conductor (F = 1) then reflects everything.
//   - dielectric: the lost light leaves by reflection or by transmission. With E_s the albedo
//     (reflection + transmission, importance transport) seen from side s, the lobes
//       f_R(wo, wi) = r_s (1 - E_s(mu_o)) (1 - E_s(mu_i))          (both on side s)
//       f_T(wo, wi) = t_s (1 - E_s(mu_o)) (1 - E_s'(mu_i))         (wi on the other side s')
//     add 1 - E_s(mu_o) when r_s pi (1 - E_avg,s) + t_s pi (1 - E_avg,s') = 1, and are reciprocal
//     when n_s^2 t_s = n_s'^2 t_s' (the BTDF's generalized reciprocity, n the absolute indices).
//     The fraction x = t pi (1 - E_avg,s') transmitted from the rarer side is 1 - F_avg (the
//     paper's split by the interface's average Fresnel), reduced where the denser side's
//     fraction would exceed 1. Radiance transport divides f_T by eta'^2 as the lobe does.
// Sampling: the compensation lobe is chosen with probability 1 - E(mu_o) (its share for F = 1)
// and sampled by the cosine on the side it sends light to; pdfs are the mixture of both
// lobes', so sample(), eval() and pdf() agree.
//
// Limits (docs/SCENE_FORMAT.md): the tables are isotropic, so an anisotropic distribution uses
// alpha = sqrt(alpha_x alpha_y) and is compensated approximately; alpha > 1 uses alpha = 1, and
// eta' > 3 uses 3.
#include "candela/materials/microfacet_albedo.h"
#include "candela/materials/trowbridge_reitz.h"
#include "candela/math/color.h"

namespace candela {

// 2 integral_0^1 f(mu) mu dmu (f's values of type T) by 8-point Gauss-Legendre quadrature on
// [0, 1]: nodes (1 +- x_i) / 2, weights w_i / 2 (within 1e-5 for the Fresnel reflectance of the
// metals of metal_table.h and of glass, whose curves are smooth).
template <class T, class F>
CANDELA_HD T hemispherical_average(F f) {
    constexpr float kNodes[4] = {0.1834346425f, 0.5255324099f, 0.7966664774f, 0.9602898565f};
    constexpr float kWeights[4] = {0.3626837834f, 0.3137066459f, 0.2223810345f, 0.1012285363f};
    T sum(0.0f);
    for (int i = 0; i < 4; ++i) {
        for (float sign : {-1.0f, 1.0f}) {
            float mu = 0.5f * (1.0f + sign * kNodes[i]);
            sum += f(mu) * (kWeights[i] * mu);  // 2 * w_i / 2 * mu
        }
    }
    return sum;
}

// The albedo curve a distribution is compensated with.
CANDELA_HD inline float multiscatter_alpha(const TrowbridgeReitz& d) {
    return albedo_alpha(d.alpha_x, d.alpha_y);
}

// The compensation of a rough conductor of hemispherical average Fresnel reflectance
// `fresnel_avg`, at roughness alpha.
struct ConductorMultiscatter {
    AlbedoCurve albedo;
    Color scale{0.0f};  // F_ms / (pi (1 - E_avg)); 0 when nothing is lost

    CANDELA_HD ConductorMultiscatter(float alpha, const Color& fresnel_avg) : albedo(conductor_albedo(alpha)) {
        float lost = 1.0f - albedo.average;
        if (!(lost > 1e-6f)) return;
        // F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), per channel.
        Color fresnel_ms = map_channels(fresnel_avg, [&](float f) {
            return f * f * albedo.average / (1.0f - f * lost);
        });
        scale = fresnel_ms * (kInvPi / lost);
    }
    // Probability of sampling the compensation lobe for wo at |cos| cos_o.
    CANDELA_HD float probability(float cos_o) const { return scale.is_black() ? 0.0f : 1.0f - albedo(cos_o); }
    // f_ms for wo and wi on one side.
    CANDELA_HD Color f(float cos_o, float cos_i) const {
        return scale * ((1.0f - albedo(cos_o)) * (1.0f - albedo(cos_i)));
    }
};

// The compensation of a rough dielectric of index eta (inside over outside) for wo on the outside
// (wo_outside) or the inside: the lobes of the header comment for wo's side s.
struct DielectricMultiscatter {
    AlbedoCurve albedo_same;   // E_s: seen from wo's side
    AlbedoCurve albedo_other;  // E_s': seen from the other side
    float reflect_scale = 0.0f;     // r_s
    float transmit_scale = 0.0f;    // t_s (importance transport)
    float transmit_fraction = 0.0f; // x_s = t_s pi (1 - E_avg,s')
    bool active = false;

    // fresnel_avg: the smooth interface's average reflectance from its rarer side.
    CANDELA_HD DielectricMultiscatter(float alpha, float eta, float fresnel_avg, bool wo_outside) {
        const float eta_big = eta >= 1.0f ? eta : 1.0f / eta;
        const bool wo_rare = wo_outside == (eta >= 1.0f);
        AlbedoCurve rare = dielectric_albedo(alpha, eta_big), dense = dielectric_albedo(alpha, 1.0f / eta_big);
        albedo_same = wo_rare ? rare : dense;
        albedo_other = wo_rare ? dense : rare;
        const float lost_rare = 1.0f - rare.average, lost_dense = 1.0f - dense.average;
        if (!(lost_rare > 1e-6f) && !(lost_dense > 1e-6f)) return;
        active = true;
        // pi t_rare: the split 1 - F_avg, capped so that the dense side transmits at most all of
        // its lost light (pi t_dense (1 - E_avg,rare) <= 1 with t_dense = t_rare / eta'^2).
        const float eta2 = eta_big * eta_big;
        float pi_t_rare = lost_dense > 1e-6f ? (1.0f - fresnel_avg) / lost_dense : eta2 / lost_rare;
        if (lost_rare > 1e-6f && pi_t_rare > eta2 / lost_rare) pi_t_rare = eta2 / lost_rare;
        const float pi_t_same = wo_rare ? pi_t_rare : pi_t_rare / eta2;
        const float lost_same = wo_rare ? lost_rare : lost_dense;
        const float lost_other = wo_rare ? lost_dense : lost_rare;
        transmit_fraction = clamp(pi_t_same * lost_other, 0.0f, 1.0f);
        transmit_scale = pi_t_same * kInvPi;
        reflect_scale = lost_same > 1e-6f ? (1.0f - transmit_fraction) / lost_same * kInvPi : 0.0f;
    }
    // Probability of sampling the compensation lobes for wo at |cos| cos_o.
    CANDELA_HD float probability(float cos_o) const { return active ? 1.0f - albedo_same(cos_o) : 0.0f; }
    // f_R or f_T (importance transport) for |cos| cos_o, cos_i, by the side of wi.
    CANDELA_HD float f(float cos_o, float cos_i, bool transmission) const {
        if (!active) return 0.0f;
        float lost_o = 1.0f - albedo_same(cos_o);
        return transmission ? transmit_scale * lost_o * (1.0f - albedo_other(cos_i))
                            : reflect_scale * lost_o * (1.0f - albedo_same(cos_i));
    }
    // The density of the compensation lobes' sampling at wi (per solid angle).
    CANDELA_HD float pdf(float cos_i, bool transmission) const {
        return (transmission ? transmit_fraction : 1.0f - transmit_fraction) * cos_i * kInvPi;
    }
};

}  // namespace candela
