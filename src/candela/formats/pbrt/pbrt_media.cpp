// pbrt-v4's MakeNamedMedium as candela's media (docs/SCENE_FORMAT.md, "media"): homogeneous,
// uniformgrid, rgbgrid, cloud and nanovdb, each with pbrt-v4's parameters (media.cpp, the
// types' Create) under candela's names, and the transformation current at the directive.
// pbrt-v4's checks that stop a render (a missing density, grids of different sizes, Le together
// with temperature) are located errors here.
#include <fmt/format.h>

#include <cmath>

#include "candela/formats/pbrt/pbrt_import_context.h"
#include "candela/media/scattering_presets.h"

namespace candela::pbrt {
namespace {

// A medium's coefficient or emission: a number, [r, g, b], a spectrum or a blackbody, as the
// importer writes colours for materials. A medium cannot read a texture.
Json medium_colour(const Params& p, const char* name) {
    return p.colour(name, [&](const Parameter& t) -> std::string {
        fail(t.location, fmt::format("{}: \"{}\" cannot be a texture", p.directive(), name));
    });
}

void copy_colour(const Params& p, const char* pbrt_name, const char* json_name, Json& m) {
    Json v = medium_colour(p, pbrt_name);
    if (!v.is_null()) m[json_name] = std::move(v);
}

void copy_float(const Params& p, const char* pbrt_name, const char* json_name, Json& m) {
    if (auto v = p.get_float(pbrt_name)) m[json_name] = *v;
}

// sigma_a, sigma_s (default 1 each in pbrt-v4, left to the loader), scale and g.
void coefficients(const Params& p, Json& m, bool with_scale = true) {
    copy_colour(p, "sigma_a", "sigma_a", m);
    copy_colour(p, "sigma_s", "sigma_s", m);
    if (with_scale) copy_float(p, "scale", "scale", m);
    copy_float(p, "g", "g", m);
}

// The grid's bounds in medium space, p0 and p1 (pbrt-v4's default: the unit cube).
void bounds(const Params& p, Json& m) {
    if (auto p0 = p.get_point3("p0")) m["p0"] = vec_json(*p0);
    if (auto p1 = p.get_point3("p1")) m["p1"] = vec_json(*p1);
}

// pbrt-v4 reads temperatureoffset with temperaturecutoff as its default (the older name), then 0:
// one offset, written as such.
void temperature_mapping(const Params& p, Json& m) {
    const std::optional<double> cutoff = p.get_float("temperaturecutoff");
    const std::optional<double> offset = p.get_float("temperatureoffset");
    if (offset || cutoff) m["temperature_offset"] = offset ? *offset : *cutoff;
    copy_float(p, "temperaturescale", "temperature_scale", m);
}

// nx, ny, nz (default 1 each) as "size", checked against the number of values `count`.
Json grid_size(const Params& p, size_t count, const char* what) {
    const long long nx = p.int_or("nx", 1), ny = p.int_or("ny", 1), nz = p.int_or("nz", 1);
    if (nx < 1 || ny < 1 || nz < 1)
        p.fail(p.find(nx < 1   ? "nx"
                      : ny < 1 ? "ny"
                               : "nz"),
               fmt::format("{}: nx, ny and nz must be >= 1", p.directive()));
    const double n = double(nx) * double(ny) * double(nz);
    if (double(count) != n)
        p.fail(nullptr, fmt::format("{}: the grid has {} {} values; expected nx*ny*nz = {}*{}*{} = {}", p.directive(),
                                    count, what, nx, ny, nz, n));
    return Json::array({nx, ny, nz});
}

// A per-voxel float grid ("float density" [...]): pbrt-v4 reads only the float type.
std::vector<double> float_grid(const Params& p, const char* name) {
    const Parameter* g = p.find(name);
    if (!g) return {};
    if (g->type != "float")
        p.fail(g, fmt::format("{}: \"{}\" must be \"float {}\" values, not {}", p.directive(), name, name, g->type));
    return g->numbers;
}

// An RGB grid ("rgb sigma_a" [r g b r g b ...]), 3 numbers a voxel; empty when absent.
std::vector<double> rgb_grid(const Params& p, const char* name) {
    const Parameter* g = p.find(name);
    if (!g) return {};
    if (g->type != "rgb" && g->type != "color")
        p.fail(g, fmt::format("{}: \"{}\" must be \"rgb {}\" values, not {}", p.directive(), name, name, g->type));
    if (g->numbers.empty() || g->numbers.size() % 3 != 0)
        p.fail(g, fmt::format("{}: \"rgb {}\" has {} values, not a positive multiple of 3", p.directive(), name,
                              g->numbers.size()));
    return g->numbers;
}

Json homogeneous(const Params& p, ImportContext& ctx) {
    Json m{{"type", "homogeneous"}};
    // pbrt-v4 reads sigma_a and sigma_s only where the preset is not found (it warns then); with a
    // preset it knows, they are unused parameters (an error in pbrt-v4, a warning here).
    const std::optional<std::string> preset = p.get_string("preset");
    const bool known = preset && find_scattering_preset(*preset);
    if (preset && !preset->empty() && !known)
        ctx.warn(p.find("preset")->location,
                 fmt::format("{}: preset \"{}\" not found (as pbrt-v4 warns); sigma_a and sigma_s are used",
                             p.directive(), *preset));
    if (known) {
        m["preset"] = *preset;
    } else {
        copy_colour(p, "sigma_a", "sigma_a", m);
        copy_colour(p, "sigma_s", "sigma_s", m);
    }
    copy_float(p, "scale", "scale", m);
    copy_float(p, "g", "g", m);
    copy_colour(p, "Le", "Le", m);
    copy_float(p, "Lescale", "Le_scale", m);
    return m;
}

Json uniform_grid(const Params& p) {
    Json m{{"type", "uniformgrid"}};
    const std::vector<double> density = float_grid(p, "density");
    if (density.empty()) p.fail(nullptr, "uniformgrid: no \"float density\" values (pbrt-v4 requires them)");
    const std::vector<double> temperature = float_grid(p, "temperature");
    if (!temperature.empty() && temperature.size() != density.size())
        p.fail(p.find("temperature"), fmt::format("uniformgrid: {} density values but {} temperature values",
                                                  density.size(), temperature.size()));
    m["size"] = grid_size(p, density.size(), "density");
    m["density"] = density;
    bounds(p, m);
    coefficients(p, m);
    if (!temperature.empty()) {
        if (p.has("Le")) p.fail(p.find("Le"), "uniformgrid: both \"Le\" and \"temperature\" are given");
        m["temperature"] = temperature;
    } else {
        copy_colour(p, "Le", "Le", m);
    }
    // Lescale: one value per voxel, always written as an array (pbrt-v4 makes a grid of it; a
    // number would read as a constant, which pbrt-v4's grid lookup is not: see docs/PBRT.md).
    if (const Parameter* s = p.find("Lescale")) {
        const std::vector<double> scale = float_grid(p, "Lescale");
        if (scale.size() != density.size())
            p.fail(s, fmt::format("uniformgrid: \"Lescale\" has {} values; expected one per voxel, {}", scale.size(),
                                  density.size()));
        m["Le_scale"] = scale;
    }
    temperature_mapping(p, m);
    return m;
}

Json rgb_grid_medium(const Params& p) {
    Json m{{"type", "rgbgrid"}};
    const std::vector<double> sigma_a = rgb_grid(p, "sigma_a"), sigma_s = rgb_grid(p, "sigma_s"),
                              Le = rgb_grid(p, "Le");
    if (sigma_a.empty() && sigma_s.empty()) p.fail(nullptr, "rgbgrid: \"rgb sigma_a\" or \"rgb sigma_s\" is required");
    if (!sigma_a.empty() && !sigma_s.empty() && sigma_a.size() != sigma_s.size())
        p.fail(p.find("sigma_s"),
               fmt::format("rgbgrid: sigma_a has {} values, sigma_s {}", sigma_a.size() / 3, sigma_s.size() / 3));
    if (!Le.empty() && sigma_a.empty()) p.fail(p.find("Le"), "rgbgrid: \"Le\" needs \"sigma_a\" (as in pbrt-v4)");
    const size_t n = (sigma_a.empty() ? sigma_s.size() : sigma_a.size()) / 3;
    if (!Le.empty() && Le.size() / 3 != n)
        p.fail(p.find("Le"), fmt::format("rgbgrid: \"Le\" has {} values; expected {}", Le.size() / 3, n));
    m["size"] = grid_size(p, n, "rgb");
    if (!sigma_a.empty()) m["sigma_a"] = sigma_a;
    if (!sigma_s.empty()) m["sigma_s"] = sigma_s;
    if (!Le.empty()) m["Le"] = Le;
    copy_float(p, "Lescale", "Le_scale", m);
    copy_float(p, "scale", "scale", m);
    copy_float(p, "g", "g", m);
    bounds(p, m);
    return m;
}

Json cloud(const Params& p) {
    Json m{{"type", "cloud"}};
    copy_float(p, "density", "density", m);
    copy_float(p, "wispiness", "wispiness", m);
    copy_float(p, "frequency", "frequency", m);
    coefficients(p, m, false);  // pbrt-v4's cloud has no "scale"
    bounds(p, m);
    return m;
}

Json nanovdb(const Params& p) {
    const std::string file = p.string_or("filename", "");
    if (file.empty()) p.fail(p.find("filename"), "nanovdb: \"string filename\" is required");
    Json m{{"type", "nanovdb"}, {"file", file}};
    if (auto name = p.get_string("gridname")) m["grid_name"] = *name;
    if (auto name = p.get_string("temperaturename")) m["temperature_name"] = *name;
    copy_float(p, "Lescale", "Le_scale", m);
    temperature_mapping(p, m);
    coefficients(p, m);
    return m;
}

}  // namespace

void translate_medium(const std::string& name, const Params& p, const Transform& to_world, ImportContext& ctx) {
    const std::string type = p.string_or("type", "");
    if (type.empty()) p.fail(nullptr, fmt::format("MakeNamedMedium \"{}\": \"string type\" is required", name));
    Json m;
    if (type == "homogeneous") {
        m = homogeneous(p, ctx);
    } else if (type == "uniformgrid") {
        m = uniform_grid(p);
    } else if (type == "rgbgrid") {
        m = rgb_grid_medium(p);
    } else if (type == "cloud") {
        m = cloud(p);
    } else if (type == "nanovdb") {
        m = nanovdb(p);
    } else {
        p.fail(p.find("type"), fmt::format("MakeNamedMedium \"{}\": unknown medium type \"{}\"; pbrt-v4's are "
                                           "homogeneous, uniformgrid, rgbgrid, cloud and nanovdb",
                                           name, type));
    }
    // The medium's space: the transformation current at MakeNamedMedium (pbrt-v4's
    // renderFromMedium). A homogeneous medium has no use for it, but has it all the same.
    if (!to_world.is_identity()) m["transform"] = transform_json(to_world);
    ctx.doc()["media"][name] = std::move(m);
    ctx.origin("/media/" + pointer_token(name), p.location());
}

}  // namespace candela::pbrt
