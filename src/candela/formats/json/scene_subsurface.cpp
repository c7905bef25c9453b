// The `subsurface` material (docs/SCENE_FORMAT.md, "subsurface"): pbrt-v4's SubsurfaceMaterial,
// its four ways to give the interior (a named measured medium, sigma_a and sigma_s, reflectance
// and mfp, or its defaults), and for the random walk the interior's homogeneous medium.
#include <fmt/format.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/materials/subsurface.h"
#include "candela/media/scattering_presets.h"
#include "candela/scene/enum_names.h"
#include "candela/spectrum/rgb_to_spectrum.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 2> kMethods = {"random_walk", "tabulated"};

// A coefficient's value at every nm and in RGB, for the random walk's medium: its spectrum when
// the file gives one, else the RGB value's uplift (what the tabulated method evaluates too).
MediumSpectrum constant_coefficient(const ColorParam& p, const Scene& scene) {
    if (p.spectrum != kNoSpectrum) return MediumSpectrum{p.value, scene.textures.spectrum(p.spectrum)};
    return medium_coefficient(p.value);
}

// One constant colour parameter's value at wavelength `lambda` (nm), in its spectral form.
float spectral_value(const ColorParam& p, const Scene& scene, float lambda) {
    if (p.spectrum != kNoSpectrum) return scene.textures.spectrum(p.spectrum)(lambda);
    return uplift(p.value, p.form)(lambda);
}

// The random walk's medium: the interior's constant coefficients, inverted from reflectance and
// mfp channel by channel (RGB) and nm by nm (spectral), as the tabulated method inverts them at
// the path's channels.
HomogeneousMedium walk_medium(const Subsurface& s, const Scene& scene) {
    HomogeneousMedium m;
    m.g = s.g;
    m.subsurface = true;
    if (!s.from_reflectance) {
        m.sigma_a = scaled(constant_coefficient(s.sigma_a, scene), s.scale);
        m.sigma_s = scaled(constant_coefficient(s.sigma_s, scene), s.scale);
        return m;
    }
    Color sig_a, sig_s;
    subsurface_from_diffuse(s.table, clamp_channels(Color(s.reflectance.value), 0.0f, 1.0f),
                            Color(s.mfp.value) * s.scale, sig_a, sig_s);
    m.sigma_a.rgb = Rgb(sig_a[0], sig_a[1], sig_a[2]);
    m.sigma_s.rgb = Rgb(sig_s[0], sig_s[1], sig_s[2]);
    for (int i = 0; i < kDenseSamples; i += 4) {
        Color r, mfree;
        for (int k = 0; k < 4; ++k) {
            const float lambda = float(kDenseLambdaMin + std::min(i + k, kDenseSamples - 1));
            r.c[k] = std::clamp(spectral_value(s.reflectance, scene, lambda), 0.0f, 1.0f);
            mfree.c[k] = std::max(spectral_value(s.mfp, scene, lambda), 0.0f) * s.scale;
        }
        subsurface_from_diffuse(s.table, r, mfree, sig_a, sig_s);
        for (int k = 0; k < 4 && i + k < kDenseSamples; ++k) {
            m.sigma_a.spectrum.v[size_t(i + k)] = sig_a[k];
            m.sigma_s.spectrum.v[size_t(i + k)] = sig_s[k];
        }
    }
    return m;
}

