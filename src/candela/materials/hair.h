#pragma once
// Hair: the fibre scattering model of Chiang, Bitterli, Tappan and Burley, "A Practical and
// Controllable Hair and Fur Model for Production Path Tracing" (EGSR 2016), with pbrt-v4's
// semantics (HairBxDF). A fibre is a rough dielectric cylinder of index eta whose interior absorbs
// sigma_a per unit of the fibre's radius. Light leaves after p internal paths (p = 0 reflected at
// the surface, 1 transmitted through, 2 reflected once inside, 3 all the rest); each path p adds
// Mp(theta_i, theta_o) Ap(theta_o, h) Np(phi) to the scattering function S, with
//   Mp  the longitudinal lobe (d'Eon et al. 2011), of variance v_p from beta_m,
//   Ap  the attenuation by Fresnel and absorption along the path,
//   Np  the azimuthal lobe: a logistic of scale s (from beta_n) around the path's exit azimuth,
// and the cuticle's scales tilt the lobes of p = 0, 1, 2 by -2 alpha, alpha, 4 alpha.
//
// Frame: x is the fibre's tangent (the surface's dpdu, Material::anisotropic sets that up), z
// the shading normal, y = z x x. sin theta = w.x, phi = atan2(w.z, w.y). h in [-1, 1] is the
// offset across the fibre where the ray met it (pbrt-v4: -1 + 2 v). eval() is S / |cos wi|, so
// that the integrators' cosine to the shading normal gives back S (pbrt-v4's convention), and S
// integrates over the sphere to sum_p Ap: 1 without absorption.
//
// Not reciprocal in general: Ap, the azimuthal shifts and the tilts depend on wo alone (Chiang et
// al. section 4). S(wo, wi) = S(wi, wo) holds for h = 0, alpha = 0 and |theta_i| = |theta_o|
// (hair_test.cpp); Mp alone is symmetric always.
#include <array>
#include <cmath>
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"
#include "candela/math/constants.h"

