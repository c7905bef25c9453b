#include "candela/materials/bssrdf_table.h"

#include <cmath>
#include <span>


#include "candela/materials/fresnel.h"
#include "candela/math/catmull_rom.h"
#include "candela/math/constants.h"
#include "candela/sampling/henyey_greenstein.h"

namespace candela {
namespace {

// Depths along the beam: the midpoints of 100 equal-probability strata of the exponential
// distribution of rate sigma (pbrt-v4's SampleExponential((i + 0.5) / 100)).
constexpr int kBeamSamples = 100;
float stratified_exponential(int i, float sigma) {
    float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(kBeamSamples);
    return -std::log(1.0f - u) / sigma;
}

}  // namespace

float beam_diffusion_ms(float sigma_s, float sigma_a, float g, float eta, float r) {
    // Similarity theory: the reduced coefficients of an isotropic medium that diffuses alike.
    const float sigmap_s = sigma_s * (1.0f - g);
    const float sigmap_t = sigma_a + sigmap_s;
    const float rhop = sigmap_s / sigmap_t;
    // Grosjean's non-classical diffusion coefficient, exact for single scattering's first term,
    // and the effective transport coefficient it gives.
    const float d_g = (2.0f * sigma_a + sigmap_s) / (3.0f * sigmap_t * sigmap_t);
    const float sigma_tr = safe_sqrt(sigma_a / d_g);
    // The boundary condition: the fluence extrapolates linearly to zero at height -ze above the
    // surface, where ze accounts for the boundary's internal Fresnel reflection.
    const float fm1 = fresnel_moment1(eta), fm2 = fresnel_moment2(eta);
    const float ze = -2.0f * d_g * (1.0f + 3.0f * fm2) / (1.0f - 2.0f * fm1);
    // Exitance is a mix of fluence and vector irradiance (Kienle and Patterson's weights).
    const float c_phi = 0.25f * (1.0f - 2.0f * fm1), c_e = 0.5f * (1.0f - 3.0f * fm2);

    float ed = 0.0f;
    for (int i = 0; i < kBeamSamples; ++i) {
        // A real point source at depth zr on the beam and its mirror image above the
        // extrapolated boundary.
        const float zr = stratified_exponential(i, sigmap_t);
        const float zv = -zr + 2.0f * ze;
        const float dr = std::sqrt(r * r + zr * zr), dv = std::sqrt(r * r + zv * zv);
        const float er = std::exp(-sigma_tr * dr), ev = std::exp(-sigma_tr * dv);
        // The dipole's fluence and the normal component of its vector irradiance at the surface.
        const float phi_d = kInv4Pi / d_g * (er / dr - ev / dv);
        const float ed_n = kInv4Pi * (zr * (1.0f + sigma_tr * dr) * er / (dr * dr * dr) -
                                      zv * (1.0f + sigma_tr * dv) * ev / (dv * dv * dv));
        const float e = phi_d * c_phi + ed_n * c_e;
        // Habel et al.'s correction that removes the single-scattering part the diffusion
        // overestimates near the source.
        const float kappa = 1.0f - std::exp(-2.0f * sigmap_t * (dr + zr));
        ed += kappa * rhop * rhop * e;
    }
    return ed / static_cast<float>(kBeamSamples);
}

float beam_diffusion_ss(float sigma_s, float sigma_a, float g, float eta, float r) {
    const float sigma_t = sigma_a + sigma_s, rho = sigma_s / sigma_t;
    // Below depth t_crit the path to the exit point r away is beyond the critical angle: no
    // light leaves from shallower scattering.
    const float t_crit = r * safe_sqrt(eta * eta - 1.0f);
    float ess = 0.0f;
    for (int i = 0; i < kBeamSamples; ++i) {
        const float ti = t_crit + stratified_exponential(i, sigma_t);
        const float d = std::sqrt(r * r + ti * ti);
        const float cos_theta_o = ti / d;
        // Attenuation along the beam (to depth ti, whose part t_crit the exponential samples
        // leave out) and to the exit, the phase function turning the beam towards the exit, and
        // the boundary's transmittance from inside.
        ess += rho * std::exp(-sigma_t * (d + t_crit)) / (d * d) * henyey_greenstein(cos_theta_o, g) *
               (1.0f - fresnel_dielectric(-cos_theta_o, eta)) * std::abs(cos_theta_o);
    }
    return ess / static_cast<float>(kBeamSamples);
}

BssrdfTable make_beam_diffusion_table(float g, float eta) {
    constexpr int kRhoSamples = 100, kRadiusSamples = 64;
    BssrdfTable t;
    t.rho_samples.resize(kRhoSamples);
    t.radius_samples.resize(kRadiusSamples);
    t.profile.resize(kRhoSamples * kRadiusSamples);
    t.rho_eff.resize(kRhoSamples);
    t.profile_cdf.resize(kRhoSamples * kRadiusSamples);

    t.radius_samples[0] = 0.0f;
    t.radius_samples[1] = 2.5e-3f;
    for (int i = 2; i < kRadiusSamples; ++i) t.radius_samples[i] = t.radius_samples[i - 1] * 1.2f;
    for (int i = 0; i < kRhoSamples; ++i)
        t.rho_samples[i] = (1.0f - std::exp(-8.0f * static_cast<float>(i) / (kRhoSamples - 1))) /
                           (1.0f - std::exp(-8.0f));

    // 6,400 entries of 200 exponentials each: about 60 ms on one core, once per distinct (g, eta)
    // at load. Serial: materials/ is value code without TBB (DESIGN.md).
    for (int i = 0; i < kRhoSamples; ++i) {
        const float rho = t.rho_samples[i];
        const size_t row = static_cast<size_t>(i) * kRadiusSamples;
        for (int j = 0; j < kRadiusSamples; ++j) {
            const float r = t.radius_samples[j];
            t.profile[row + j] = 2.0f * kPi * r *
                                 (beam_diffusion_ss(rho, 1.0f - rho, g, eta, r) +
                                  beam_diffusion_ms(rho, 1.0f - rho, g, eta, r));
        }
        t.rho_eff[i] = integrate_catmull_rom(t.radius_samples,
                                             std::span<const float>(&t.profile[row], kRadiusSamples),
                                             std::span<float>(&t.profile_cdf[row], kRadiusSamples));
    }
    return t;
}

void subsurface_from_diffuse(const BssrdfTable& table, const Color& rho_eff, const Color& mfp,
                             Color& sigma_a, Color& sigma_s) {
    for (int c = 0; c < kColorChannels; ++c) {
        const float rho = invert_catmull_rom(table.rho_samples, table.rho_eff, rho_eff[c]);
        sigma_s.set(c, rho / mfp[c]);
        sigma_a.set(c, (1.0f - rho) / mfp[c]);
    }
}

}  // namespace candela
