#pragma once
// A colour value written as a spectrum (DESIGN: "Colour: RGB and spectral transport";
// docs/SCENE_FORMAT.md, "Spectra"). The four forms are JSON objects of one key:
//   {"spectrum": "metal-Au-eta"}             a named spectrum, pbrt-v4's names (named_spectra.h)
//   {"spectrum": [400, 0.1, 500, 0.4, ...]}  (nm, value) pairs, piecewise linear
//   {"spectrum_file": "Au.eta.spd"}          a pbrt-v4 .spd file of (nm, value) pairs
//   {"blackbody": 3200}                      a blackbody of that many kelvin, peak 1
// Internal to scene/: the materials and lights readers call it before reading an RGB colour.
#include <filesystem>
#include <optional>

#include "candela/scene/json_cursor.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// The spectrum `c` gives in one of the four forms, or nullopt when `c` is anything else (a
// number, an array, an object without those keys), so the caller reads it as RGB. A spectrum
// file is found relative to `scene_dir`. Values are any finite floats: the caller checks their
// range. Throws SceneError for a form written wrong: located at the value in the scene file, or
// at file:line in a spectrum file (with the scene location that names the file).
std::optional<DenseSpectrum> read_spectrum(const JsonCursor& c, const std::filesystem::path& scene_dir);

}  // namespace candela