namespace candela {

// The number of explicit paths; p = kHairPMax is the residual of all longer ones.
inline constexpr int kHairPMax = 3;

// The modified Bessel function of the first kind I0(x) by its series sum_i (x^2/4)^i / (i!)^2,
// summed until the terms stop counting (at most 40; x <= 12 needs fewer, and above 12
// hair_log_i0 uses the asymptote). pbrt-v4 sums 10 terms, 2% short at x = 12, so its Mp lost up to
// that much of its integral for narrow lobes (v < 0.1); here Mp integrates to 1.
CANDELA_HD inline float hair_i0(float x) {
    float sum = 1.0f, term = 1.0f;
    const float q = 0.25f * x * x;
    for (int i = 1; i < 40; ++i) {
        term *= q / float(i * i);
        sum += term;
        if (term < 1e-8f * sum) break;
    }
    return sum;
}

// log I0(x); above 12 by the asymptotic expansion
// I0(x) ~ e^x / sqrt(2 pi x) (1 + 1/(8x) + 9/(128 x^2) + 225/(3072 x^3)) (Abramowitz and Stegun
// 9.7.1), whose next term is below 1e-5 there. (pbrt-v4 keeps 1/(16x) of it: 0.5% low at 12.)
CANDELA_HD inline float hair_log_i0(float x) {
    if (x > 12.0f) {
        const float r = 1.0f / x;
        return x - 0.5f * std::log(2.0f * kPi * x) + std::log1p(r * (0.125f + r * (0.0703125f + r * 0.0732421875f)));
    }
    return std::log(hair_i0(x));
}

// The longitudinal lobe Mp of variance v (d'Eon et al. 2011, eq. 7):
//   csch(1/v) / (2 v) exp(-sin_i sin_o / v) I0(cos_i cos_o / v),
// in logarithms for v <= 0.1, where csch and I0 overflow (csch(1/v) ~ 2 exp(-1/v)).
CANDELA_HD inline float hair_mp(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
    const float a = cos_i * cos_o / v, b = sin_i * sin_o / v;
    if (v <= 0.1f)
        return std::exp(hair_log_i0(a) - b - 1.0f / v + 0.69314718f + std::log(1.0f / (2.0f * v)));
    return std::exp(-b) * hair_i0(a) / (std::sinh(1.0f / v) * 2.0f * v);
}

// The logistic density of scale s at x, and its distribution function.
CANDELA_HD inline float hair_logistic(float x, float s) {
    const float e = std::exp(-std::abs(x) / s);
    return e / (s * (1.0f + e) * (1.0f + e));
}
CANDELA_HD inline float hair_logistic_cdf(float x, float s) { return 1.0f / (1.0f + std::exp(-x / s)); }

// The logistic of scale s restricted to [-pi, pi] and renormalized there (Chiang et al. eq. 11).
CANDELA_HD inline float hair_trimmed_logistic(float x, float s) {
    return hair_logistic(x, s) / (hair_logistic_cdf(kPi, s) - hair_logistic_cdf(-kPi, s));
}
// Inverts the trimmed logistic's distribution function at u in [0, 1).
CANDELA_HD inline float sample_hair_trimmed_logistic(float u, float s) {
    const float lo = hair_logistic_cdf(-kPi, s), hi = hair_logistic_cdf(kPi, s);
    const float y = lo + u * (hi - lo);
    const float x = -s * std::log(1.0f / y - 1.0f);
    return clamp(x, -kPi, kPi);
}

// The azimuth at which path p leaves, relative to phi_o (Chiang et al. eq. 9).
CANDELA_HD inline float hair_phi(int p, float gamma_o, float gamma_t) {
    return 2.0f * float(p) * gamma_t - 2.0f * gamma_o + float(p) * kPi;
}

// The azimuthal lobe Np at relative azimuth phi: the trimmed logistic around hair_phi, the
// difference taken into [-pi, pi].
CANDELA_HD inline float hair_np(float phi, int p, float s, float gamma_o, float gamma_t) {
    float d = phi - hair_phi(p, gamma_o, gamma_t);
    d -= 2.0f * kPi * std::round(d * kInv2Pi);
    return hair_trimmed_logistic(d, s);
}

// pbrt-v4's SigmaAFromReflectance (Chiang et al. eq. 4): the absorption that makes a fibre of
// azimuthal roughness beta_n look of colour c after multiple scattering, per channel.
CANDELA_HD inline float hair_sigma_a_from_reflectance(float c, float beta_n) {
    const float b = beta_n, b2 = b * b, b3 = b2 * b, b4 = b3 * b, b5 = b4 * b;
    const float d = 5.969f - 0.215f * b + 2.532f * b2 - 10.73f * b3 + 5.574f * b4 + 0.245f * b5;
    const float r = std::log(c) / d;
    return r * r;
}

// The absorption of eumelanin and pheomelanin concentrations in linear sRGB (Chiang et al.
// section 4.2; the coefficients of pbrt-v4's SigmaAFromConcentration).
inline Rgb hair_sigma_a_from_concentration(float eumelanin, float pheomelanin) {
    return Rgb(0.419f * eumelanin + 0.187f * pheomelanin, 0.697f * eumelanin + 0.4f * pheomelanin,
               1.37f * eumelanin + 1.05f * pheomelanin);
}

struct HairLobe {
    float h = 0.0f;        // offset across the fibre, in [-1, 1]
    float gamma_o = 0.0f;  // asin(h)
    float eta = 1.55f;     // the fibre's index of refraction
    Color sigma_a{0.0f};   // absorption per unit radius, per channel
    float v0 = 0.0f;       // Mp's variance for p = 0; v1 = v0 / 4, v2 = v3 = 4 v0
    float s = 0.0f;        // Np's logistic scale
    // sin and cos of 2^k alpha for k = 0, 1, 2: the scales' tilts.
    std::array<float, kHairPMax> sin2k_alpha{}, cos2k_alpha{};

    // The lobe at offset h (clamped to [-1, 1]) for roughnesses beta_m, beta_n in (0, 1] and the
    // scales' angle alpha (radians): the variances are Chiang et al.'s fits (eqs. 7, 8).
    CANDELA_HD static HairLobe make(float h, float eta, const Color& sigma_a, float beta_m, float beta_n,
                                    float alpha) {
        HairLobe l;
        l.h = clamp(h, -1.0f, 1.0f);
        l.gamma_o = std::asin(l.h);
        l.eta = eta;
        l.sigma_a = sigma_a;
        const float m = 0.726f * beta_m + 0.812f * beta_m * beta_m + 3.7f * std::pow(beta_m, 20.0f);
        l.v0 = m * m;
        // sqrt(pi / 8) (0.265 b + 1.194 b^2 + 5.372 b^22).
        l.s = 0.626657069f * (0.265f * beta_n + 1.194f * beta_n * beta_n + 5.372f * std::pow(beta_n, 22.0f));
        l.sin2k_alpha[0] = std::sin(alpha);
        l.cos2k_alpha[0] = safe_sqrt(1.0f - l.sin2k_alpha[0] * l.sin2k_alpha[0]);
        for (int k = 1; k < kHairPMax; ++k) {
            l.sin2k_alpha[k] = 2.0f * l.cos2k_alpha[k - 1] * l.sin2k_alpha[k - 1];
            l.cos2k_alpha[k] = l.cos2k_alpha[k - 1] * l.cos2k_alpha[k - 1] - l.sin2k_alpha[k - 1] * l.sin2k_alpha[k - 1];
        }
        return l;
    }

