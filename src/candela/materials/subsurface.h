#pragma once
// pbrt-v4's `subsurface` material (SubsurfaceMaterial): a dielectric boundary of index `eta`
// (the material's one lobe: smooth, or rough by its roughness) over a scattering interior. The
// interior's coefficients are sigma_a and sigma_s (per unit length, times `scale`), or come from a
// diffuse `reflectance` and a mean free path `mfp` by inverting the effective albedo of the
// photon beam diffusion table (pbrt-v4's SubsurfaceFromDiffuse). Light crosses the interior by
// one of two methods:
// - kTabulated, pbrt-v4's: where a path refracts into the material, a probe segment finds an
//   exit point on the same material by the tabulated BSSRDF (tabulated_bssrdf.h), and the path
//   leaves there through the NormalizedFresnel lobe (integrators/volpath_integrator.cpp).
// - kRandomWalk (candela's JSON only, as Cycles and Arnold do): the interior is a homogeneous
//   medium of the same coefficients and g, which volpath walks by delta tracking and leaves
//   through the dielectric boundary; the scene loader makes that medium and gives it to the
//   shapes of the material as their interior (Subsurface::medium).
#include <cstdint>

#include "candela/materials/bssrdf_table.h"
#include "candela/textures/texture_set.h"

namespace candela {

enum class SubsurfaceMethod : uint8_t { kTabulated, kRandomWalk };

// The interior of one `subsurface` material; the scene keeps them (Scene::subsurfaces) and its
// material names one by index (Material::subsurface).
struct Subsurface {
    SubsurfaceMethod method = SubsurfaceMethod::kTabulated;
    // pbrt-v4's defaults (whole milk's coefficients, per mm) unless the file gives others.
    ColorParam sigma_a{Rgb(0.0011f, 0.0024f, 0.014f), kNoTexture, 0.0f, kUnbounded, SpectrumForm::kUnbounded};
    ColorParam sigma_s{Rgb(2.55f, 3.21f, 3.77f), kNoTexture, 0.0f, kUnbounded, SpectrumForm::kUnbounded};
    // from_reflectance: the coefficients are those whose multiple-scattering albedo is
    // `reflectance` and whose mean free path 1 / sigma_t is `mfp` (times `scale`).
    bool from_reflectance = false;
    ColorParam reflectance{Rgb(1.0f), kNoTexture, 0.0f, 1.0f, SpectrumForm::kAlbedo};
    ColorParam mfp{Rgb(1.0f), kNoTexture, 0.0f, kUnbounded, SpectrumForm::kUnbounded};
    float scale = 1.0f;
    float eta = 1.33f;  // the boundary's index, inside over outside (its lobe has the same)
    float g = 0.0f;     // Henyey-Greenstein asymmetry inside (the table is made for it)
    // kRandomWalk: the scene's medium of the interior (an index into Scene::media).
    uint32_t medium = 0xffffffffu;
    // Photon beam diffusion's profile for (g, eta), made once when the material is loaded
    // (pbrt-v4's ComputeBeamDiffusionBSSRDF, in its constructor).
    BssrdfTable table;

    bool is_textured() const {
        return sigma_a.is_textured() || sigma_s.is_textured() || reflectance.is_textured() || mfp.is_textured();
    }

    // The interior's coefficients at a shading point, `scale` applied (pbrt-v4's GetBSSRDF: each
    // clamped at 0; a reflectance clamped to [0, 1]).
    void coefficients(const TextureSet& t, const TextureContext& ctx, Color& sig_a, Color& sig_s) const {
        if (!from_reflectance) {
            sig_a = clamp_channels(t.eval(sigma_a, ctx) * scale, 0.0f, kUnbounded);
            sig_s = clamp_channels(t.eval(sigma_s, ctx) * scale, 0.0f, kUnbounded);
            return;
        }
        const Color mfree = clamp_channels(t.eval(mfp, ctx) * scale, 0.0f, kUnbounded);
        const Color r = clamp_channels(t.eval(reflectance, ctx), 0.0f, 1.0f);
        subsurface_from_diffuse(table, r, mfree, sig_a, sig_s);
    }
};

}  // namespace candela
