// The `materials` part of a scene file: each material's lobes as LobeParams (materials/
// lobe_params.h), whose colours and numbers may be textures (scene_textures.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "candela/scene/enum_names.h"
#include "candela/formats/json/scene_sections.h"
#include "candela/formats/json/scene_spectra.h"
#include "candela/spectrum/named_spectra.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 14> kMaterialTypes = {
    "blend", "coated_conductor", "coated_diffuse", "conductor", "diffuse", "diffuse_transmission", "dielectric",
    "hair", "interface", "mirror", "mix", "subsurface", "thin_dielectric", "transmission"};
// The types a `mix` may combine: every material type but `mix` itself.
constexpr std::array<std::string_view, 10> kLobeMaterialTypes = {
    "coated_conductor", "coated_diffuse", "conductor", "diffuse", "diffuse_transmission", "dielectric", "hair",
    "mirror",
    "thin_dielectric", "transmission"};
constexpr std::array<std::string_view, 2> kFresnelNames = {"exact", "schlick"};
constexpr std::array<std::string_view, 2> kNormalMapConventions = {"opengl", "directx"};
// Reflectances above 1 would create energy; negative ones are meaningless.
constexpr Bounds kReflectance = Bounds::closed(0, 1);
// A Trowbridge-Reitz alpha: 0 is smooth; there is no upper limit (pbrt-v4 sets none either).
constexpr Bounds kRoughness = Bounds::at_least(0);

// True when the roughness is the constant 0: the smooth lobe of before roughness existed.
bool is_zero(const RoughnessParams& r) {
    return !r.is_textured() && r.alpha_u.value == 0.0f && r.alpha_v.value == 0.0f;
}

// `multiscatter`: Kulla & Conty's compensation on a rough conductor or dielectric (off, as pbrt-v4).
bool read_multiscatter(JsonCursor& c) {
    std::optional<JsonCursor> v = c.get("multiscatter");
    return v && v->boolean();
}

// `conductor`: eta and k, or reflectance, or a measured metal (one of the three, as pbrt-v4
// takes eta/k or reflectance), and roughness.
LobeParams read_conductor(JsonCursor& c, Scene& scene) {
    RoughnessParams roughness;
    if (auto v = c.get("roughness")) roughness = read_roughness(*v, scene);
    const bool multiscatter = read_multiscatter(c);
    std::optional<JsonCursor> eta = c.get("eta"), k = c.get("k"), reflectance = c.get("reflectance");
    if (std::optional<JsonCursor> metal = c.get("metal")) {
        if (eta || k || reflectance)
            (eta ? *eta : k ? *k : *reflectance)
                .fail("give one of \"metal\", \"eta\" and \"k\", or \"reflectance\"");
        const std::string_view symbol = metal->choice("metal", metal_names());
        const MetalIor& ior = metal_ior(*parse_metal(symbol));
        ColorParam eta_param{ior.eta, kNoTexture, -kUnbounded, kUnbounded, SpectrumForm::kUnbounded};
        ColorParam k_param{ior.k, kNoTexture, -kUnbounded, kUnbounded, SpectrumForm::kUnbounded};
        // Spectral mode uses the measured spectra where pbrt-v4 names them (metal-Au-eta, ...);
        // RGB mode, and spectral mode for a metal without them (Cr, Fe, Ti), the RGB table.
        const DenseSpectrum* eta_spectrum = named_spectrum(fmt::format("metal-{}-eta", symbol));
        const DenseSpectrum* k_spectrum = named_spectrum(fmt::format("metal-{}-k", symbol));
        if (eta_spectrum && k_spectrum) {
            eta_param.spectrum = scene.textures.add_spectrum(*eta_spectrum);
            k_param.spectrum = scene.textures.add_spectrum(*k_spectrum);
        }
        return ConductorParams{eta_param, k_param, roughness, multiscatter};
    }
    if (reflectance) {
        if (eta || k)
            (eta ? *eta : *k).fail("give \"eta\" and \"k\" or \"reflectance\", not both");
        return ConductorReflectanceParams{read_color_param(*reflectance, scene, kReflectance), roughness,
                                          multiscatter};
    }
    if (!eta || !k) c.fail("a conductor needs \"eta\" and \"k\", \"reflectance\" or \"metal\"");
    return ConductorParams{read_color_param(*eta, scene, Bounds::at_least(0)),
                           read_color_param(*k, scene, Bounds::at_least(0)), roughness, multiscatter};
}

