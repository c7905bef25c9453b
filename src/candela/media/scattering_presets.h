#pragma once
// pbrt-v4's named media (`"preset"` of a homogeneous medium: pbrt-v4's
// GetMediumScatteringProperties): measured scattering and absorption coefficients, RGB, per mm.
// Data from Jensen, Marschner, Levoy and Hanrahan, "A Practical Model for Subsurface Light
// Transport" (SIGGRAPH 2001), and Narasimhan, Gupta, Donner, Ramamoorthi, Nayar and Jensen,
// "Acquiring Scattering Properties of Participating Media by Dilution" (SIGGRAPH 2006), as
// pbrt-v4 tabulates them (src/pbrt/media.cpp).
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "candela/math/rgb.h"

namespace candela {

struct ScatteringPreset {
    std::string_view name;
    Rgb sigma_s;  // the reduced scattering coefficient sigma_s', which pbrt-v4 uses as sigma_s
    Rgb sigma_a;
};

// The preset of that name (pbrt-v4's spelling, e.g. "Wholemilk", "Regular Milk"), or nullopt.
std::optional<ScatteringPreset> find_scattering_preset(std::string_view name);
std::span<const ScatteringPreset> scattering_presets();
// Their names, in the table's order (for the message that lists them).
std::vector<std::string_view> scattering_preset_names();

}  // namespace candela
