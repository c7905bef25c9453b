// The scene file's `media` section (docs/SCENE_FORMAT.md, "Media"): named participating media,
// pbrt-v4's kinds with pbrt-v4's parameters and defaults (media.cpp, MakeNamedMedium), and the
// names that the camera and shapes give for the media they sit in.
#include <fmt/format.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/formats/json/scene_spectra.h"
#include "candela/media/scattering_presets.h"
#include "candela/scene/enum_names.h"
#include "candela/spectrum/spectrum_rgb.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 6> kMediumTypes = {"cloud", "homogeneous", "nanovdb", "openvdb", "rgbgrid",
                                                         "uniformgrid"};

// pbrt-v4's `homogeneous`: sigma_a and sigma_s (default 1 each, or a `preset`'s), `scale`, `g`,
// and emission `Le` (default none) with `Le_scale`.
HomogeneousMedium read_homogeneous(JsonCursor& c, const Scene& scene) {
    HomogeneousMedium m;
    m.sigma_a = medium_coefficient(Rgb(1.0f));
    m.sigma_s = medium_coefficient(Rgb(1.0f));
    std::optional<JsonCursor> preset = c.get("preset");
    if (preset) {
        const std::string name = preset->string();
        std::optional<ScatteringPreset> p = find_scattering_preset(name);
        if (!p)
            preset->fail(fmt::format("unknown medium preset {}; the presets are {}", json_quoted(name),
                                     names_list(scattering_preset_names())));
        m.sigma_a = medium_coefficient(p->sigma_a);
        m.sigma_s = medium_coefficient(p->sigma_s);
    }
    // pbrt-v4 takes sigma_a and sigma_s only when no preset was found; candela says so.
    for (std::string_view key : {"sigma_a", "sigma_s"}) {
        std::optional<JsonCursor> v = c.get(key);
        if (!v) continue;
        if (preset) c.document().fail_at_key(c.pointer(), key, fmt::format("give \"preset\" or \"{}\", not both", key));
        (key == "sigma_a" ? m.sigma_a : m.sigma_s) = read_medium_coefficient(*v, scene);
    }
    const float scale = read_medium_scale(c);
    m.sigma_a = scaled(m.sigma_a, scale);
    m.sigma_s = scaled(m.sigma_s, scale);
    if (std::optional<MediumSpectrum> Le = read_medium_emission(c, scene)) {
        m.Le = *Le;
        m.emissive = true;
    }
    m.g = read_medium_g(c);
    return m;
}

}  // namespace

MediumSpectrum read_medium_coefficient(const JsonCursor& c, const Scene& scene) {
    if (std::optional<DenseSpectrum> s = read_spectrum(c, scene.file.parent_path())) {
        for (int i = 0; i < kDenseSamples; ++i)
            if (const float v = s->v[size_t(i)]; !(v >= 0.0f) || !std::isfinite(v))
                c.fail(fmt::format("a medium's coefficient must be finite and >= 0 at every wavelength; it is {} at {} nm",
                                   v, kDenseLambdaMin + i));
        // RGB mode: the spectrum's colour as a reflectance's (linear in the spectrum), clipped at 0.
        const Rgb rgb = reflectance_rgb(*s);
        return MediumSpectrum{Rgb(std::max(rgb.r, 0.0f), std::max(rgb.g, 0.0f), std::max(rgb.b, 0.0f)), *s};
    }
    const Rgb rgb = c.colour(Bounds::at_least(0));
    if (!rgb.is_finite()) c.fail("a medium's coefficient must be finite");
    return medium_coefficient(rgb);
}

float read_medium_scale(JsonCursor& c) {
    std::optional<JsonCursor> v = c.get("scale");
    return v ? v->number_f(Bounds::at_least(0)) : 1.0f;
}

