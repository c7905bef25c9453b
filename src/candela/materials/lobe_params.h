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

using LobeParams = Variant<DiffuseParams, MirrorParams, DielectricParams, TransmissionParams>;

}  // namespace candela
