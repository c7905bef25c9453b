#pragma once
// The round trip of the uplifting tests: a spectrum sampled at every nm from 360 to 830
// (DenseSpectrum), then linear sRGB: of a reflectance under D65 (spectrum_rgb.h's
// reflectance_rgb), or of an emission's own XYZ (not normalized to luminance 1 as
// spectrum_rgb.h's emission_rgb is: the emission's brightness is part of its colour here).
#include <algorithm>
#include <cmath>

#include "candela/math/rgb.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela::test {

template <class F>
DenseSpectrum sampled(const F& spectrum) {
    DenseSpectrum s;
    for (int i = 0; i < kDenseSamples; ++i) s.v[size_t(i)] = spectrum(float(kDenseLambdaMin + i));
    return s;
}

inline Rgb emitted_rgb(const DenseSpectrum& s) { return xyz_to_linear_srgb(spectrum_to_xyz(s)); }

inline float largest_difference(const Rgb& a, const Rgb& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

}  // namespace candela::test