void read_medium_coefficients(JsonCursor& c, const Scene& scene, MediumSpectrum& sigma_a, MediumSpectrum& sigma_s,
                              bool scalable) {
    sigma_a = medium_coefficient(Rgb(1.0f));
    sigma_s = medium_coefficient(Rgb(1.0f));
    if (auto v = c.get("sigma_a")) sigma_a = read_medium_coefficient(*v, scene);
    if (auto v = c.get("sigma_s")) sigma_s = read_medium_coefficient(*v, scene);
    if (!scalable) return;
    const float scale = read_medium_scale(c);
    sigma_a = scaled(sigma_a, scale);
    sigma_s = scaled(sigma_s, scale);
}

void read_temperature_mapping(JsonCursor& c, float& offset, float& scale) {
    std::optional<JsonCursor> cutoff = c.get("temperature_cutoff"), given = c.get("temperature_offset");
    offset = given ? given->number_f() : (cutoff ? cutoff->number_f() : 0.0f);
    if (auto s = c.get("temperature_scale")) scale = s->number_f();
}

float read_medium_g(JsonCursor& c) {
    std::optional<JsonCursor> v = c.get("g");
    // pbrt-v4 clamps |g| to 0.99 where it evaluates the phase function; beyond 1 it is no
    // phase function at all.
    return v ? v->number_f(Bounds::closed(-1, 1)) : 0.0f;
}

std::optional<MediumSpectrum> read_medium_emission(JsonCursor& c, const Scene& scene) {
    std::optional<JsonCursor> Le = c.get("Le");
    std::optional<JsonCursor> Le_scale = c.get("Le_scale");
    if (!Le) return std::nullopt;
    float scale = 1.0f;
    if (Le_scale && Le_scale->is_number()) scale = Le_scale->number_f(Bounds::at_least(0));
    MediumSpectrum m;
    // As an area light's `emission` (scene_shapes.cpp): a spectrum normalized to luminance 1,
    // an RGB colour's illuminant uplift (pbrt-v4: Lescale /= SpectrumToPhotometric(Le)).
    if (std::optional<LightSpectrum> s = read_light_spectrum(*Le, scene.file.parent_path())) {
        m = MediumSpectrum{s->rgb, s->normalized};
    } else {
        const Rgb rgb = Le->colour(Bounds::at_least(0));
        if (!rgb.is_finite()) Le->fail("a medium's emission must be finite");
        m = medium_emission(rgb);
    }
    m = scaled(m, scale);
    if (m.is_black()) return std::nullopt;
    return m;
}

uint32_t medium_index(const JsonCursor& c, const Scene& scene) {
    const std::string name = c.string();
    if (name.empty()) return kNoMedium;  // pbrt-v4's "": no medium
    for (size_t i = 0; i < scene.medium_names.size(); ++i)
        if (scene.medium_names[i] == name) return uint32_t(i);
    if (scene.medium_names.empty()) c.fail(fmt::format("unknown medium {}; no media are defined", json_quoted(name)));
    std::vector<std::string_view> names(scene.medium_names.begin(), scene.medium_names.end());
    c.fail(fmt::format("unknown medium {}; defined media: {}", json_quoted(name), names_list(names)));
}

void read_media(JsonCursor media, Scene& scene, MemoryBudget& budget) {
    for (auto& [name, c] : media.members()) {
        if (name.empty()) c.fail("a medium needs a name: \"\" means no medium");
        const std::string_view type = c.require("type").choice("medium type", kMediumTypes);
        // The medium's placement (pbrt-v4: the transformation current at MakeNamedMedium).
        Transform to_world;
        if (auto t = c.get("transform")) to_world = read_transform(*t);
        if (type == "homogeneous") {
            scene.media.push_back(read_homogeneous(c, scene));
        } else if (type == "nanovdb" || type == "openvdb") {
            scene.media.push_back(read_vdb_medium(type, c, scene, to_world, budget));
        } else {
            scene.media.push_back(read_bounded_medium(type, c, scene, to_world, budget));
        }
        c.reject_unknown_keys();
        scene.medium_names.push_back(name);
    }
}

}  // namespace candela
