#pragma once
// A material's lobes as the scene file describes them: each lobe's parameters, any colour or
// number of which may be a texture (textures/texture_param.h). `lobe()` evaluates the parameters
// at a shading point and builds the BsdfLobe there; a material none of whose parameters is
// textured builds its lobes once, at load time (material.h).
//
// A new lobe kind adds its parameter struct here (checked by LobeParamsType) and its alternative
// to LobeParams; the scene loader (formats/json/scene_materials.cpp) reads it.
#include <cmath>
#include <concepts>
#include <cstdint>

#include "candela/core/variant.h"
#include "candela/materials/bsdf_lobes.h"
#include "candela/textures/texture_set.h"

namespace candela {

// The index of refraction a lobe uses: `ior`, or in spectral mode, when the scene gives the index
// as a spectrum (a dispersive glass), its value at the path's hero wavelength (the integrator has
// then kept only that wavelength: SampledWavelengths::terminate_secondary).
CANDELA_HD inline float ior_at(float ior, uint32_t ior_spectrum, const TextureSet& t, const TextureContext& ctx) {
    return ctx.lambda && ior_spectrum != kNoSpectrum ? t.spectrum(ior_spectrum)((*ctx.lambda)[0]) : ior;
}

template <class T>
concept LobeParamsType = requires(const T& p, const TextureSet& textures, const TextureContext& ctx) {
    // The lobe at a shading point.
    { p.lobe(textures, ctx) } -> std::same_as<BsdfLobe>;
    // Whether some parameter is a texture (else lobe() is the same everywhere).
    { p.is_textured() } -> std::same_as<bool>;
};

// `diffuse`: Lambertian reflection.
struct DiffuseParams {
    ColorParam albedo{Rgb(0.5f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return LambertianLobe{t.eval(albedo, ctx)};
    }
    CANDELA_HD bool is_textured() const { return albedo.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(albedo);
    }
};
static_assert(LobeParamsType<DiffuseParams>);

// `mirror`: perfect specular reflection scaled by albedo.
struct MirrorParams {
    ColorParam albedo{Rgb(1.0f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return SpecularReflectionLobe{t.eval(albedo, ctx)};
    }
    CANDELA_HD bool is_textured() const { return albedo.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(albedo);
    }
};
static_assert(LobeParamsType<MirrorParams>);

// `dielectric` (smooth): glass of index `ior` (inside over outside), exact Fresnel or Schlick's.
struct DielectricParams {
    float ior = 1.5f;
    ColorParam tint{Rgb(1.0f)};
    bool schlick = false;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return FresnelSpecularLobe{t.eval(tint, ctx), ior_at(ior, ior_spectrum, t, ctx), schlick};
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(tint);
    }
    // The index as a spectrum of the TextureSet (a dispersive glass), for spectral mode; `ior` is
    // then its value at 587.6 nm (the d line, a glass's catalogue index), for RGB mode.
    uint32_t ior_spectrum = kNoSpectrum;
    CANDELA_HD bool is_dispersive() const { return ior_spectrum != kNoSpectrum; }
};
static_assert(LobeParamsType<DielectricParams>);

// `transmission`: the refracted part of a smooth dielectric only.
struct TransmissionParams {
    float ior = 1.5f;
    ColorParam tint{Rgb(1.0f)};

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        SpecularTransmissionLobe l;
        l.tint = t.eval(tint, ctx);
        l.eta = ior_at(ior, ior_spectrum, t, ctx);
        return l;
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(tint);
    }
    // The index as a spectrum of the TextureSet (a dispersive glass), for spectral mode; `ior` is
    // then its value at 587.6 nm (the d line, a glass's catalogue index), for RGB mode.
    uint32_t ior_spectrum = kNoSpectrum;
    CANDELA_HD bool is_dispersive() const { return ior_spectrum != kNoSpectrum; }
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

// `conductor` by its complex index of refraction eta + i k, per channel (given, or of a measured
// `metal`); `multiscatter` adds the compensation of microfacet_multiscatter.h.
struct ConductorParams {
    ColorParam eta{Rgb(1.0f)};
    ColorParam k{Rgb(0.0f)};
    RoughnessParams roughness;
    bool multiscatter = false;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        ConductorLobe l{roughness.distribution(t, ctx), t.eval(eta, ctx), t.eval(k, ctx)};
        if (multiscatter) return l.with_multiscatter();
        return l;
    }
    CANDELA_HD bool is_textured() const {
        return eta.is_textured() || k.is_textured() || roughness.is_textured();
    }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(eta);
        f(k);
    }
};
static_assert(LobeParamsType<ConductorParams>);

