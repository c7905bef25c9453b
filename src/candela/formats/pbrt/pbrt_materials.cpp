// pbrt-v4's textures and materials as candela's (docs/SCENE_FORMAT.md, "textures" and
// "materials"), with pbrt-v4's defaults and parameter names. Roughness: pbrt-v4 remaps it to the
// microfacet alpha with sqrt (remaproughness, true by default); candela's roughness is alpha.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "candela/formats/pbrt/pbrt_import_context.h"

namespace candela::pbrt {
namespace {

auto spectrum_textures(const ImportContext& ctx) {
    return [&ctx](const Parameter& p) { return ctx.texture_reference(p, false); };
}
auto float_textures(const ImportContext& ctx) {
    return [&ctx](const Parameter& p) { return ctx.texture_reference(p, true); };
}

// A texture input: a colour or texture for a spectrum texture, a number or texture for a float.
Json texture_input(const Params& p, const std::string& name, bool is_float, const Json& fallback,
                   const ImportContext& ctx) {
    Json v = is_float ? p.number_or_texture(name, float_textures(ctx)) : p.colour(name, spectrum_textures(ctx));
    return v.is_null() ? fallback : v;
}

// pbrt-v4's (u, v) mapping: (su u + du, sv v + dv). Other mappings are warned about.
void read_uv_mapping(const Params& p, Json& t, ImportContext& ctx) {
    const std::string mapping = p.string_or("mapping", "uv");
    if (mapping != "uv")
        ctx.warn(p.find("mapping")->location,
                 fmt::format("{}: mapping \"{}\" is not supported; the surface's (u, v) is used", p.directive(), mapping));
    const double su = p.float_or("uscale", 1), sv = p.float_or("vscale", 1);
    const double du = p.float_or("udelta", 0), dv = p.float_or("vdelta", 0);
    if (su != 1 || sv != 1) t["uv_scale"] = Json::array({su, sv});
    if (du != 0 || dv != 0) t["uv_offset"] = Json::array({du, dv});
    for (const char* unused : {"v1", "v2"})
        if (p.has(unused)) ctx.warn(p.find(unused)->location, fmt::format("{}: \"{}\" (planar mapping) is ignored", p.directive(), unused));
}

bool is_8bit_image(const std::string& file) {
    std::string ext = file.substr(file.find_last_of('.') + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "tga" || ext == "bmp";
}

Json image_texture(const Params& p, ImportContext& ctx) {
    const std::string file = p.string_or("filename", "");
    if (file.empty()) p.fail(nullptr, fmt::format("{}: \"string filename\" is required", p.directive()));
    Json t{{"type", "image"}, {"file", file}};
    const std::string filter = p.string_or("filter", "bilinear");
    if (filter == "point") {
        t["filter"] = "point";
    } else if (filter != "bilinear") {
        // candela has no mipmaps: a texture much finer than the pixels averages out over samples.
        ctx.warn(p.find("filter")->location,
                 fmt::format("{}: filter \"{}\" is rendered as bilinear (candela has no mipmaps)", p.directive(), filter));
    }
    p.float_or("maxanisotropy", 8);
    const std::string wrap = p.string_or("wrap", "repeat");
    if (wrap == "repeat" || wrap == "black" || wrap == "clamp") {
        t["wrap"] = wrap;
    } else {
        ctx.warn(p.find("wrap")->location, fmt::format("{}: wrap \"{}\" is rendered as repeat", p.directive(), wrap));
    }
    const std::string encoding = p.string_or("encoding", is_8bit_image(file) ? "sRGB" : "linear");
    if (is_8bit_image(file)) {
        if (encoding == "linear") {
            t["colorspace"] = "linear";
        } else if (encoding.rfind("gamma ", 0) == 0) {
            t["colorspace"] = "gamma";
            t["gamma"] = std::atof(encoding.c_str() + 6);
        } else if (encoding != "sRGB") {
            p.fail(p.find("encoding"), fmt::format("unknown encoding \"{}\"; expected sRGB, linear or \"gamma G\"", encoding));
        }
    }
    if (const double s = p.float_or("scale", 1); s != 1) t["scale"] = s;
    if (p.bool_or("invert", false)) t["invert"] = true;
    read_uv_mapping(p, t, ctx);
    return t;
}

}  // namespace

void translate_texture(const std::string& name, const std::string& value_type, const std::string& type,
                       const Params& p, const Transform& to_world, ImportContext& ctx) {
    if (value_type != "float" && value_type != "spectrum")
        p.fail(nullptr, fmt::format("Texture \"{}\": the value type must be \"float\" or \"spectrum\", not \"{}\"", name,
                                    value_type));
    const bool is_float = value_type == "float";
    const Json one = is_float ? Json(1.0) : Json(1.0), zero = Json(0.0);
    Json t;
    if (type == "imagemap") {
        t = image_texture(p, ctx);
    } else if (type == "constant") {
        t = Json{{"type", "constant"}, {"value", texture_input(p, "value", is_float, one, ctx)}};
    } else if (type == "scale") {
        t = Json{{"type", "scale"},
                 {"tex", texture_input(p, "tex", is_float, one, ctx)},
                 {"scale", texture_input(p, "scale", true, one, ctx)}};
    } else if (type == "mix") {
        t = Json{{"type", "mix"},
                 {"tex1", texture_input(p, "tex1", is_float, zero, ctx)},
                 {"tex2", texture_input(p, "tex2", is_float, one, ctx)},
                 {"amount", texture_input(p, "amount", true, Json(0.5), ctx)}};
    } else if (type == "checkerboard") {
        const long long dimension = p.int_or("dimension", 2);
        if (dimension != 2 && dimension != 3) p.fail(p.find("dimension"), "checkerboard: dimension must be 2 or 3");
        t = Json{{"type", "checkerboard"},
                 {"color0", texture_input(p, "tex1", is_float, one, ctx)},
                 {"color1", texture_input(p, "tex2", is_float, zero, ctx)}};
        if (dimension == 3) {
            // A solid checkerboard in the texture's space: the transform at the Texture directive.
            t["dimension"] = 3;
            if (!to_world.is_identity()) t["transform"] = transform_json(to_world);
        } else {
            read_uv_mapping(p, t, ctx);
        }
    } else if (type == "bilerp") {
        t = Json{{"type", "bilerp"},
                 {"v00", texture_input(p, "v00", is_float, zero, ctx)},
                 {"v01", texture_input(p, "v01", is_float, one, ctx)},
                 {"v10", texture_input(p, "v10", is_float, zero, ctx)},
                 {"v11", texture_input(p, "v11", is_float, one, ctx)}};
        for (const char* v : {"v00", "v01", "v10", "v11"})
            if (t[v].is_object()) p.fail(p.find(v), "bilerp: the corner values must be constants, not textures");
        read_uv_mapping(p, t, ctx);
    } else if (type == "directionmix") {
        const Vec3d dir = to_world.apply_vector(p.get_point3("dir").value_or(Vec3d(0, 1, 0)));
        if (!(length(dir) > 0)) p.fail(p.find("dir"), "directionmix: dir must be nonzero");
        t = Json{{"type", "directionmix"},
                 {"tex1", texture_input(p, "tex1", is_float, zero, ctx)},
                 {"tex2", texture_input(p, "tex2", is_float, one, ctx)},
                 {"dir", Json::array({dir.x, dir.y, dir.z})}};
    } else {
        ctx.warn(p.location(), fmt::format("Texture class \"{}\" is not supported; a constant 0.5 stands in", type));
        t = Json{{"type", "constant"}, {"value", 0.5}};
    }
    const std::string json_name = ctx.define_texture_name(name, is_float);
    ctx.doc()["textures"][json_name] = t;
    ctx.origin("/textures/" + json_name, p.location());
}

namespace {

// pbrt-v4's roughness pair (roughness, or uroughness / vroughness) as candela's alpha: remapped
// with sqrt unless remaproughness is false (TrowbridgeReitzDistribution::RoughnessToAlpha).
Json roughness(const Params& p, const std::string& prefix, ImportContext& ctx) {
    const auto textures = float_textures(ctx);
    Json r = p.number_or_texture(prefix + "roughness", textures);
    Json u = p.number_or_texture(prefix + "uroughness", textures);
    Json v = p.number_or_texture(prefix + "vroughness", textures);
    if (u.is_null()) u = r.is_null() ? Json(0.0) : r;
    if (v.is_null()) v = r.is_null() ? Json(0.0) : r;
    const bool remap = p.bool_or("remaproughness", true);
    auto to_alpha = [&](const Json& x) -> Json {
        if (!x.is_number()) {
            if (remap)
                ctx.warn(p.location(), fmt::format("{}: a roughness texture is used as alpha without pbrt-v4's remapping "
                                                   "(set remaproughness false to silence this)",
                                                   p.directive()));
            return x;
        }
        const double value = x.get<double>();
        if (value < 0) p.fail(p.find(prefix + "roughness"), "roughness must be >= 0");
        return remap ? std::sqrt(value) : value;
    };
    Json au = to_alpha(u), av = to_alpha(v);
    if (au == av) return au;
    return Json::array({au, av});
}

// eta as candela's ior: a number or a spectrum (a float texture cannot be an index here).
Json ior(const Params& p, const std::string& name, double fallback, ImportContext& ctx) {
    const Parameter* e = p.find(name);
    if (!e) return fallback;
    if (e->type == "texture") {
        ctx.warn(e->location, fmt::format("{}: a textured \"{}\" is not supported; {} is used", p.directive(), name, fallback));
        return fallback;
    }
    Json v = p.colour(name, spectrum_textures(ctx));
    // pbrt-v4: an eta of 0 means 1 (an index-matched interface).
    if (v.is_number() && v.get<double>() == 0) return 1.0;
    return v;
}

void surface_keys(const Params& p, Json& m, ImportContext& ctx) {
    if (auto file = p.get_string("normalmap")) m["normal_map"] = *file;
    if (const Parameter* d = p.find("displacement")) {
        if (m.contains("normal_map")) {
            ctx.warn(d->location, "displacement together with normalmap: the displacement is ignored");
        } else {
            m["bump_map"] = p.number_or_texture("displacement", float_textures(ctx));
        }
    }
}

Json conductor(const Params& p, const std::string& prefix, Json& m, ImportContext& ctx, const char* eta_key,
               const char* k_key) {
    Json reflectance = p.colour("reflectance", spectrum_textures(ctx));
    Json eta = p.colour(prefix + "eta", spectrum_textures(ctx));
    Json k = p.colour(prefix + "k", spectrum_textures(ctx));
    if (!reflectance.is_null()) {
        if (!eta.is_null() || !k.is_null())
            ctx.warn(p.location(), fmt::format("{}: reflectance is given, so eta and k are ignored (as in pbrt-v4)", p.directive()));
        m["reflectance"] = reflectance;
    } else {
        m[eta_key] = eta.is_null() ? Json{{"spectrum", "metal-Cu-eta"}} : eta;
        m[k_key] = k.is_null() ? Json{{"spectrum", "metal-Cu-k"}} : k;
    }
    return m;
}

void layered_keys(const Params& p, Json& m, ImportContext& ctx) {
    const auto textures = float_textures(ctx);
    Json thickness = p.number_or_texture("thickness", textures);
    if (!thickness.is_null()) m["thickness"] = thickness;
    Json albedo = p.colour("albedo", spectrum_textures(ctx));
    if (!albedo.is_null()) m["medium_albedo"] = albedo;
    Json g = p.number_or_texture("g", textures);
    if (!g.is_null()) m["g"] = g;
    if (auto d = p.get_int("maxdepth")) m["maxdepth"] = *d;
    if (auto n = p.get_int("nsamples")) m["nsamples"] = *n;
    // Render as pbrt-v4 renders: its LayeredBxDF's weights (layered.h says where they differ).
    m["pbrt_v4_weights"] = true;
}

// pbrt-v4's hair: sigma_a, else reflectance (or its older name color), else the melanin
// concentrations, each ignored with a warning when an earlier one is given, as pbrt-v4 does.
// candela takes the concentrations as numbers: a texture warns and its default is used.
void hair_keys(const Params& p, Json& m, ImportContext& ctx) {
    const auto colours = spectrum_textures(ctx);
    const auto numbers = float_textures(ctx);
    Json sigma_a = p.colour("sigma_a", colours);
    Json reflectance = p.colour("reflectance", colours);
    if (reflectance.is_null()) reflectance = p.colour("color", colours);
    std::optional<double> melanin[2];
    const char* melanin_keys[2] = {"eumelanin", "pheomelanin"};
    for (int i = 0; i < 2; ++i) {
        const Parameter* e = p.find(melanin_keys[i]);
        if (!e) continue;
        Json v = p.number_or_texture(melanin_keys[i], numbers);
        if (v.is_number()) {
            melanin[i] = std::max(0.0, v.get<double>());  // pbrt-v4 clamps at 0
        } else {
            ctx.warn(e->location, fmt::format("{}: a textured \"{}\" is not supported; 0 is used", p.directive(),
                                              melanin_keys[i]));
            melanin[i] = 0.0;
        }
    }
    const bool has_melanin = melanin[0] || melanin[1];
    auto ignored = [&](const char* key, const char* because) {
        ctx.warn(p.location(), fmt::format("{}: \"{}\" is ignored since \"{}\" is given (as in pbrt-v4)", p.directive(),
                                           key, because));
    };
    if (!sigma_a.is_null()) {
        if (!reflectance.is_null()) ignored("reflectance", "sigma_a");
        if (has_melanin) ignored("eumelanin/pheomelanin", "sigma_a");
        m["sigma_a"] = sigma_a;
    } else if (!reflectance.is_null()) {
        if (has_melanin) ignored("eumelanin/pheomelanin", "reflectance");
        m["reflectance"] = reflectance;
    } else if (has_melanin) {
        // pbrt-v4: a concentration not given is 0 when the other is.
        m["eumelanin"] = melanin[0].value_or(0.0);
        m["pheomelanin"] = melanin[1].value_or(0.0);
    }
    for (const char* key : {"eta", "beta_m", "beta_n", "alpha"}) {
        Json v = p.number_or_texture(key, numbers);
        if (v.is_null()) continue;
        // pbrt-v4 clamps beta_m and beta_n into [0.01, 1] where candela's file refuses them.
        if (v.is_number() && (std::string_view(key) == "beta_m" || std::string_view(key) == "beta_n"))
            v = std::clamp(v.get<double>(), 0.01, 1.0);
        // pbrt-v4's `alpha` (the scales' angle) is candela's scale_angle: a material's alpha is its coverage.
        m[std::string_view(key) == "alpha" ? "scale_angle" : key] = v;
    }
}

// pbrt-v4's SubsurfaceMaterial::Create: the interior by `name`, by sigma_a and sigma_s, by
// reflectance (and mfp), or its defaults; scale, eta (candela's ior), g, and the dielectric
// boundary's roughness. The JSON loader checks the values (one located line for each error).
void subsurface_keys(const Params& p, Json& m, ImportContext& ctx) {
    const auto colours = spectrum_textures(ctx);
    const auto numbers = float_textures(ctx);
    const std::string name = p.string_or("name", "");
    std::optional<double> g;
    if (const Parameter* e = p.find("g")) {
        Json v = p.number_or_texture("g", numbers);
        if (!v.is_number()) p.fail(e, "subsurface: \"g\" must be a number");
        g = v.get<double>();
    }
    if (!name.empty()) {
        m["name"] = name;
        // pbrt-v4: the measured media give reduced coefficients; their g is 0.
        if (g && *g != 0)
            ctx.warn(p.find("g")->location, "subsurface: non-zero \"g\" ignored with named scattering coefficients");
        g.reset();
    } else {
        Json sigma_a = p.colour("sigma_a", colours), sigma_s = p.colour("sigma_s", colours);
        if (!sigma_a.is_null() && sigma_s.is_null())
            p.fail(p.find("sigma_a"), "subsurface: provided \"sigma_a\" parameter without \"sigma_s\"");
        if (sigma_a.is_null() && !sigma_s.is_null())
            p.fail(p.find("sigma_s"), "subsurface: provided \"sigma_s\" parameter without \"sigma_a\"");
        if (!sigma_a.is_null()) {
            m["sigma_a"] = sigma_a;
            m["sigma_s"] = sigma_s;
        } else if (Json r = p.colour("reflectance", colours); !r.is_null()) {
            m["reflectance"] = r;
            if (Json mfp = p.colour("mfp", colours); !mfp.is_null()) m["mfp"] = mfp;
        }
    }
    if (g) m["g"] = *g;
    if (const double scale = p.float_or("scale", 1.0); scale != 1) m["scale"] = scale;
    m["ior"] = p.float_or("eta", 1.33);
    Json r = roughness(p, "", ctx);
    if (r != Json(0.0)) m["roughness"] = r;
}

}  // namespace

std::string translate_material(const std::string& wanted_name, const std::string& type, const Params& p,
                               ImportContext& ctx) {
    const auto colours = spectrum_textures(ctx);
    Json m;
    if (type == "diffuse") {
        Json r = p.colour("reflectance", colours);
        m = Json{{"type", "diffuse"}, {"albedo", r.is_null() ? Json(0.5) : r}};
    } else if (type == "coateddiffuse") {
        Json r = p.colour("reflectance", colours);
        m = Json{{"type", "coated_diffuse"}, {"albedo", r.is_null() ? Json(0.5) : r}};
        m["roughness"] = roughness(p, "", ctx);
        m["ior"] = ior(p, "eta", 1.5, ctx);
        layered_keys(p, m, ctx);
    } else if (type == "coatedconductor") {
        m = Json{{"type", "coated_conductor"}};
        m["interface_roughness"] = roughness(p, "interface.", ctx);
        m["ior"] = ior(p, "interface.eta", 1.5, ctx);
        m["conductor_roughness"] = roughness(p, "conductor.", ctx);
        conductor(p, "conductor.", m, ctx, "conductor_eta", "conductor_k");
        layered_keys(p, m, ctx);
    } else if (type == "conductor") {
        m = Json{{"type", "conductor"}};
        conductor(p, "", m, ctx, "eta", "k");
        m["roughness"] = roughness(p, "", ctx);
    } else if (type == "dielectric") {
        m = Json{{"type", "dielectric"}, {"ior", ior(p, "eta", 1.5, ctx)}};
        Json r = roughness(p, "", ctx);
        if (r != Json(0.0)) m["roughness"] = r;
    } else if (type == "diffusetransmission") {
        // pbrt-v4's DiffuseTransmissionMaterial: R and T (0.25 each by default) times `scale`.
        Json r = p.colour("reflectance", colours), t = p.colour("transmittance", colours);
        m = Json{{"type", "diffuse_transmission"},
                 {"reflectance", r.is_null() ? Json(0.25) : r},
                 {"transmittance", t.is_null() ? Json(0.25) : t}};
        const double scale = p.float_or("scale", 1.0);
        if (!(scale >= 0)) p.fail(p.find("scale"), "diffusetransmission: scale must be >= 0");
        if (scale != 1) m["scale"] = scale;
    } else if (type == "thindielectric") {
        m = Json{{"type", "thin_dielectric"}, {"ior", ior(p, "eta", 1.5, ctx)}};
    } else if (type == "mix") {
        std::vector<std::string> parts = p.strings("materials");
        if (parts.size() != 2) p.fail(p.find("materials"), "mix: \"string materials\" must name two materials");
        Json names = Json::array();
        for (const std::string& part : parts) {
            auto it = ctx.named_materials().find(part);
            if (it == ctx.named_materials().end())
                p.fail(p.find("materials"), fmt::format("mix: no material named \"{}\"", part));
            names.push_back(it->second);
        }
        Json amount = p.number_or_texture("amount", float_textures(ctx));
        m = Json{{"type", "blend"}, {"materials", names}, {"amount", amount.is_null() ? Json(0.5) : amount}};
    } else if (type == "hair") {
        m = Json{{"type", "hair"}};
        hair_keys(p, m, ctx);
    } else if (type == "interface" || type == "" || type == "none") {
        // pbrt-v4 makes no material of these three: a boundary between media only, which rays
        // cross unchanged (and no surface to carry an area light).
        m = Json{{"type", "interface"}};
    } else if (type == "subsurface") {
        m = Json{{"type", "subsurface"}};
        subsurface_keys(p, m, ctx);
    } else {
        // measured: a diffuse stand-in of its colour.
        Json r = p.colour("reflectance", colours);
        ctx.warn(p.location(), fmt::format("Material \"{}\" is not supported; a diffuse material of {} stands in", type,
                                           r.is_null() ? "reflectance 0.5" : "its reflectance"));
        m = Json{{"type", "diffuse"}, {"albedo", r.is_null() ? Json(0.5) : r}};
    }
    p.string_or("type", "");
    if (m["type"] != "blend" && m["type"] != "interface") surface_keys(p, m, ctx);
    const std::string name = ctx.new_material_name(wanted_name);
    ctx.doc()["materials"][name] = m;
    ctx.origin("/materials/" + name, p.location());
    return name;
}

std::string material_with_alpha(const std::string& name, const Json& alpha, ImportContext& ctx) {
    // On a blend (pbrt's mix) the alpha goes on the blend itself: pbrt-v4's alpha is the shape's.
    Json m = ctx.doc()["materials"][name];
    m["alpha"] = alpha;
    const std::string copy = ctx.new_material_name(name + " (alpha)");
    ctx.doc()["materials"][copy] = m;
    return copy;
}

}  // namespace candela::pbrt
