#pragma once
// Typed access to a pbrt-v4 directive's parameters for the importer: lookups by name with pbrt-v4's
// defaults, type checks with located errors, and the translation of pbrt-v4's colour-valued
// parameters (rgb, spectrum, blackbody, texture) into candela's JSON colour values. Every read
// marks the parameter used; what no one read is reported as a warning (pbrt-v4 stops on it).
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/formats/pbrt/pbrt_location.h"
#include "candela/formats/pbrt/pbrt_parameters.h"
#include "candela/math/vec.h"

namespace candela::pbrt {

using Json = nlohmann::ordered_json;

class Params {
  public:
    // `directive` names the directive in messages ("Shape \"sphere\"").
    Params(ParameterList list, std::string directive, Location at);

    const Location& location() const { return at_; }
    const std::string& directive() const { return directive_; }
    // The parameter `name` (marked used), or null.
    const Parameter* find(std::string_view name) const;
    bool has(std::string_view name) const { return find(name) != nullptr; }

    std::optional<double> get_float(std::string_view name) const;
    double float_or(std::string_view name, double fallback) const { return get_float(name).value_or(fallback); }
    std::optional<long long> get_int(std::string_view name) const;
    long long int_or(std::string_view name, long long fallback) const { return get_int(name).value_or(fallback); }
    bool bool_or(std::string_view name, bool fallback) const;
    std::optional<std::string> get_string(std::string_view name) const;
    std::string string_or(std::string_view name, std::string fallback) const {
        return get_string(name).value_or(std::move(fallback));
    }
    // All the numbers of a numeric parameter (point3 P: 3 per point), checked to be a multiple of
    // `group`; empty when absent.
    std::vector<double> numbers(std::string_view name, size_t group = 1) const;
    std::vector<std::string> strings(std::string_view name) const;
    std::optional<Vec3d> get_point3(std::string_view name) const;

    // A colour-valued parameter as candela's JSON writes it: [r, g, b] for rgb, {"spectrum": ...}
    // for a spectrum (named, or lambda-value pairs), {"spectrum_file": path} for an .spd file,
    // {"blackbody": K} for blackbody, a number for float, {"texture": NAME} for texture (named by
    // `texture_name`, which maps pbrt's spectrum-texture names to the JSON's). Null when absent.
    Json colour(std::string_view name, const std::function<std::string(const Parameter&)>& texture_name) const;
    // A float-valued parameter that may be a texture: a number, or {"texture": NAME}.
    Json number_or_texture(std::string_view name,
                           const std::function<std::string(const Parameter&)>& texture_name) const;

    // For a directive that is skipped as a whole (with its own warning).
    void mark_all_used() const {
        for (const Parameter& p : list_) p.used = true;
    }
    // Calls `warn` once per parameter no lookup read.
    void report_unused(const std::function<void(const Location&, const std::string&)>& warn) const;

    // An error at the parameter (or the directive when null).
    [[noreturn]] void fail(const Parameter* p, const std::string& message) const;

  private:
    ParameterList list_;
    std::string directive_;
    Location at_;
};

// Adds the parameters of `defaults` (an Attribute directive's) that `list` lacks.
void merge_defaults(ParameterList& list, const ParameterList& defaults);

}  // namespace candela::pbrt