// The absorption k of a conductor of eta = 1 that reflects r at normal incidence (pbrt-v4's
// artist-friendly form): k = 2 sqrt(r) / sqrt(1 - r), which makes F(normal) = k^2 / (4 + k^2) = r
// exactly; r is clamped to 0.9999 first, as pbrt-v4's materials do, so that k stays finite.
CANDELA_HD inline Color conductor_k_for_reflectance(const Color& reflectance) {
    Color r = clamp_channels(reflectance, 0.0f, 0.9999f);
    return safe_div(sqrt_channels(r) * 2.0f, sqrt_channels(Color(1.0f) - r));
}

// `conductor` by its reflectance at normal incidence: eta = 1, k = conductor_k_for_reflectance.
struct ConductorReflectanceParams {
    ColorParam reflectance{Rgb(1.0f)};
    RoughnessParams roughness;
    bool multiscatter = false;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        ConductorLobe l{roughness.distribution(t, ctx), Color(1.0f),
                        conductor_k_for_reflectance(t.eval(reflectance, ctx))};
        if (multiscatter) return l.with_multiscatter();
        return l;
    }
    CANDELA_HD bool is_textured() const { return reflectance.is_textured() || roughness.is_textured(); }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(reflectance);
    }
};
static_assert(LobeParamsType<ConductorReflectanceParams>);

// `dielectric` with a `roughness`: microfacet glass (DielectricLobe, smooth below alpha 1e-3).
struct RoughDielectricParams {
    float ior = 1.5f;
    ColorParam tint{Rgb(1.0f)};
    RoughnessParams roughness;
    bool multiscatter = false;  // add the compensation of microfacet_multiscatter.h

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        DielectricLobe l{t.eval(tint, ctx), ior_at(ior, ior_spectrum, t, ctx), roughness.distribution(t, ctx)};
        if (multiscatter) return l.with_multiscatter();
        return l;
    }
    CANDELA_HD bool is_textured() const { return tint.is_textured() || roughness.is_textured(); }
    CANDELA_HD bool is_anisotropic() const { return roughness.is_anisotropic(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(tint);
    }
    // The index as a spectrum of the TextureSet (a dispersive glass), for spectral mode; `ior` is
    // then its value at 587.6 nm (the d line, a glass's catalogue index), for RGB mode.
    uint32_t ior_spectrum = kNoSpectrum;
    CANDELA_HD bool is_dispersive() const { return ior_spectrum != kNoSpectrum; }
};
static_assert(LobeParamsType<RoughDielectricParams>);

// `thin_dielectric`: a pane of glass of index `ior`.
struct ThinDielectricParams {
    float ior = 1.5f;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return ThinDielectricLobe{ior_at(ior, ior_spectrum, t, ctx)};
    }
    CANDELA_HD bool is_textured() const { return false; }
    template <class F>
    void for_each_color(F&&) {}
    // The index as a spectrum of the TextureSet (a dispersive glass), for spectral mode; `ior` is
    // then its value at 587.6 nm (the d line, a glass's catalogue index), for RGB mode.
    uint32_t ior_spectrum = kNoSpectrum;
    CANDELA_HD bool is_dispersive() const { return ior_spectrum != kNoSpectrum; }
};
static_assert(LobeParamsType<ThinDielectricParams>);