// An index of refraction: a number, or a spectrum (a glass that disperses, e.g.
// {"spectrum": "glass-BK7"}). A spectrum is kept for spectral mode (`spectrum` gets its index in
// the scene's textures) and the number returned is its value at the d line, 587.6 nm, the index a
// glass catalogue quotes, which RGB mode uses. A constant spectrum is just that number.
float read_ior(const JsonCursor& v, Scene& scene, uint32_t& spectrum) {
    std::optional<DenseSpectrum> s = read_spectrum(v, scene.file.parent_path());
    if (!s) return v.number_f(Bounds::above(0));
    for (float x : s->v)
        if (!(x > 0.0f)) v.fail(fmt::format("an index of refraction must be > 0 at every wavelength, got {}", x));
    const float d_line = (*s)(587.6f);
    if (std::all_of(s->v.begin(), s->v.end(), [&](float x) { return x == s->v[0]; })) return d_line;
    spectrum = scene.textures.add_spectrum(*s);
    return d_line;
}

// What both coated materials share: the coat (its roughness under `roughness_key`) and the
// medium beneath it. pbrt-v4's names: uroughness/vroughness (or interface.*), eta (or
// interface.eta), thickness, albedo, g, maxdepth, nsamples.
CoatParams read_coat(JsonCursor& c, Scene& scene, std::string_view roughness_key) {
    CoatParams p;
    if (auto v = c.get(roughness_key)) p.roughness = read_roughness(*v, scene);
    if (auto v = c.get("ior")) p.ior = v->number_f(Bounds::above(0));
    if (auto v = c.get("thickness")) p.thickness = read_float_param(*v, scene, Bounds::at_least(0));
    if (auto v = c.get("medium_albedo")) p.medium_albedo = read_color_param(*v, scene, kReflectance);
    if (auto v = c.get("g")) p.g = read_float_param(*v, scene, Bounds::closed(-1, 1));
    if (auto v = c.get("maxdepth")) p.max_depth = static_cast<uint16_t>(v->integer(Bounds::closed(0, 65535)));
    if (auto v = c.get("nsamples")) p.n_samples = static_cast<uint16_t>(v->integer(Bounds::closed(1, 65535)));
    if (auto v = c.get("pbrt_v4_weights")) p.pbrt_v4_weights = v->boolean();
    return p;
}

CoatedDiffuseParams read_coated_diffuse(JsonCursor& c, Scene& scene) {
    CoatedDiffuseParams p;
    p.coat = read_coat(c, scene, "roughness");
    if (auto v = c.get("albedo")) p.albedo = read_color_param(*v, scene, kReflectance);
    return p;
}

CoatedConductorParams read_coated_conductor(JsonCursor& c, Scene& scene) {
    CoatedConductorParams p;
    p.coat = read_coat(c, scene, "interface_roughness");
    if (auto v = c.get("conductor_roughness")) p.conductor_roughness = read_roughness(*v, scene);
    std::optional<JsonCursor> eta = c.get("conductor_eta"), k = c.get("conductor_k");
    if (auto r = c.get("reflectance")) {
        // pbrt-v4 refuses both forms of the base's colour at once; without either, the base is
        // its default copper (each of eta and k defaults on its own, as in pbrt-v4).
        if (eta || k)
            (eta ? *eta : *k).fail("give \"conductor_eta\" and \"conductor_k\" or \"reflectance\", not both");
        p.reflectance = read_color_param(*r, scene, kReflectance);
        p.from_reflectance = true;
    }
    if (eta) p.conductor_eta = read_color_param(*eta, scene, Bounds::above(0));
    if (k) p.conductor_k = read_color_param(*k, scene, Bounds::at_least(0));
    return p;
}

