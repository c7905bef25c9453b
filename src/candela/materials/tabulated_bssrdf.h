#pragma once
// pbrt-v4's tabulated BSSRDF: the separable approximation
//   S(po, wo, pi, wi) = (1 - Fr(cos theta_o)) Sp(|pi - po|) Sw(wi)
// with the radial profile Sp of a semi-infinite homogeneous medium taken from a photon beam
// diffusion table (bssrdf_table.h), and the exit lobe Sw a normalized Fresnel transmittance
// (NormalizedFresnel below). The entry's Fresnel factor is the dielectric boundary's BSDF, which
// the material samples first; this file is what follows: a probe segment near the entry point to
// find exit points pi on the same material, their density, the profile's value, and the lobe at
// the exit. (Christensen and Burley 2015 use the same probe scheme; King et al. 2013 the three
// projection axes.)
//
// Colours: sigma_a and sigma_s are per channel (RGB (r, g, b, r), or four wavelengths), and
// radius sampling follows one channel, `hero`, as pbrt-v4 samples its first wavelength; pdf_sr
// and pdf_sp give every channel's density, so the caller may combine them.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/bssrdf_table.h"
#include "candela/materials/fresnel.h"
#include "candela/math/color.h"
#include "candela/math/frame.h"
#include "candela/math/vec.h"
#include "candela/sampling/warps.h"

namespace candela {

// The segment a probe ray traces from p0 to p1 to find exit points on the material's surface.
struct BssrdfProbeSegment {
    Vec3f p0, p1;
};

class TabulatedBssrdf {
  public:
    // po: the entry point; ns: the shading normal there (unit); eta: the medium's index relative
    // to the outside; table: the profile table for the material's g and eta, which must outlive
    // this object; hero: the channel (0..3) that sample_sr follows.
    TabulatedBssrdf(const Vec3f& po, const Vec3f& ns, float eta, const Color& sigma_a,
                    const Color& sigma_s, const BssrdfTable* table, int hero);

    // The radial profile per unit area at distance r from po, per channel (0 where the table
    // does not reach: beyond about 235 mean free paths, or for an albedo outside [0, 1]).
    Color sr(float r) const;
    // sr at the distance from po to pi.
    Color sp(const Vec3f& pi) const { return sr(length(pi - po_)); }

    // A radius drawn from the hero channel's profile, in proportion to 2 pi r Sr(r) (the radial
    // density); nullopt when that channel's extinction is 0.
    std::optional<float> sample_sr(float u) const;
    // The density per unit area of the plane of sample_sr's radii, per channel as if each
    // channel were sampled: Sr(r) / rho_eff, so that pdf_sr(r) 2 pi r is the radial density.
    Color pdf_sr(float r) const;

    // A probe segment: one of three axes (ns with probability 1/2, either tangent of
    // Frame::from_normal(ns) with 1/4), a radius from sample_sr(u2a) and an angle 2 pi u2b in
    // the plane normal to the axis, and a chord of the sphere of radius r_max = sample_sr(0.999)
    // through that disk point, parallel to the axis. nullopt when r >= r_max (or no radius).
    std::optional<BssrdfProbeSegment> sample_sp(float u1, float u2a, float u2b) const;
    // The density per unit area of the exit point pi (normal ni there) that sample_sp finds, per
    // channel: the mixture over the three axes of pdf_sr of the radius projected along each,
    // times the cosine between ni and that axis (probe rays cross the surface obliquely). Exit
    // points beyond r_max and additional intersections along the chord are the caller's affair
    // (pbrt-v4 picks one of the chord's hits uniformly and divides by their count).
    Color pdf_sp(const Vec3f& pi, const Vec3f& ni) const;

    float eta() const { return eta_; }

  private:
    Vec3f po_, ns_;
    float eta_;
    Color sigma_t_, rho_;
    const BssrdfTable* table_;
    int hero_;
};

// The exit lobe Sw of the tabulated BSSRDF (pbrt-v4's NormalizedFresnelBxDF): the boundary's
// Fresnel transmittance towards wi, normalized so that it integrates to 1 against the cosine:
//   Sw(wi) = (1 - Fr(cos theta_i, eta)) / (c pi),   c = 1 - 2 fresnel_moment1(1 / eta),
// where 2 fresnel_moment1(1 / eta) is the boundary's reflectance to a uniform flux from outside.
// A BSDF lobe in the local frame at the exit point (wo is the normal there, as pbrt-v4 sets it);
// it reflects into wo's hemisphere, cosine sampled. For camera paths (TransportMode::kRadiance)
// the value is multiplied by eta^2: radiance entering the denser medium was compressed by
// 1 / eta^2 by the boundary's BSDF, and leaving it expands again.
struct NormalizedFresnel {
    float eta = 1.33f;

    // Sw for an exit direction at cos_theta_i to the normal (positive: outside), times eta^2 for
    // camera paths.
    CANDELA_HD Color f(float cos_theta_i, TransportMode mode = TransportMode::kRadiance) const {
        const float c = 1.0f - 2.0f * fresnel_moment1(1.0f / eta);
        float value = (1.0f - fresnel_dielectric(cos_theta_i, eta)) / (c * kPi);
        if (mode == TransportMode::kRadiance) value *= eta * eta;
        return Color(value);
    }

    // The lobe interface (bsdf_lobe.h).
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
        return same_hemisphere(wo, wi) ? f(cos_theta(wi), mode) : Color(0.0f);
    }
    // |cos(theta_i)| / pi in wo's hemisphere, else 0.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const {
        return same_hemisphere(wo, wi) ? abs_cos_theta(wi) * kInvPi : 0.0f;
    }
    // A cosine-distributed wi on wo's side (uc unused).
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float, const Vec2f& u,
                                                TransportMode mode) const {
        std::optional<BsdfSample> result;
        Vec3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
        if (!same_hemisphere(wo, wi)) return result;  // wo in the plane, or wi on the rim
        BsdfSample& s = result.emplace();
        s.f = f(cos_theta(wi), mode);
        s.wi = wi;
        s.pdf = abs_cos_theta(wi) * kInvPi;
        return result;
    }
    static constexpr bool kUsesChoice = false;
    CANDELA_HD bool is_delta() const { return false; }
    CANDELA_HD Color albedo() const { return Color(1.0f); }
};
static_assert(BsdfLobeType<NormalizedFresnel>);

}  // namespace candela
