#include "candela/media/medium_spectrum.h"

#include "candela/spectrum/rgb_to_spectrum.h"

namespace candela {

namespace {

// The spectrum tabulated at every nm.
DenseSpectrum tabulate(const RgbSpectrum& s) {
    DenseSpectrum d;
    for (int i = 0; i < kDenseSamples; ++i) d.v[size_t(i)] = s(float(kDenseLambdaMin + i));
    return d;
}

}  // namespace

MediumSpectrum medium_coefficient(const Rgb& rgb) { return MediumSpectrum{rgb, tabulate(rgb_unbounded_spectrum(rgb))}; }

MediumSpectrum medium_emission(const Rgb& rgb) { return MediumSpectrum{rgb, tabulate(rgb_illuminant_spectrum(rgb))}; }

}  // namespace candela