// `hair` (pbrt-v4's HairMaterial): the absorption as `sigma_a`, `reflectance` or melanin
// concentrations `eumelanin` and `pheomelanin` (one of the three; none: eumelanin 1.3, pbrt-v4's
// brown), and eta, beta_m, beta_n, scale_angle (degrees; pbrt-v4's `alpha`, a name every candela
// material already gives its coverage). Concentrations are numbers, not textures.
HairParams read_hair(JsonCursor& c, Scene& scene) {
    HairParams p;
    std::optional<JsonCursor> sigma_a = c.get("sigma_a"), reflectance = c.get("reflectance");
    std::optional<JsonCursor> eumelanin = c.get("eumelanin"), pheomelanin = c.get("pheomelanin");
    const int given = int(sigma_a.has_value()) + int(reflectance.has_value()) +
                      int(eumelanin.has_value() || pheomelanin.has_value());
    if (given > 1) {
        const JsonCursor& second = reflectance && sigma_a ? *reflectance : eumelanin ? *eumelanin : *pheomelanin;
        second.fail("give one of \"sigma_a\", \"reflectance\", or \"eumelanin\"/\"pheomelanin\"");
    }
    if (sigma_a) {
        p.sigma_a = read_color_param(*sigma_a, scene, Bounds::at_least(0));
    } else if (reflectance) {
        p.reflectance = read_color_param(*reflectance, scene, kReflectance);
        p.from_reflectance = true;
    } else {
        const float ce = eumelanin ? eumelanin->number_f(Bounds::at_least(0)) : (pheomelanin ? 0.0f : 1.3f);
        const float cp = pheomelanin ? pheomelanin->number_f(Bounds::at_least(0)) : 0.0f;
        p.sigma_a.value = hair_sigma_a_from_concentration(ce, cp);
    }
    if (auto v = c.get("eta")) p.eta = read_float_param(*v, scene, Bounds::above(0));
    if (auto v = c.get("beta_m")) p.beta_m = read_float_param(*v, scene, Bounds::closed(0, 1));
    if (auto v = c.get("beta_n")) p.beta_n = read_float_param(*v, scene, Bounds::closed(0, 1));
    if (auto v = c.get("scale_angle")) p.alpha = read_float_param(*v, scene, Bounds::closed(-90, 90));
    return p;
}

// The lobe of a material of one of kLobeMaterialTypes, whose `type` (already read) is `type`.
LobeParams read_lobe(JsonCursor& c, std::string_view type, Scene& scene) {
    if (type == "coated_diffuse") return read_coated_diffuse(c, scene);
    if (type == "coated_conductor") return read_coated_conductor(c, scene);
    if (type == "diffuse") {
        DiffuseParams p;
        if (auto v = c.get("albedo")) p.albedo = read_color_param(*v, scene, kReflectance);
        return p;
    }
    if (type == "diffuse_transmission") {
        DiffuseTransmissionParams p;
        if (auto v = c.get("reflectance")) p.reflectance = read_color_param(*v, scene, kReflectance);
        if (auto v = c.get("transmittance")) p.transmittance = read_color_param(*v, scene, kReflectance);
        if (auto v = c.get("scale")) p.scale = v->number_f(Bounds::at_least(0));
        return p;
    }
    if (type == "mirror") {
        MirrorParams p;
        if (auto v = c.get("albedo")) p.albedo = read_color_param(*v, scene, kReflectance);
        return p;
    }
    if (type == "conductor") return read_conductor(c, scene);
    if (type == "hair") return read_hair(c, scene);
    float ior = 1.5f;
    uint32_t ior_spectrum = kNoSpectrum;
    if (auto v = c.get("ior")) ior = read_ior(*v, scene, ior_spectrum);
    if (type == "thin_dielectric") {
        ThinDielectricParams p{ior};
        p.ior_spectrum = ior_spectrum;
        return p;
    }
    ColorParam tint{Rgb(1.0f)};
    if (auto v = c.get("tint")) tint = read_color_param(*v, scene, kReflectance);
    if (type == "transmission") {
        TransmissionParams p{ior, tint};
        p.ior_spectrum = ior_spectrum;
        return p;
    }
    std::optional<JsonCursor> fresnel = c.get("fresnel");
    bool schlick = fresnel && fresnel->choice("fresnel", kFresnelNames) == "schlick";
    RoughnessParams roughness;
    if (auto v = c.get("roughness")) roughness = read_roughness(*v, scene);
    // Smooth glass loses nothing between microfacets: multiscatter changes nothing there.
    const bool multiscatter = read_multiscatter(c);
    // Roughness 0 keeps the smooth lobe of version 1 (and its images, bit for bit).
    if (is_zero(roughness)) {
        DielectricParams p{ior, tint, schlick};
        p.ior_spectrum = ior_spectrum;
        return p;
    }
    if (schlick) fresnel->fail("fresnel \"schlick\" is for a smooth dielectric (roughness 0)");
    RoughDielectricParams p{ior, tint, roughness, multiscatter};
    p.ior_spectrum = ior_spectrum;
    return p;
}

