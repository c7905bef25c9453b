#pragma once
// A material's lobes as the scene file describes them: each lobe's parameters, any colour or
// number of which may be a texture (textures/texture_param.h). `lobe()` evaluates the parameters
// at a shading point and builds the BsdfLobe there; a material none of whose parameters is
// textured builds its lobes once, at load time (material.h).
//
// A new lobe kind adds its parameter struct here (checked by LobeParamsType) and its alternative
// to LobeParams; the scene loader (scene/scene_materials.cpp) reads it.
#include <concepts>

#include "candela/core/variant.h"
#include "candela/materials/bsdf_lobes.h"
#include "candela/textures/texture_set.h"

namespace candela {

template <class T>
concept LobeParamsType = requires(const T& p, const TextureSet& textures, const TextureContext& ctx) {
    // The lobe at a shading point.
    { p.lobe(textures, ctx) } -> std::same_as<BsdfLobe>;
    // Whether some parameter is a texture (else lobe() is the same everywhere).
    { p.is_textured() } -> std::same_as<bool>;
};

// `diffuse`: Lambertian reflection.
struct DiffuseParams {
    ColorParam albedo{Color(0.5f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return LambertianLobe{t.eval(albedo, ctx)};
    }
    CANDELA_HD bool is_textured() const { return albedo.is_textured(); }
};
static_assert(LobeParamsType<DiffuseParams>);

// `mirror`: perfect specular reflection scaled by albedo.
struct MirrorParams {
    ColorParam albedo{Color(1.0f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return SpecularReflectionLobe{t.eval(albedo, ctx)};
    }
    CANDELA_HD bool is_textured() const { return albedo.is_textured(); }
};
static_assert(LobeParamsType<MirrorParams>);

// `dielectric` (smooth): glass of index `ior` (inside over outside), exact Fresnel or Schlick's.
struct DielectricParams {
    float ior = 1.5f;
    ColorParam tint{Color(1.0f)};
    bool schlick = false;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return FresnelSpecularLobe{t.eval(tint, ctx), ior, schlick};
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured(); }
};
static_assert(LobeParamsType<DielectricParams>);

// `transmission`: the refracted part of a smooth dielectric only.
struct TransmissionParams {
    float ior = 1.5f;
    ColorParam tint{Color(1.0f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return SpecularTransmissionLobe{t.eval(tint, ctx), ior};
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured(); }
};
static_assert(LobeParamsType<TransmissionParams>);

// A `roughness`: the Trowbridge-Reitz alpha along the surface's u (dpdu) and v directions.
struct RoughnessParams {
    FloatParam alpha_u{0.0f};
    FloatParam alpha_v{0.0f};

    CANDELA_HD TrowbridgeReitz distribution(const TextureSet& t, const TextureContext& ctx) const {
        return TrowbridgeReitz(t.eval(alpha_u, ctx), t.eval(alpha_v, ctx));
    }
    CANDELA_HD bool is_textured() const { return alpha_u.is_textured() || alpha_v.is_textured(); }
    // Whether alpha may differ between u and v somewhere (the shading frame must follow dpdu).
    CANDELA_HD bool is_anisotropic() const {
        if (alpha_u.texture != alpha_v.texture) return true;
        return !alpha_u.is_textured() && alpha_u.value != alpha_v.value;
    }
};

// `conductor` by its complex index of refraction eta + i k, per channel.
struct ConductorParams {
    ColorParam eta{Color(1.0f)};
    ColorParam k{Color(0.0f)};
    RoughnessParams roughness;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return ConductorLobe{roughness.distribution(t, ctx), t.eval(eta, ctx), t.eval(k, ctx)};
    }
    CANDELA_HD bool is_textured() const {
        return eta.is_textured() || k.is_textured() || roughness.is_textured();
    }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
};
static_assert(LobeParamsType<ConductorParams>);

// `conductor` by its reflectance at normal incidence (pbrt-v4's artist-friendly form): eta = 1
// and k = 2 sqrt(r) / sqrt(1 - r), which makes F(normal) = k^2 / (4 + k^2) = r exactly; r is
// clamped to 0.9999 first, as pbrt-v4's ConductorMaterial does, so that k stays finite.
struct ConductorReflectanceParams {
    ColorParam reflectance{Color(1.0f)};
    RoughnessParams roughness;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        Color r = clamp_channels(t.eval(reflectance, ctx), 0.0f, 0.9999f);
        Color k = safe_div(sqrt_channels(r) * 2.0f, sqrt_channels(Color(1.0f) - r));
        return ConductorLobe{roughness.distribution(t, ctx), Color(1.0f), k};
    }
    CANDELA_HD bool is_textured() const { return reflectance.is_textured() || roughness.is_textured(); }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
};
static_assert(LobeParamsType<ConductorReflectanceParams>);

// `dielectric` with a `roughness`: microfacet glass (DielectricLobe, smooth below alpha 1e-3).
struct RoughDielectricParams {
    float ior = 1.5f;
    ColorParam tint{Color(1.0f)};
    RoughnessParams roughness;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return DielectricLobe{t.eval(tint, ctx), ior, roughness.distribution(t, ctx)};
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured() || roughness.is_textured(); }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
};
static_assert(LobeParamsType<RoughDielectricParams>);

// `thin_dielectric`: a pane of glass of index `ior`.
struct ThinDielectricParams {
    float ior = 1.5f;

    CANDELA_HD BsdfLobe lobe(const TextureSet&, const TextureContext&) const {
        return ThinDielectricLobe{ior};
    }
    CANDELA_HD bool is_textured() const { return false; }
};
static_assert(LobeParamsType<ThinDielectricParams>);

using LobeParams = Variant<DiffuseParams, MirrorParams, DielectricParams, TransmissionParams,
                           ConductorParams, ConductorReflectanceParams, RoughDielectricParams,
                           ThinDielectricParams>;

}  // namespace candela
