#include "candela/spectrum/rgb_to_spectrum.h"

#include "candela/spectrum/rgb_to_spectrum_table.h"

namespace candela {

CANDELA_HD RgbSigmoid rgb_to_sigmoid(const Rgb& c) { return srgb_to_spectrum_table()(c); }

CANDELA_HD RgbSpectrum rgb_albedo_spectrum(const Rgb& rgb) {
    const Rgb c = clamp_channels(rgb, 0.0f, 1.0f);
    if (c.r == c.g && c.g == c.b) return RgbSpectrum{RgbSigmoid{}, 2.0f * c.r, false};
    return RgbSpectrum{rgb_to_sigmoid(c), 1.0f, false};
}

CANDELA_HD RgbSpectrum rgb_unbounded_spectrum(const Rgb& rgb) {
    // 2m * s(rgb / 2m): a grey v gives 2v * 1/2 = v exactly.
    const float m = rgb.max_component();
    const float scale = 2.0f * m;
    if (!(scale > 0.0f)) return RgbSpectrum{RgbSigmoid{}, 0.0f, false};
    return RgbSpectrum{rgb_to_sigmoid(clamp_channels(rgb / scale, 0.0f, 1.0f)), scale, false};
}

CANDELA_HD RgbSpectrum rgb_illuminant_spectrum(const Rgb& rgb) {
    RgbSpectrum s = rgb_unbounded_spectrum(rgb);
    s.illuminant = true;
    return s;
}

}  // namespace candela