    CANDELA_HD float variance(int p) const { return p == 0 ? v0 : p == 1 ? 0.25f * v0 : 4.0f * v0; }

    // What depends on wo alone: its angles, the refracted ray's gamma_t and the attenuations Ap.
    struct Outgoing {
        float sin_o = 0.0f, cos_o = 0.0f, phi_o = 0.0f, gamma_t = 0.0f;
        std::array<Color, kHairPMax + 1> ap{};
        std::array<float, kHairPMax + 1> ap_pdf{};  // Ap's channel averages, normalized
        bool valid = false;                          // some path carries light
    };
    CANDELA_HD Outgoing outgoing(const Vec3f& wo) const {
        Outgoing o;
        o.sin_o = wo.x;
        o.cos_o = safe_sqrt(1.0f - wo.x * wo.x);
        o.phi_o = std::atan2(wo.z, wo.y);
        // The refracted ray: its longitudinal angle by Snell's law, and its azimuth in the
        // cross-section through Bravais's modified index eta' (Chiang et al. eq. 10).
        const float sin_t = o.sin_o / eta;
        const float cos_t = safe_sqrt(1.0f - sin_t * sin_t);
        const float eta_p = safe_sqrt(eta * eta - o.sin_o * o.sin_o) / o.cos_o;
        const float sin_gamma_t = h / eta_p;
        const float cos_gamma_t = safe_sqrt(1.0f - sin_gamma_t * sin_gamma_t);
        o.gamma_t = std::asin(clamp(sin_gamma_t, -1.0f, 1.0f));
        // One crossing of the interior is 2 cos(gamma_t) / cos(theta_t) radii long.
        const Color t = exp_channels(sigma_a * (-2.0f * cos_gamma_t / cos_t));
        const float f = fresnel_dielectric(o.cos_o * safe_sqrt(1.0f - h * h), eta);
        o.ap[0] = Color(f);
        o.ap[1] = t * ((1.0f - f) * (1.0f - f));
        for (int p = 2; p < kHairPMax; ++p) o.ap[p] = o.ap[p - 1] * t * f;
        // The geometric series of all longer paths.
        o.ap[kHairPMax] = safe_div(o.ap[kHairPMax - 1] * t * f, Color(1.0f) - t * f);
        float sum = 0.0f;
        for (int p = 0; p <= kHairPMax; ++p) sum += channel_average(o.ap[p]);
        if (!(sum > 0.0f) || !std::isfinite(sum)) return o;
        for (int p = 0; p <= kHairPMax; ++p) o.ap_pdf[p] = channel_average(o.ap[p]) / sum;
        o.valid = true;
        return o;
    }

    // sin and |cos| of theta_o tilted by the scales for path p (p = 0: -2 alpha, 1: alpha,
    // 2: 4 alpha, 3: none); |cos| because a tilt past the pole folds back.
    CANDELA_HD void tilted(int p, float sin_o, float cos_o, float& sin_p, float& cos_p) const {
        if (p == 0) {
            sin_p = sin_o * cos2k_alpha[1] - cos_o * sin2k_alpha[1];
            cos_p = cos_o * cos2k_alpha[1] + sin_o * sin2k_alpha[1];
        } else if (p == 1) {
            sin_p = sin_o * cos2k_alpha[0] + cos_o * sin2k_alpha[0];
            cos_p = cos_o * cos2k_alpha[0] - sin_o * sin2k_alpha[0];
        } else if (p == 2) {
            sin_p = sin_o * cos2k_alpha[2] + cos_o * sin2k_alpha[2];
            cos_p = cos_o * cos2k_alpha[2] - sin_o * sin2k_alpha[2];
        } else {
            sin_p = sin_o;
            cos_p = cos_o;
        }
        cos_p = std::abs(cos_p);
    }

