#pragma once
// The radial scattering profile of a homogeneous, semi-infinite medium below a smooth dielectric
// boundary, by photon beam diffusion (Habel, Christensen and Jarosz 2013, "Photon Beam
// Diffusion: A Hybrid Monte Carlo Method for Subsurface Scattering"), tabulated over albedo and
// optical radius as pbrt-v4 tabulates it (ComputeBeamDiffusionBSSRDF), so that a subsurface
// material renders as pbrt-v4's does. tabulated_bssrdf.h evaluates and samples the table.
//
// Units: the table is for a medium of unit extinction (sigma_t = 1), so radii are optical
// radii r sigma_t; a medium of extinction sigma_t scales a radius by 1 / sigma_t and the
// profile per unit area by sigma_t^2. eta is the medium's index relative to the outside (1.33
// for skin in air, candela's and pbrt-v4's convention alike); g its Henyey-Greenstein asymmetry.
#include <vector>

#include "candela/math/color.h"

namespace candela {

// The multiple-scattering part of the profile at radius r: radiant exitance at distance r from
// where a unit flux enters, from the classical dipole integrated along the refracted beam (the
// beam's exponential attenuation, sampled at 100 stratified depths, pbrt-v4's rule), with
// Grosjean's diffusion coefficient and the Fresnel-moment boundary condition.
float beam_diffusion_ms(float sigma_s, float sigma_a, float g, float eta, float r);
// The single-scattering part: light scattered once along the beam below the critical angle's
// depth, leaving through the boundary (100 stratified depths as above).
float beam_diffusion_ss(float sigma_s, float sigma_a, float g, float eta, float r);

// The profile on a grid of albedos rho = sigma_s / sigma_t (rho_samples) and optical radii
// (radius_samples), for a unit-extinction medium. profile holds 2 pi r (S_ss + S_ms)(r) per
// (albedo, radius), row-major with albedo outer: the radial density up to normalisation, which
// is what sampling a radius needs. rho_eff is its integral over the plane for each albedo (the
// fraction of entering light that leaves: the effective albedo) and profile_cdf its running
// integral over radius (both of the Catmull-Rom spline through the profile).
struct BssrdfTable {
    std::vector<float> rho_samples, radius_samples, profile, rho_eff, profile_cdf;

    float eval_profile(int rho_index, int radius_index) const {
        return profile[static_cast<size_t>(rho_index) * radius_samples.size() +
                       static_cast<size_t>(radius_index)];
    }
};

// The table of pbrt-v4's subsurface material: 100 albedos, denser towards 1 as
// (1 - exp(-8 i / 99)) / (1 - exp(-8)), and 64 radii, 0 then 2.5e-3 growing by 1.2 per step (to
// about 235 mean free paths).
BssrdfTable make_beam_diffusion_table(float g, float eta);

// The scattering and absorption coefficients of the medium whose effective albedo is rho_eff and
// mean free path mfp (1 / sigma_t), per channel: the albedo rho whose table rho_eff matches,
// then sigma_s = rho / mfp and sigma_a = (1 - rho) / mfp (pbrt-v4 SubsurfaceFromDiffuse: how its
// subsurface material takes a `reflectance` and `mfp`). rho_eff beyond the table's range clamps
// to its ends (rho 0 or 1).
void subsurface_from_diffuse(const BssrdfTable& table, const Color& rho_eff, const Color& mfp,
                             Color& sigma_a, Color& sigma_s);

}  // namespace candela