// `mix`: 1 to Bsdf::kMaxLobes materials of the other types, their lobes in one material. Mixes do
// not nest, so each part is one lobe and the count bounds the lobes.
Material read_mix(JsonCursor& c, Scene& scene) {
    JsonCursor lobes = c.require("lobes");
    std::vector<JsonCursor> parts = lobes.elements();
    if (parts.empty() || parts.size() > Bsdf::kMaxLobes)
        lobes.fail_expected(fmt::format("an array of 1 to {} materials", Bsdf::kMaxLobes));
    std::vector<LobeParams> params;
    for (JsonCursor& part : parts) {
        JsonCursor type_cursor = part.require("type");
        if (type_cursor.is_string() && (type_cursor.string() == "mix" || type_cursor.string() == "blend"))
            type_cursor.fail(fmt::format("a mix cannot contain a {}; expected one of: {}", type_cursor.string(),
                                         names_list(kLobeMaterialTypes)));
        std::string_view type = type_cursor.choice("material type", kLobeMaterialTypes);
        params.push_back(read_lobe(part, type, scene));
        part.reject_unknown_keys();
    }
    return make_material(params);
}

// A blend whose parts are named in the file, to be resolved once every material is read (parts
// may be defined after the blend).
struct PendingBlend {
    uint32_t index;                    // the blend's index in Scene::materials
    std::vector<JsonCursor> parts;     // its two part names
};

// `blend`: two materials named in the section and the probability `amount` of the second
// (pbrt-v4's `mix` material: "materials" and "amount", default 0.5). A blend's normal comes from
// the part that shades, so it takes no map; it may take the shape's `alpha` (read_surface).
Material read_blend(JsonCursor& c, Scene& scene, std::vector<PendingBlend>& pending) {
    std::vector<JsonCursor> parts = c.require("materials").elements(2, "an array of 2 material names");
    for (const JsonCursor& part : parts)
        if (!part.is_string()) part.fail_expected("a material name");
    FloatParam amount{0.5f, kNoTexture, 0.0f, 1.0f};
    if (auto v = c.get("amount")) amount = read_float_param(*v, scene, Bounds::closed(0, 1));
    for (std::string_view key : {"normal_map", "normal_map_convention", "bump_map"})
        if (auto v = c.get(key))
            v->fail(fmt::format("a blend shades with the normal of the part it chooses; give \"{}\" to its parts",
                                key));
    pending.push_back({uint32_t(scene.materials.size()), std::move(parts)});
    return make_blend(0, 0, amount);
}

// Gives each pending blend the indices of its parts: names of the section, not the blend itself,
// not cut out (alpha is the shape's, read from the material the shape names: a part's alpha
// would never be used), and no chain of parts that leads back to a blend.
void resolve_blends(const std::vector<PendingBlend>& pending, Scene& scene) {
    std::vector<std::string_view> names(scene.material_names.begin(), scene.material_names.end());
    std::vector<const PendingBlend*> pending_of(scene.materials.size(), nullptr);
    for (const PendingBlend& b : pending) {
        pending_of[b.index] = &b;
        for (size_t k = 0; k < 2; ++k) {
            const std::string name = b.parts[k].string();
            const auto found = std::find(names.begin(), names.end(), name);
            if (found == names.end())
                b.parts[k].fail(fmt::format("unknown material {}; defined materials: {}", json_quoted(name),
                                            names_list(names)));
            const uint32_t part = uint32_t(found - names.begin());
            if (part == b.index) b.parts[k].fail(fmt::format("a blend cannot contain itself ({})", json_quoted(name)));
            // The random walk's medium is given to the shapes of its material, which a blend's
            // part is not.
            if (const uint32_t s = scene.materials[part].subsurface;
                s != kNoSubsurface && scene.subsurfaces[s].method == SubsurfaceMethod::kRandomWalk)
                b.parts[k].fail(fmt::format("material {} is a subsurface random walk, which cannot be a blend's part "
                                            "(its interior is the medium of its shapes); use the tabulated method",
                                            json_quoted(name)));
            if (scene.materials[part].surface.cuts_out())
                b.parts[k].fail(fmt::format(
                    "material {} has alpha < 1: a blend's parts cannot be cut out (give the alpha to the blend)",
                    json_quoted(name)));
            scene.materials[b.index].blend->parts[k] = part;
        }
    }
    // Depth-first search for a cycle, with an explicit stack (no file's nesting exhausts the call
    // stack): 0 unseen, 1 on the current chain, 2 finished.
    std::vector<uint8_t> state(scene.materials.size(), 0);
    struct Step {
        uint32_t blend;
        size_t next_part;
    };
    for (const PendingBlend& root : pending) {
        if (state[root.index] != 0) continue;
        std::vector<Step> chain{{root.index, 0}};
        state[root.index] = 1;
        while (!chain.empty()) {
            Step& top = chain.back();
            if (top.next_part == 2) {
                state[top.blend] = 2;
                chain.pop_back();
                continue;
            }
            const size_t k = top.next_part++;
            const uint32_t part = scene.materials[top.blend].blend->parts[k];
            if (!scene.materials[part].blend || state[part] == 2) continue;
            if (state[part] == 1) {
                std::string cycle;
                bool on = false;
                for (const Step& s : chain) {
                    on = on || s.blend == part;
                    if (on) cycle += json_quoted(names[s.blend]) + " -> ";
                }
                pending_of[top.blend]->parts[k].fail(
                    fmt::format("blends form a cycle: {}{}", cycle, json_quoted(names[part])));
            }
            state[part] = 1;
            chain.push_back({part, 0});
        }
    }
}

