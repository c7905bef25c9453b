#pragma once
// Coated surfaces: a dielectric coat (CoatInterface, smooth or rough) over a base lobe, with a
// slab of homogeneous medium of optical thickness `thickness` (sigma_t = 1 per unit length),
// single-scattering albedo `medium_albedo` and Henyey-Greenstein asymmetry `g` between them.
// pbrt-v4's LayeredBxDF<DielectricBxDF, Base, twoSided = true> (Pharr, Jakob & Humphreys, PBR 4th
// ed., 14.3), after Guo, Hasan & Zhao 2018 ("Position-Free Monte Carlo Simulation for Arbitrary
// Layered BSDFs"): there is no closed form, so
//   eval()   is an unbiased estimate of f by `n_samples` random walks between the layers (at most
//            `max_depth` scattering events each, Russian roulette after 3), joined to wi by next-
//            event estimation through the coat, combined by MIS (pbrt-v4's LayeredBxDF::f);
//   sample() follows one random walk from wo until it leaves through the coat: its f / pdf is
//            the walk's weight (pbrt-v4's LayeredBxDF::Sample_f);
//   pdf()    is pbrt-v4's approximation of the sampling density (the coat's reflection plus one
//            transmission-reflection-transmission path, mixed 9:1 with the uniform density
//            1 / (4 pi)), good enough to weight strategies by MIS; it is not the exact density of
//            sample(), which has none in closed form.
// The random numbers inside eval() and pdf() come from a generator seeded by a hash of the two
// directions (inside sample(), of wo and the caller's numbers), as pbrt-v4 does: each is then a
// deterministic function of its arguments, so the same pair always gives the same estimate and
// the MIS weights of a light sample and a BSDF sample of one direction add to 1.
//
// pbrt-v4's integrator weights a layered sample by f / pdf of the walk and uses PDF(wo, wi) for
// MIS (BSDFSample::pdfIsProportional). candela's integrators read both from the sample, so
// sample() returns pdf = pdf(wo, wi) and f = (walk f / walk pdf) pdf(wo, wi): the same weight and
// the same MIS density. A sample through the layers that met only specular events (smooth coat
// over a smooth conductor, clear medium) is a delta sample and keeps the walk's f and pdf.
//
// Two-sided: wo below the surface mirrors the configuration above (as the other lobes). The base
// reflects only, so nothing is transmitted and f = 0 between opposite hemispheres.
//
// Truncation: eval() and sample() count the paths with at most max_depth scattering events
// between the interfaces (pbrt-v4's f does; its Sample_f counts one event fewer, see below).
//
// Where this differs from pbrt-v4, on purpose, so that eval() and sample() estimate the same
// BSDF (a renderer adds light-sampled eval() and BSDF-sampled sample() by MIS):
//   - eval()'s MIS weights for a path leaving through a rough coat use the density of the
//     next-event strategy in the measure of the direction it draws (layered.cpp); pbrt-v4's
//     weights do not add to 1 there and its f exceeds what its own Sample_f gives by 3 to 11 %
//     for rough coats (layered_stat_test.cpp measures the agreement of ours).
//   - sample() walks max_depth + 1 events, the last being its exit through the coat, to count
//     eval()'s paths; pbrt-v4's Sample_f walks max_depth, missing the paths of exactly max_depth
//     events inside (none in a clear slab with even max_depth, pbrt-v4's default case).
//   - pdf() of a delta-only lobe is 0 (pbrt-v4 returns its uniform share 0.1 / (4 pi)), so that
//     mixtures with other lobes keep their densities; an index-matched coat (eta = 1) is
//     specular throughout (pbrt-v4 samples it as specular but weights it as glossy).
//   - a walk whose f and density both underflow float is dropped instead of returning inf.
#include <cstdint>
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/coat_interface.h"
#include "candela/materials/conductor.h"
#include "candela/materials/lambertian.h"

namespace candela {

template <class Base>
struct LayeredLobe {
    CoatInterface coat;            // the top interface: eta = coat index / outside index
    Base base;                     // the bottom: LambertianLobe or ConductorLobe (its eta and k
                                   // relative to the coat's index)
    Color medium_albedo{0.0f};     // of the medium between them; black: a clear, absorbing slab
    float thickness = 0.01f;       // in mean free paths; pbrt-v4's default
    float g = 0.0f;                // Henyey-Greenstein asymmetry of the medium, in [-1, 1]
    uint16_t max_depth = 10;       // scattering events per random walk
    uint16_t n_samples = 1;        // random walks per eval()
    // Reproduce pbrt-v4's LayeredBxDF where it differs from the above (pbrt-v4 scenes set it, so
    // that they render as pbrt-v4 renders them): eval()'s exit weights use pbrt-v4's reverse
    // density (all of the coat's lobes, in wi's measure), and sample() walks max_depth events.
    bool pbrt_v4_weights = false;

    // An estimate of f(wo, wi) without the cosine (see the top of the file).
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const;
    // pbrt-v4's approximate sampling density per solid angle, > 0 on the whole sphere; 0 for a
    // delta-only lobe.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const;
    // A direction from one random walk: reflection at the coat (chosen by uc and u, as the
    // coat's own sample) or a walk through the layers that leaves through the coat; nullopt when
    // the walk is absorbed, cut by roulette or runs past max_depth.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                TransportMode mode) const;
    static constexpr bool kUsesChoice = true;
    // Only specular events are possible: a smooth coat over a smooth base in a clear medium.
    CANDELA_HD bool is_delta() const {
        return coat.is_specular() && base.is_delta() && medium_albedo.is_black();
    }
    // The base's colour (its reflectance, or a conductor's colour at normal incidence).
    CANDELA_HD Color albedo() const { return base.albedo(); }

  private:
    CANDELA_HD float pdf_upper(const Vec3f& wo, const Vec3f& wi) const;
};

// A dielectric coat over a Lambertian base: pbrt-v4's CoatedDiffuseBxDF.
using CoatedDiffuseLobe = LayeredLobe<LambertianLobe>;
// A dielectric coat over a (rough) conductor: pbrt-v4's CoatedConductorBxDF.
using CoatedConductorLobe = LayeredLobe<ConductorLobe>;

// Whether a lobe's eval() and pdf() are estimates (the coated lobes): pdf() is then no density
// of sample(), and a Bsdf of several lobes cannot weight one lobe's sample by the others'
// densities (bsdf.cpp).
template <class T>
inline constexpr bool kIsLayeredLobe = false;
template <class Base>
inline constexpr bool kIsLayeredLobe<LayeredLobe<Base>> = true;

extern template struct LayeredLobe<LambertianLobe>;
extern template struct LayeredLobe<ConductorLobe>;

static_assert(BsdfLobeType<CoatedDiffuseLobe>);
static_assert(BsdfLobeType<CoatedConductorLobe>);

}  // namespace candela
