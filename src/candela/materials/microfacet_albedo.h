#pragma once
// The directional albedo E(mu) = integral of f |cos wi| d wi of single-scattering GGX microfacet
// lobes, tabulated for Kulla & Conty's energy compensation (microfacet_multiscatter.h):
//   - a conductor of Fresnel F = 1 (ConductorLobe, white): E(mu, alpha);
//   - a dielectric (DielectricLobe, reflection + refraction, importance transport, i.e. the
//     fraction of the light's power that leaves): E(mu, alpha, eta) with eta the index ratio
//     crossed, > 1 from the rarer medium ("entering") and < 1 from the denser ("leaving", total
//     internal reflection included), both tabulated by eta' = max(eta, 1 / eta);
// and each curve's average E_avg = 2 integral_0^1 E(mu) mu dmu (Kulla & Conty 2017, "Revisiting
// Physically Based Shading at Imageworks", the tables of their section on multiple scattering).
//
// Nodes: mu_j = (j / (n - 1))^2 (E changes fastest at grazing incidence, over a width about
// alpha); alpha_i = (i / (n - 1))^2 (E changes fastest at small alpha); for dielectrics
// z_k = k / (n - 1) z_max with z = (eta' - 1) / (eta' + 1), for eta' in [1, 3] (the square root
// of the normal reflectance). Lookups interpolate linearly in mu, sqrt(alpha) and z, and clamp
// outside (alpha > 1 and eta' > 3 take the last node). E_avg is the exact average of the curve
// interpolated in mu, so that the compensation lobe adds exactly 1 - E(mu) of the table.
// tools/microfacet_albedo/ computes the tables (numerical integration over the visible normals;
// its output is microfacet_albedo_tables.cpp) and measures their interpolation error.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"

namespace candela {

inline constexpr int kAlbedoMuCount = 32;
inline constexpr int kAlbedoAlphaCount = 32;
inline constexpr int kAlbedoEtaCount = 16;
inline constexpr float kAlbedoEtaMax = 3.0f;
inline constexpr float kAlbedoZMax = (kAlbedoEtaMax - 1.0f) / (kAlbedoEtaMax + 1.0f);

// [alpha node][mu node] and [alpha node].
extern const float kConductorAlbedo[kAlbedoAlphaCount][kAlbedoMuCount];
extern const float kConductorAlbedoAvg[kAlbedoAlphaCount];
// [0: entering, 1: leaving][eta node][alpha node][mu node] and [..][eta node][alpha node].
extern const float kDielectricAlbedo[2][kAlbedoEtaCount][kAlbedoAlphaCount][kAlbedoMuCount];
extern const float kDielectricAlbedoAvg[2][kAlbedoEtaCount][kAlbedoAlphaCount];

CANDELA_HD inline float albedo_mu_node(int j) { return sqr(float(j) / float(kAlbedoMuCount - 1)); }
CANDELA_HD inline float albedo_alpha_node(int i) { return sqr(float(i) / float(kAlbedoAlphaCount - 1)); }
// eta' of node k: z = (eta' - 1) / (eta' + 1) solved for eta'.
CANDELA_HD inline float albedo_eta_node(int k) {
    float z = float(k) / float(kAlbedoEtaCount - 1) * kAlbedoZMax;
    return (1.0f + z) / (1.0f - z);
}

// A position between two nodes of an axis: node i0 and i0 + 1 with weight t on the latter.
struct AxisPosition {
    int i0 = 0;
    float t = 0.0f;
};
// The position of x, in node units (node i at x = i), clamped to the count nodes.
CANDELA_HD inline AxisPosition axis_position(float x, int count) {
    x = clamp(x, 0.0f, float(count - 1));
    int i0 = int(x) < count - 2 ? int(x) : count - 2;
    return {i0, x - float(i0)};
}

// The mu axis position of mu in [0, 1]: the node below it (found through sqrt(mu), the nodes'
// spacing), and the weight of the node above for interpolation linear in mu.
CANDELA_HD inline AxisPosition albedo_mu_position(float mu) {
    AxisPosition p = axis_position(std::sqrt(mu) * float(kAlbedoMuCount - 1), kAlbedoMuCount);
    float a = albedo_mu_node(p.i0), b = albedo_mu_node(p.i0 + 1);
    p.t = clamp((mu - a) / (b - a), 0.0f, 1.0f);
    return p;
}

// 2 integral_0^1 E(mu) mu dmu for E linear between the values e[j] at albedo_mu_node(j): on
// [a, b] of width h, 2 integral mu (e_a (b - mu) + e_b (mu - a)) / h = h (e_a (2a + b) + e_b (a + 2b)) / 3.
CANDELA_HD inline float albedo_average(const float* e) {
    float sum = 0.0f;
    for (int j = 0; j + 1 < kAlbedoMuCount; ++j) {
        float a = albedo_mu_node(j), b = albedo_mu_node(j + 1);
        sum += (b - a) * (e[j] * (2.0f * a + b) + e[j + 1] * (a + 2.0f * b)) / 3.0f;
    }
    return sum;
}

// One albedo curve E(mu) at a roughness (and index) between nodes: the weighted sum of up to four
// table rows, and its average.
struct AlbedoCurve {
    const float* rows[4] = {};
    float weights[4] = {};
    int count = 0;
    float average = 1.0f;

