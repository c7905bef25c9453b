#pragma once
// The colour of a spectrum, as the uplifting tests compute it: the spectrum sampled at every nm
// from 360 to 830 (DenseSpectrum), its CIE XYZ (dense_spectrum.h), then linear sRGB.
#include <algorithm>
#include <cmath>

#include "candela/math/rgb.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela::test {

// sRGB of the light a spectrum emits: its own XYZ.
template <class F>
Rgb emission_rgb(const F& spectrum) {
    DenseSpectrum s;
    for (int i = 0; i < kDenseSamples; ++i) s.v[size_t(i)] = spectrum(float(kDenseLambdaMin + i));
    return xyz_to_linear_srgb(spectrum_to_xyz(s));
}

// sRGB of a reflectance lit by D65 (luminance 1, the sRGB white).
template <class F>
Rgb reflectance_rgb(const F& reflectance) {
    const DenseSpectrum& d65 = d65_illuminant();
    return emission_rgb([&](float lambda) { return reflectance(lambda) * d65(lambda); });
}

inline float largest_difference(const Rgb& a, const Rgb& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

}  // namespace candela::test
