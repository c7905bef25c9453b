#pragma once
// What a medium's coefficients and emission are in each colour mode. A path carries either RGB
// mode's three colours or spectral mode's four wavelengths (`MediumChannels`); a medium stores
// each quantity once per mode (`MediumSpectrum`) and answers at the path's channels.
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/math/rgb.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// The medium index of "no medium" (vacuum): pbrt-v4's empty medium name.
inline constexpr uint32_t kNoMedium = 0xffffffffu;

// The channels of a path: its wavelengths (nm) in spectral mode, null in RGB mode.
struct MediumChannels {
    const Color* lambda = nullptr;
    CANDELA_HD bool spectral() const { return lambda != nullptr; }
};

// A coefficient (per unit length) or an emitted radiance: its RGB value for RGB mode and its
// spectrum, sampled at every nm, for spectral mode (an RGB input's spectrum is pbrt-v4's
// uplift: RGBUnboundedSpectrum for coefficients, RGBIlluminantSpectrum for emission).
struct MediumSpectrum {
    Rgb rgb;
    DenseSpectrum spectrum;

    // The values at the path's channels. In RGB mode channel 3 repeats red (Color(Rgb)), and
    // the integrator averages only over channels 0-2.
    CANDELA_HD Color at(const MediumChannels& ch) const { return ch.lambda ? spectrum.eval(*ch.lambda) : Color(rgb); }
    bool is_black() const { return rgb.r == 0.0f && rgb.g == 0.0f && rgb.b == 0.0f && spectrum.max_value() == 0.0f; }
};

// An RGB coefficient and its spectrum, pbrt-v4's RGBUnboundedSpectrum (any value >= 0).
MediumSpectrum medium_coefficient(const Rgb& rgb);
// An RGB emission and its spectrum, pbrt-v4's RGBIlluminantSpectrum (the colour times D65).
MediumSpectrum medium_emission(const Rgb& rgb);

// Multiplies both forms by s.
inline MediumSpectrum scaled(MediumSpectrum m, float s) {
    m.rgb = m.rgb * s;
    for (float& v : m.spectrum.v) v *= s;
    return m;
}

}  // namespace candela