// The parameters both coated materials share: the coat and the medium under it (pbrt-v4's
// CoatedDiffuseMaterial and CoatedConductorMaterial; scene keys in docs/SCENE_FORMAT.md).
struct CoatParams {
    RoughnessParams roughness;  // the coat's (pbrt-v4's uroughness, vroughness, not remapped)
    float ior = 1.5f;           // the coat's index over the outside's; pbrt-v4's 0 means 1
    FloatParam thickness{0.01f};
    ColorParam medium_albedo{Rgb(0.0f)};  // pbrt-v4's `albedo`
    FloatParam g{0.0f};
    uint16_t max_depth = 10;
    uint16_t n_samples = 1;
    bool pbrt_v4_weights = false;  // LayeredLobe::pbrt_v4_weights

    // Fills the coat and medium of `lobe` at ctx, clamping as pbrt-v4's GetBxDF does.
    template <class Lobe>
    CANDELA_HD void apply(Lobe& lobe, const TextureSet& t, const TextureContext& ctx) const {
        lobe.coat = CoatInterface{ior == 0.0f ? 1.0f : ior, roughness.distribution(t, ctx)};
        lobe.medium_albedo = clamp_channels(t.eval(medium_albedo, ctx), 0.0f, 1.0f);
        lobe.thickness = t.eval(thickness, ctx);
        lobe.g = clamp(t.eval(g, ctx), -1.0f, 1.0f);
        lobe.max_depth = max_depth;
        lobe.n_samples = n_samples;
        lobe.pbrt_v4_weights = pbrt_v4_weights;
    }
    CANDELA_HD bool is_textured() const {
        return roughness.is_textured() || thickness.is_textured() || medium_albedo.is_textured() ||
               g.is_textured();
    }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(medium_albedo);
    }
};

// `coated_diffuse`: a dielectric coat over a Lambertian base of reflectance `albedo`.
struct CoatedDiffuseParams {
    CoatParams coat;
    ColorParam albedo{Rgb(0.5f)};  // the base's reflectance (pbrt-v4's `reflectance`)

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        CoatedDiffuseLobe l;
        coat.apply(l, t, ctx);
        l.base = LambertianLobe{clamp_channels(t.eval(albedo, ctx), 0.0f, 1.0f)};
        return l;
    }
    CANDELA_HD bool is_textured() const { return coat.is_textured() || albedo.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        coat.for_each_color(f);
        f(albedo);
    }
};
static_assert(LobeParamsType<CoatedDiffuseParams>);

// `coated_conductor`: a dielectric coat over a conductor given by its complex index eta + i k
// relative to the outside (divided by the coat's index here, as pbrt-v4 does), or by its
// normal-incidence `reflectance` (eta = 1, k = conductor_k_for_reflectance, before that
// division).
struct CoatedConductorParams {
    CoatParams coat;
    // pbrt-v4's default base, copper: its metal-Cu-eta and metal-Cu-k spectra
    // interpolated at 650, 550 and 450 nm for red, green and blue.
    ColorParam conductor_eta{Rgb(0.216561f, 0.958162f, 1.165808f)};
    ColorParam conductor_k{Rgb(3.637741f, 2.577065f, 2.393857f)};
    ColorParam reflectance{Rgb(0.0f)};
    bool from_reflectance = false;  // use `reflectance` instead of eta and k
    RoughnessParams conductor_roughness;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        CoatedConductorLobe l;
        coat.apply(l, t, ctx);
        Color eta = from_reflectance ? Color(1.0f) : t.eval(conductor_eta, ctx);
        Color k = from_reflectance ? conductor_k_for_reflectance(t.eval(reflectance, ctx)) : t.eval(conductor_k, ctx);
        float coat_eta = l.coat.eta;
        l.base = ConductorLobe{conductor_roughness.distribution(t, ctx), eta / coat_eta, k / coat_eta};
        return l;
    }
    CANDELA_HD bool is_textured() const {
        return coat.is_textured() || conductor_eta.is_textured() || conductor_k.is_textured() ||
               reflectance.is_textured() || conductor_roughness.is_textured();
    }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        coat.for_each_color(f);
        f(conductor_eta);
        f(conductor_k);
        f(reflectance);
    }
};
static_assert(LobeParamsType<CoatedConductorParams>);