    // f and pdf for wi and the wo of `o`, computed together (sample() returns exactly these).
    struct Evaluation {
        Color f{0.0f};
        float pdf = 0.0f;
    };
    CANDELA_HD Evaluation evaluate(const Vec3f& wi, const Outgoing& o) const {
        Evaluation e;
        if (!o.valid) return e;
        const float sin_i = wi.x;
        const float cos_i = safe_sqrt(1.0f - sin_i * sin_i);
        const float phi = std::atan2(wi.z, wi.y) - o.phi_o;
        for (int p = 0; p < kHairPMax; ++p) {
            float sin_p, cos_p;
            tilted(p, o.sin_o, o.cos_o, sin_p, cos_p);
            const float mn = hair_mp(cos_i, cos_p, sin_i, sin_p, variance(p)) * hair_np(phi, p, s, gamma_o, o.gamma_t);
            e.f += o.ap[p] * mn;
            e.pdf += o.ap_pdf[p] * mn;
        }
        // The residual paths: untilted, and uniform in azimuth.
        const float m = hair_mp(cos_i, o.cos_o, sin_i, o.sin_o, variance(kHairPMax)) * kInv2Pi;
        e.f += o.ap[kHairPMax] * m;
        e.pdf += o.ap_pdf[kHairPMax] * m;
        const float c = abs_cos_theta(wi);
        if (c > 0.0f) e.f = e.f / c;
        return e;
    }

    // S(wo, wi) / |cos wi| over the whole sphere.
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
        return evaluate(wi, outgoing(wo)).f;
    }
    // sum_p Ap_pdf Mp Np (pbrt-v4's HairBxDF::PDF), per solid angle over the sphere.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const { return evaluate(wi, outgoing(wo)).pdf; }
    // uc picks the path p in proportion to Ap's channel averages and, stretched back over [0, 1),
    // then samples Np; u samples Mp (d'Eon et al.'s inversion, theta around the tilted -theta_o).
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u, TransportMode) const {
        std::optional<BsdfSample> result;
        const Outgoing o = outgoing(wo);
        if (!o.valid) return result;
        int p = 0;
        float below = 0.0f;
        while (p < kHairPMax && uc >= below + o.ap_pdf[p]) below += o.ap_pdf[p++];
        while (p > 0 && o.ap_pdf[p] == 0.0f) below -= o.ap_pdf[--p];  // rounding past the last path
        const float u_np = clamp((uc - below) / o.ap_pdf[p], 0.0f, kOneMinusEpsilon);

        float sin_p, cos_p;
        tilted(p, o.sin_o, o.cos_o, sin_p, cos_p);
        const float v = variance(p);
        // The cosine of the angle to the lobe's axis: 1 + v log(u + (1 - u) exp(-2 / v)) has the
        // density of Mp's von Mises-Fisher form (its logarithm's argument never below e^(-2/v)
        // but for rounding; a zero gives -infinity, clamped to -1).
        const float cos_theta = clamp(1.0f + v * std::log(u.x + (1.0f - u.x) * std::exp(-2.0f / v)), -1.0f, 1.0f);
        const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
        const float sin_i = clamp(-cos_theta * sin_p + sin_theta * std::cos(2.0f * kPi * u.y) * cos_p, -1.0f, 1.0f);
        const float cos_i = safe_sqrt(1.0f - sin_i * sin_i);
        const float dphi = p < kHairPMax ? hair_phi(p, gamma_o, o.gamma_t) + sample_hair_trimmed_logistic(u_np, s)
                                         : 2.0f * kPi * u_np;
        const float phi_i = o.phi_o + dphi;
        const Vec3f wi(sin_i, cos_i * std::cos(phi_i), cos_i * std::sin(phi_i));

        const Evaluation e = evaluate(wi, o);
        if (!(e.pdf > 0.0f)) return result;
        BsdfSample& bs = result.emplace();
        bs.f = e.f;
        bs.wi = wi;
        bs.pdf = e.pdf;
        bs.is_transmission = wi.z * wo.z < 0.0f;
        return result;
    }
    static constexpr bool kUsesChoice = true;
    CANDELA_HD bool is_delta() const { return false; }
    // The fraction of light the fibre scatters at its centre line, seen head-on: sum_p Ap for
    // h = 0 and theta_o = 0 (Mp and Np integrate to 1).
    CANDELA_HD Color albedo() const {
        HairLobe centre = *this;
        centre.h = 0.0f;
        centre.gamma_o = 0.0f;
        const Outgoing o = centre.outgoing(Vec3f(0.0f, 0.0f, 1.0f));
        Color sum(0.0f);
        for (const Color& a : o.ap) sum += a;
        return sum;
    }
};
static_assert(BsdfLobeType<HairLobe>);

}  // namespace candela