    // E(|mu|), linear in mu between the mu nodes (as albedo_average integrates it).
    CANDELA_HD float operator()(float mu) const {
        AxisPosition p = albedo_mu_position(std::abs(mu));
        float e = 0.0f;
        for (int r = 0; r < count; ++r)
            e += weights[r] * (rows[r][p.i0] + p.t * (rows[r][p.i0 + 1] - rows[r][p.i0]));
        return e;
    }
};

// The isotropic alpha the tables stand for when a distribution is anisotropic: the geometric
// mean (as Cycles does), exact for isotropic ones.
CANDELA_HD inline float albedo_alpha(float alpha_x, float alpha_y) { return std::sqrt(alpha_x * alpha_y); }

// E of the white conductor at roughness alpha.
CANDELA_HD inline AlbedoCurve conductor_albedo(float alpha) {
    AxisPosition a = axis_position(std::sqrt(alpha) * float(kAlbedoAlphaCount - 1), kAlbedoAlphaCount);
    AlbedoCurve c;
    c.count = 2;
    c.rows[0] = kConductorAlbedo[a.i0];
    c.rows[1] = kConductorAlbedo[a.i0 + 1];
    c.weights[0] = 1.0f - a.t;
    c.weights[1] = a.t;
    c.average = c.weights[0] * kConductorAlbedoAvg[a.i0] + c.weights[1] * kConductorAlbedoAvg[a.i0 + 1];
    return c;
}

// The eta axis position of a dielectric of index ratio eta' >= 1.
CANDELA_HD inline AxisPosition albedo_eta_position(float eta_big) {
    float z = (eta_big - 1.0f) / (eta_big + 1.0f);
    return axis_position(z / kAlbedoZMax * float(kAlbedoEtaCount - 1), kAlbedoEtaCount);
}

// E of the dielectric at roughness alpha seen from the side whose crossing has index ratio eta
// (entering when eta > 1, leaving when eta < 1).
CANDELA_HD inline AlbedoCurve dielectric_albedo(float alpha, float eta) {
    const int side = eta >= 1.0f ? 0 : 1;
    AxisPosition a = axis_position(std::sqrt(alpha) * float(kAlbedoAlphaCount - 1), kAlbedoAlphaCount);
    AxisPosition z = albedo_eta_position(eta >= 1.0f ? eta : 1.0f / eta);
    AlbedoCurve c;
    c.count = 4;
    c.average = 0.0f;
    for (int r = 0; r < 4; ++r) {
        int k = z.i0 + (r >> 1), i = a.i0 + (r & 1);
        c.rows[r] = kDielectricAlbedo[side][k][i];
        c.weights[r] = ((r >> 1) ? z.t : 1.0f - z.t) * ((r & 1) ? a.t : 1.0f - a.t);
        c.average += c.weights[r] * kDielectricAlbedoAvg[side][k][i];
    }
    return c;
}

}  // namespace candela