// `hair`: pbrt-v4's HairMaterial (hair.h). The absorption is `sigma_a`, or the one that gives
// the colour `reflectance` (hair_sigma_a_from_reflectance, at this point's beta_n); the scene
// loader turns melanin concentrations into sigma_a. beta_m and beta_n are clamped to
// [0.01, 1] as pbrt-v4 does; alpha is in degrees. h = -1 + 2 v: the lobe changes along the
// surface's v whatever the parameters, so it is built at every hit (is_textured), and its x axis
// is the fibre's tangent dpdu (is_anisotropic).
struct HairParams {
    // pbrt-v4's default: eumelanin 1.3, a brown.
    ColorParam sigma_a{hair_sigma_a_from_concentration(1.3f, 0.0f), kNoTexture, 0.0f, kUnbounded,
                       SpectrumForm::kUnbounded};
    ColorParam reflectance{Rgb(0.0f), kNoTexture, 0.0f, 1.0f, SpectrumForm::kAlbedo};
    bool from_reflectance = false;
    FloatParam eta{1.55f};
    FloatParam beta_m{0.3f};
    FloatParam beta_n{0.3f};
    FloatParam alpha{2.0f};  // degrees

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        const float bm = clamp(t.eval(beta_m, ctx), 0.01f, 1.0f);
        const float bn = clamp(t.eval(beta_n, ctx), 0.01f, 1.0f);
        Color sa;
        if (from_reflectance) {
            sa = map_channels(clamp_channels(t.eval(reflectance, ctx), 0.0f, 1.0f),
                              [bn](float c) { return hair_sigma_a_from_reflectance(c, bn); });
        } else {
            sa = clamp_channels(t.eval(sigma_a, ctx), 0.0f, kUnbounded);
        }
        return HairLobe::make(-1.0f + 2.0f * ctx.uv.y, t.eval(eta, ctx), sa, bm, bn, radians(t.eval(alpha, ctx)));
    }
    CANDELA_HD bool is_textured() const { return true; }
    CANDELA_HD bool is_anisotropic() const { return true; }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(sigma_a);
        f(reflectance);
    }
};
static_assert(LobeParamsType<HairParams>);

// `diffuse_transmission`: Lambertian reflection `reflectance` and transmission `transmittance`,
// each times `scale` and clamped to [0, 1] (pbrt-v4's DiffuseTransmissionMaterial).
struct DiffuseTransmissionParams {
    ColorParam reflectance{Rgb(0.25f)};
    ColorParam transmittance{Rgb(0.25f)};
    float scale = 1.0f;

    CANDELA_HD BsdfLobe lobe(const TextureSet& t, const TextureContext& ctx) const {
        return DiffuseTransmissionLobe{clamp_channels(t.eval(reflectance, ctx) * scale, 0.0f, 1.0f),
                                       clamp_channels(t.eval(transmittance, ctx) * scale, 0.0f, 1.0f)};
    }
    CANDELA_HD bool is_textured() const { return reflectance.is_textured() || transmittance.is_textured(); }
    // Passes each colour parameter to f (make_material prepares them for spectral mode).
    template <class F>
    void for_each_color(F&& f) {
        f(reflectance);
        f(transmittance);
    }
};
static_assert(LobeParamsType<DiffuseTransmissionParams>);

using LobeParams = Variant<DiffuseParams, MirrorParams, DielectricParams, TransmissionParams,
                           ConductorParams, ConductorReflectanceParams, RoughDielectricParams,
                           ThinDielectricParams, CoatedDiffuseParams, CoatedConductorParams,
                           HairParams, DiffuseTransmissionParams>;

}  // namespace candela