// The interior: `name` (a measured medium), or `sigma_a` and `sigma_s`, or `reflectance` (and
// `mfp`, default 1), or none of them (pbrt-v4's default, whole milk), as pbrt-v4's
// SubsurfaceMaterial::Create takes them.
void read_interior(JsonCursor& c, Scene& scene, Subsurface& s) {
    std::optional<JsonCursor> name = c.get("name");
    std::optional<JsonCursor> sigma_a = c.get("sigma_a"), sigma_s = c.get("sigma_s");
    std::optional<JsonCursor> reflectance = c.get("reflectance"), mfp = c.get("mfp");
    if (name) {
        for (const std::optional<JsonCursor>* other : {&sigma_a, &sigma_s, &reflectance, &mfp})
            if (*other) (*other)->fail("give a medium \"name\" or its coefficients, not both");
        const std::string medium = name->string();
        std::optional<ScatteringPreset> p = find_scattering_preset(medium);
        if (!p)
            name->fail(fmt::format("unknown measured medium {}; the media are {}", json_quoted(medium),
                                   names_list(scattering_preset_names())));
        s.sigma_a.value = p->sigma_a;
        s.sigma_s.value = p->sigma_s;
        return;
    }
    if (sigma_a || sigma_s) {
        if (!sigma_a) sigma_s->fail("\"sigma_s\" needs \"sigma_a\" too");
        if (!sigma_s) sigma_a->fail("\"sigma_a\" needs \"sigma_s\" too");
        for (const std::optional<JsonCursor>* other : {&reflectance, &mfp})
            if (*other) (*other)->fail("give \"sigma_a\" and \"sigma_s\" or \"reflectance\" and \"mfp\", not both");
        s.sigma_a = read_color_param(*sigma_a, scene, Bounds::at_least(0));
        s.sigma_s = read_color_param(*sigma_s, scene, Bounds::at_least(0));
        return;
    }
    if (mfp && !reflectance) mfp->fail("\"mfp\" needs \"reflectance\" (the albedo it goes with)");
    if (!reflectance) return;
    s.from_reflectance = true;
    s.reflectance = read_color_param(*reflectance, scene, Bounds::closed(0, 1));
    // A mean free path of 0 has no coefficients (sigma_t would be infinite).
    if (mfp) s.mfp = read_color_param(*mfp, scene, Bounds::above(0));
}

}  // namespace

Material read_subsurface(JsonCursor& c, Scene& scene, const std::string& material_name) {
    Subsurface s;
    read_interior(c, scene, s);
    if (auto v = c.get("scale")) s.scale = v->number_f(Bounds::above(0));
    if (auto v = c.get("ior")) s.eta = v->number_f(Bounds::above(0));
    if (auto v = c.get("g")) {
        // The measured media give reduced scattering coefficients: their g is 0 (pbrt-v4 ignores
        // another g with a warning).
        if (c.has("name")) v->fail("a named medium's sigma_s is a reduced coefficient: its g is 0");
        s.g = v->number_f(Bounds::open(-1, 1));
    }
    if (auto v = c.get("method")) s.method = v->choice("method", kMethods) == "random_walk"
                                                 ? SubsurfaceMethod::kRandomWalk
                                                 : SubsurfaceMethod::kTabulated;
    for (ColorParam* p : {&s.sigma_a, &s.sigma_s, &s.reflectance, &s.mfp}) prepare_spectral(*p);
    s.table = make_beam_diffusion_table(s.g, s.eta);

    if (s.method == SubsurfaceMethod::kRandomWalk) {
        // A medium has coefficients in space, a texture on a surface: a textured interior has no
        // medium to walk.
        if (s.is_textured())
            c.require("method").fail("the random walk needs constant coefficients (a texture varies on the surface, "
                                     "a medium in space); use \"method\": \"tabulated\"");
        s.medium = uint32_t(scene.media.size());
        scene.media.push_back(walk_medium(s, scene));
        // Not a name a medium of the file can take before the materials are read: shapes name
        // the file's media, never this one (read_shape gives it to the material's shapes).
        scene.medium_names.push_back(fmt::format("(subsurface {})", material_name));
    }

    RoughnessParams roughness;
    if (auto v = c.get("roughness")) roughness = read_roughness(*v, scene);
    Material m = roughness.is_textured() || roughness.alpha_u.value != 0.0f || roughness.alpha_v.value != 0.0f
                     ? make_material(RoughDielectricParams{s.eta, ColorParam{Rgb(1.0f)}, roughness})
                     : make_material(DielectricParams{s.eta});
    m.subsurface = uint32_t(scene.subsurfaces.size());
    scene.subsurfaces.push_back(std::move(s));
    return m;
}

}  // namespace candela
