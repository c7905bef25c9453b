#include "candela/formats/pbrt/pbrt_params.h"

#include <fmt/format.h>

#include <cmath>

#include "candela/spectrum/named_spectra.h"

namespace candela::pbrt {
namespace {

bool is_numeric_type(std::string_view t) {
    return t == "float" || t == "integer" || t == "point2" || t == "vector2" || t == "point3" || t == "vector3" ||
           t == "normal" || t == "normal3" || t == "point" || t == "vector" || t == "rgb" || t == "color" ||
           t == "blackbody";
}

}  // namespace

Params::Params(ParameterList list, std::string directive, Location at)
    : list_(std::move(list)), directive_(std::move(directive)), at_(std::move(at)) {}

const Parameter* Params::find(std::string_view name) const {
    // pbrt-v4 takes the first of two parameters with the same name.
    for (const Parameter& p : list_)
        if (p.name == name) {
            p.used = true;
            return &p;
        }
    return nullptr;
}

void Params::fail(const Parameter* p, const std::string& message) const {
    pbrt::fail(p ? p->location : at_, message);
}

std::optional<double> Params::get_float(std::string_view name) const {
    const Parameter* p = find(name);
    if (!p) return std::nullopt;
    if (p->type != "float" && p->type != "integer")
        fail(p, fmt::format("{}: parameter \"{}\" must be a float, not {}", directive_, name, p->type));
    if (p->numbers.size() != 1)
        fail(p, fmt::format("{}: parameter \"{}\" takes one value, got {}", directive_, name, p->numbers.size()));
    return p->numbers[0];
}

std::optional<long long> Params::get_int(std::string_view name) const {
    const Parameter* p = find(name);
    if (!p) return std::nullopt;
    if (p->type != "integer")
        fail(p, fmt::format("{}: parameter \"{}\" must be an integer, not {}", directive_, name, p->type));
    if (p->numbers.size() != 1)
        fail(p, fmt::format("{}: parameter \"{}\" takes one value, got {}", directive_, name, p->numbers.size()));
    const double v = p->numbers[0];
    if (!(std::fabs(v) < 9.0e15)) fail(p, fmt::format("{}: integer \"{}\" is out of range", directive_, name));
    return static_cast<long long>(v);
}

bool Params::bool_or(std::string_view name, bool fallback) const {
    const Parameter* p = find(name);
    if (!p) return fallback;
    if (p->type != "bool")
        fail(p, fmt::format("{}: parameter \"{}\" must be a bool, not {}", directive_, name, p->type));
    if (p->bools.size() != 1)
        fail(p, fmt::format("{}: parameter \"{}\" takes one value, got {}", directive_, name, p->bools.size()));
    return p->bools[0] != 0;
}

std::optional<std::string> Params::get_string(std::string_view name) const {
    const Parameter* p = find(name);
    if (!p) return std::nullopt;
    if (p->type != "string")
        fail(p, fmt::format("{}: parameter \"{}\" must be a string, not {}", directive_, name, p->type));
    if (p->strings.size() != 1)
        fail(p, fmt::format("{}: parameter \"{}\" takes one string, got {}", directive_, name, p->strings.size()));
    return p->strings[0];
}

std::vector<std::string> Params::strings(std::string_view name) const {
    const Parameter* p = find(name);
    if (!p) return {};
    if (p->type != "string")
        fail(p, fmt::format("{}: parameter \"{}\" must be strings, not {}", directive_, name, p->type));
    return p->strings;
}

std::vector<double> Params::numbers(std::string_view name, size_t group) const {
    const Parameter* p = find(name);
    if (!p) return {};
    if (!is_numeric_type(p->type) || p->type == "blackbody")
        fail(p, fmt::format("{}: parameter \"{}\" must be numbers, not {}", directive_, name, p->type));
    if (p->numbers.size() % group != 0)
        fail(p, fmt::format("{}: parameter \"{}\" has {} values, not a multiple of {}", directive_, name,
                            p->numbers.size(), group));
    return p->numbers;
}

std::optional<Vec3d> Params::get_point3(std::string_view name) const {
    const Parameter* p = find(name);
    if (!p) return std::nullopt;
    if (p->numbers.size() != 3 || !is_numeric_type(p->type))
        fail(p, fmt::format("{}: parameter \"{}\" must be one point3 (3 numbers)", directive_, name));
    return Vec3d(p->numbers[0], p->numbers[1], p->numbers[2]);
}

Json Params::colour(std::string_view name, const std::function<std::string(const Parameter&)>& texture_name) const {
    const Parameter* p = find(name);
    if (!p) return nullptr;
    const std::string& t = p->type;
    if (t == "rgb" || t == "color") {
        if (p->numbers.size() != 3)
            fail(p, fmt::format("{}: rgb \"{}\" takes 3 values, got {}", directive_, name, p->numbers.size()));
        return Json::array({p->numbers[0], p->numbers[1], p->numbers[2]});
    }
    if (t == "float" || t == "integer") {
        if (p->numbers.size() != 1)
            fail(p, fmt::format("{}: parameter \"{}\" takes one value, got {}", directive_, name, p->numbers.size()));
        return p->numbers[0];
    }
    if (t == "blackbody") {
        if (p->numbers.size() != 1)
            fail(p, fmt::format("{}: blackbody \"{}\" takes one temperature, got {} values", directive_, name,
                                p->numbers.size()));
        return Json{{"blackbody", p->numbers[0]}};
    }
    if (t == "spectrum") {
        if (!p->strings.empty()) {
            if (p->strings.size() != 1)
                fail(p, fmt::format("{}: spectrum \"{}\" takes one name or file", directive_, name));
            const std::string& s = p->strings[0];
            if (named_spectrum(s)) return Json{{"spectrum", s}};
            return Json{{"spectrum_file", s}};
        }
        if (p->numbers.size() < 4 || p->numbers.size() % 2 != 0)
            fail(p, fmt::format("{}: spectrum \"{}\" takes (wavelength, value) pairs, at least two", directive_, name));
        return Json{{"spectrum", p->numbers}};
    }
    if (t == "texture") {
        if (p->strings.size() != 1)
            fail(p, fmt::format("{}: texture \"{}\" takes one texture name", directive_, name));
        return Json{{"texture", texture_name(*p)}};
    }
    fail(p, fmt::format("{}: parameter \"{}\" must be a colour (rgb, spectrum, blackbody, float or texture), not {}",
                        directive_, name, t));
}

Json Params::number_or_texture(std::string_view name,
                               const std::function<std::string(const Parameter&)>& texture_name) const {
    const Parameter* p = find(name);
    if (!p) return nullptr;
    if (p->type == "texture") {
        if (p->strings.size() != 1) fail(p, fmt::format("{}: texture \"{}\" takes one texture name", directive_, name));
        return Json{{"texture", texture_name(*p)}};
    }
    return *get_float(name);
}

void Params::report_unused(const std::function<void(const Location&, const std::string&)>& warn) const {
    for (const Parameter& p : list_)
        if (!p.used)
            warn(p.location, fmt::format("{}: parameter \"{} {}\" is not used (candela does not support it, or "
                                         "pbrt-v4 does not know it here)",
                                         directive_, p.type, p.name));
}

void merge_defaults(ParameterList& list, const ParameterList& defaults) {
    for (const Parameter& d : defaults) {
        bool present = false;
        for (const Parameter& p : list) present = present || p.name == d.name;
        // A default nobody reads is not reported (pbrt-v4 reports only the directive's own).
        if (!present) {
            list.push_back(d);
            list.back().used = true;
        }
    }
}

}  // namespace candela::pbrt
