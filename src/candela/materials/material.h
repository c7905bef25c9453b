#pragma once
// A material: up to Bsdf::kMaxLobes lobes whose values add (see bsdf.h), each described by its
// parameters (lobe_params.h). The scene file's material types are the constructors below; `mix`
// concatenates the lobes of others. A `blend` (material_blend.h) has no lobes of its own: it
// names two materials of the scene, one of which shades at each point.
//
// Most materials have no textured parameter: their BSDF is the same at every point and is built
// once (`bsdf`), so the path tracer reads it in place, as before textures existed. A textured
// material builds its BSDF at each hit from the texture values there (build_bsdf).
#include <array>
#include <concepts>
#include <optional>
#include <span>

#include "candela/core/check.h"
#include "candela/materials/bsdf.h"
#include "candela/materials/lobe_params.h"
#include "candela/materials/material_blend.h"
#include "candela/materials/surface_params.h"

namespace candela {

// Material::subsurface of a material without subsurface scattering.
inline constexpr uint32_t kNoSubsurface = 0xffffffffu;

struct Material {
    Bsdf bsdf;  // the lobes at the parameters' constant values (all of them when !textured)
    std::array<LobeParams, Bsdf::kMaxLobes> params{};  // lobe k of bsdf comes from params[k]
    bool textured = false;  // some parameter is a texture: use build_bsdf at each hit
    // The shading frame needs the surface's parametrization (integrators/shading_frame.h): some lobe
    // is anisotropic, or `surface` maps the normal. Kept by set_surface and make_material.
    bool needs_shading_geometry = false;
    // textured || needs_shading_geometry || blend: the one flag the path tracer tests at every
    // vertex.
    bool per_hit = false;
    bool anisotropic = false;  // some lobe's x axis must follow the surface's dpdu
    // Some lobe's index of refraction is a spectrum: in spectral mode a path that meets this
    // material keeps only its hero wavelength (SampledWavelengths::terminate_secondary).
    bool dispersive = false;
    SurfaceParams surface;     // normal or bump map, alpha
    // A blend: which of two other materials shades is chosen at each hit (render/
    // material_choice.h); bsdf is then empty and surface holds only the alpha.
    std::optional<MaterialBlend> blend;
    // pbrt-v4's `interface`: no surface at all, only a boundary between media. Its one lobe is
    // a pass-through (index-matched specular transmission), so the surface integrators (path,
    // bsdf, whitted) go straight through it as pbrt-v4's path does; volpath skips it without
    // counting a bounce and lets shadow rays through it.
    bool interface = false;
    // pbrt-v4's `subsurface`: the index of its interior in Scene::subsurfaces (materials/
    // subsurface.h); its lobe is the dielectric boundary. Volpath reads it where a path refracts
    // into the material (the tabulated method); the other integrators see the boundary only.
    uint32_t subsurface = kNoSubsurface;
};

// Gives material `m` the surface parameters `s`.
inline void set_surface(Material& m, const SurfaceParams& s) {
    m.surface = s;
    m.needs_shading_geometry = m.anisotropic || s.perturbs_normal();
    m.per_hit = m.textured || m.needs_shading_geometry || m.blend.has_value();
}

// Whether lobe parameters `p` describe an anisotropic lobe: a lobe type says so by an
// is_anisotropic() member (isotropic types need none).
template <class P>
CANDELA_HD bool lobe_is_anisotropic(const P& p) {
    if constexpr (requires { { p.is_anisotropic() } -> std::same_as<bool>; })
        return p.is_anisotropic();
    else
        return false;
}

// Whether lobe parameters `p` have an index of refraction that varies with wavelength (a lobe
// type says so by an is_dispersive() member).
template <class P>
CANDELA_HD bool lobe_is_dispersive(const P& p) {
    if constexpr (requires { { p.is_dispersive() } -> std::same_as<bool>; })
        return p.is_dispersive();
    else
        return false;
}

// The material's BSDF at a shading point, written into `bsdf` (a fresh Bsdf: in place, so that
// the per-hit BSDF of spectral mode is not built and then copied, 420 bytes each).
CANDELA_HD inline void build_bsdf_into(Bsdf& bsdf, const Material& m, const TextureSet& textures,
                                       const TextureContext& ctx) {
    bsdf.lobe_count = m.bsdf.lobe_count;
    for (uint32_t k = 0; k < m.bsdf.lobe_count; ++k)
        bsdf.lobes[k] = visit([&](const auto& p) { return p.lobe(textures, ctx); }, m.params[k]);
}

// The material's BSDF at a shading point.
CANDELA_HD inline Bsdf build_bsdf(const Material& m, const TextureSet& textures, const TextureContext& ctx) {
    Bsdf bsdf;
    build_bsdf_into(bsdf, m, textures, ctx);
    return bsdf;
}

// A material of the lobes `parts` describe (at most Bsdf::kMaxLobes; the scene loader checks).
inline Material make_material(std::span<const LobeParams> parts) {
    CANDELA_CHECK(parts.size() <= Bsdf::kMaxLobes);
    Material m;
    const TextureSet no_textures;
    const TextureContext anywhere{};
    for (const LobeParams& p : parts) {
        const uint32_t k = m.bsdf.lobe_count++;
        m.params[k] = p;
        visit([](auto& q) { q.for_each_color([](ColorParam& c) { prepare_spectral(c); }); }, m.params[k]);
        m.dispersive = m.dispersive || visit([](const auto& q) { return lobe_is_dispersive(q); }, p);
        // Textured parameters contribute their constant here; build_bsdf replaces the lobe.
        m.bsdf.lobes[k] = visit([&](const auto& q) { return q.lobe(no_textures, anywhere); }, p);
        m.textured = m.textured || visit([](const auto& q) { return q.is_textured(); }, p);
        m.anisotropic = m.anisotropic || visit([](const auto& q) { return lobe_is_anisotropic(q); }, p);
    }
    m.needs_shading_geometry = m.anisotropic;
    m.per_hit = m.textured || m.needs_shading_geometry;
    return m;
}

// A material of the one lobe `p`.
inline Material make_material(const LobeParams& p) { return make_material(std::span<const LobeParams>(&p, 1)); }

// `diffuse`: Lambertian reflection of the given albedo.
inline Material make_diffuse(Rgb albedo) { return make_material(DiffuseParams{ColorParam{albedo}}); }

// `mirror`: perfect specular reflection scaled by albedo.
inline Material make_mirror(Rgb albedo) { return make_material(MirrorParams{ColorParam{albedo}}); }

// `dielectric`: smooth glass of index `ior` (inside over outside) reflecting and refracting in
// Fresnel's proportions, exact or by Schlick's approximation.
inline Material make_dielectric(float ior, Rgb tint = Rgb(1.0f), bool schlick = false) {
    return make_material(DielectricParams{ior, ColorParam{tint}, schlick});
}

// `transmission`: the refracted part of a dielectric only (1 - F); the reflected part is lost.
inline Material make_transmission(float ior, Rgb tint = Rgb(1.0f)) {
    return make_material(TransmissionParams{ior, ColorParam{tint}});
}

// `mix`: the lobes of `parts`, in order, in one material (their f add up). The parts may hold at
// most Bsdf::kMaxLobes lobes together (the scene loader checks).
inline Material make_mix(std::span<const Material> parts) {
    std::array<LobeParams, Bsdf::kMaxLobes> all{};
    size_t n = 0;
    for (const Material& part : parts) {
        for (uint32_t k = 0; k < part.bsdf.lobe_count; ++k) {
            CANDELA_CHECK(n < Bsdf::kMaxLobes);
            all[n++] = part.params[k];
        }
    }
    return make_material(std::span<const LobeParams>(all.data(), n));
}

// `blend`: part 1 (an index into the scene's materials) with probability `amount`, else part 0.
inline Material make_blend(uint32_t part0, uint32_t part1, const FloatParam& amount) {
    Material m;
    m.blend = MaterialBlend{{part0, part1}, amount};
    m.per_hit = true;
    return m;
}

// The surface colour the `albedo` integrator shows: the sum of the lobes' albedo or tint.
CANDELA_HD inline Color material_albedo(const Material& m) { return m.bsdf.albedo(); }

}  // namespace candela