// The keys every material takes (a mix's, not its parts'): normal_map (an image file, a colour
// texture, or a constant that tilts the normal the same way everywhere), normal_map_convention,
// bump_map, alpha.
SurfaceParams read_surface(JsonCursor& c, Scene& scene) {
    SurfaceParams s;
    std::optional<JsonCursor> normal_map = c.get("normal_map");
    if (normal_map) s.normal_map = read_normal_map_param(*normal_map, scene);
    if (auto v = c.get("normal_map_convention")) {
        if (!normal_map) v->fail("normal_map_convention needs a normal_map");
        s.normal_map_convention = v->choice("normal map convention", kNormalMapConventions) == "directx"
                                      ? NormalMapConvention::kDirectX
                                      : NormalMapConvention::kOpenGl;
    }
    if (auto v = c.get("bump_map")) {
        if (normal_map) v->fail("give \"normal_map\" or \"bump_map\", not both");
        s.bump_map = read_float_param(*v, scene, Bounds{});
    }
    if (auto v = c.get("alpha")) s.alpha = read_float_param(*v, scene, Bounds::closed(0, 1));
    return s;
}

// pbrt-v4's `interface`: no surface, only a boundary between the media of the shapes that use it
// (material.h). It takes no other key: no alpha, no maps.
Material interface_material() {
    Material m = make_material(TransmissionParams{1.0f, ColorParam{Rgb(1.0f)}});
    m.interface = true;
    return m;
}

Material read_material(JsonCursor c, const std::string& name, Scene& scene, std::vector<PendingBlend>& pending) {
    std::string_view type = c.require("type").choice("material type", kMaterialTypes);
    if (type == "interface") {
        c.reject_unknown_keys();
        return interface_material();
    }
    Material material = type == "mix"     ? read_mix(c, scene)
                        : type == "blend" ? read_blend(c, scene, pending)
                        : type == "subsurface" ? read_subsurface(c, scene, name)
                                          : make_material(read_lobe(c, type, scene));
    set_surface(material, read_surface(c, scene));
    c.reject_unknown_keys();
    return material;
}

}  // namespace

RoughnessParams read_roughness(const JsonCursor& c, Scene& scene) {
    if (!c.is_array()) {
        FloatParam alpha = read_float_param(c, scene, kRoughness);
        return {alpha, alpha};
    }
    std::vector<JsonCursor> pair = c.elements(2, "a roughness: a number or [alpha_u, alpha_v]");
    return {read_float_param(pair[0], scene, kRoughness), read_float_param(pair[1], scene, kRoughness)};
}

void read_materials(JsonCursor materials, Scene& scene) {
    std::vector<PendingBlend> pending;
    for (auto& [name, c] : materials.members()) {
        scene.materials.push_back(read_material(c, name, scene, pending));
        scene.material_names.push_back(name);
    }
    resolve_blends(pending, scene);
}

}  // namespace candela
