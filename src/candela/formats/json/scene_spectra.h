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

#include "candela/math/rgb.h"
#include "candela/formats/json/json_cursor.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// The spectrum `c` gives in one of the four forms, or nullopt when `c` is anything else (a
// number, an array, an object without those keys), so the caller reads it as RGB. A spectrum
// file is found relative to `scene_dir`. Values are any finite floats: the caller checks their
// range. Throws SceneError for a form written wrong: located at the value in the scene file, or
// at file:line in a spectrum file (with the scene location that names the file).
std::optional<DenseSpectrum> read_spectrum(const JsonCursor& c, const std::filesystem::path& scene_dir);

// A light's colour given as a spectrum, as pbrt-v4 takes it (lights.cpp: `scale /=
// SpectrumToPhotometric(L)`): normalized to luminance Y = 1, so that the light's scale or power
// alone sets its brightness and the spectrum only its colour.
struct LightSpectrum {
    DenseSpectrum normalized;  // Y = 1; all 0 when the spectrum has no luminance
    // RGB mode's colour: the linear sRGB of `normalized` (emission_rgb), a colour outside the
    // sRGB gamut clipped to 0 per channel (a negative emission has no meaning in RGB transport).
    // Black exactly when the spectrum has no luminance.
    Rgb rgb;
};

// read_spectrum for a light's colour: nullopt when `c` is no spectrum (the caller reads RGB).
// Every value must be >= 0 (a located SceneError otherwise).
std::optional<LightSpectrum> read_light_spectrum(const JsonCursor& c, const std::filesystem::path& scene_dir);

}  // namespace candela
