#pragma once
// A constant colour of spectral mode: an RGB value's uplift, or a tabulated spectrum times a
// scale (a light's named illuminant or blackbody, normalized to luminance 1 and scaled).
#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/spectrum/dense_spectrum.h"
#include "candela/spectrum/rgb_to_spectrum.h"

namespace candela {

struct SpectralColor {
    RgbSpectrum rgb{};                     // used when table is null
    const DenseSpectrum* table = nullptr;  // must outlive this value (the scene's spectra)
    float scale = 1.0f;                    // multiplies the table

    CANDELA_HD Color eval(const Color& lambda) const {
        return table ? table->eval(lambda) * scale : rgb.eval(lambda);
    }
};

}  // namespace candela
