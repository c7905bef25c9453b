#pragma once
// Spectra by name, as pbrt-v4 names them (its GetNamedSpectrum): measured metals
// ("metal-Au-eta", "metal-Au-k", ...), glasses ("glass-BK7", ...) and standard illuminants
// ("stdillum-D65", ...). The data is pbrt-v4's (named_spectra_data.cpp, sources named there),
// resampled once into dense 1-nm tables. Illuminants are scaled to luminance Y = 1, as pbrt-v4
// scales them; metals and glasses are the measured values.
#include <span>
#include <string_view>

#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// The spectrum called `name`, or nullptr if there is none. The pointer stays valid for the
// program's life; "stdillum-D65" is d65_illuminant() itself.
const DenseSpectrum* named_spectrum(std::string_view name);

// Every name named_spectrum knows, metals, glasses, then illuminants (for error messages).
std::span<const std::string_view> named_spectrum_names();

}  // namespace candela
