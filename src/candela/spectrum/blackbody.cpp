#include "candela/spectrum/blackbody.h"

#include <array>

#include "candela/core/check.h"
#include "candela/spectrum/named_spectra_data.h"

namespace candela {

DenseSpectrum blackbody_spectrum(float kelvin) {
    CANDELA_CHECK(kelvin > 0.0f);
    const double peak = planck(kWienDisplacement / double(kelvin) * 1e9, double(kelvin));
    DenseSpectrum s;
    for (int i = 0; i < kDenseSamples; ++i)
        s.v[size_t(i)] = float(planck(double(kDenseLambdaMin + i), double(kelvin)) / peak);
    return s;
}

DenseSpectrum cie_daylight(float kelvin) {
    CANDELA_CHECK(kelvin > 0.0f);
    // Colour temperatures of the D series were defined with c2 = 1.4380e-2 m K; with today's
    // 1.4388e-2 the same light has a temperature higher by that ratio (CIE 15:2004, D65 at
    // 6504 K).
    const double t = double(kelvin) * 1.4388 / 1.4380;
    if (t < 4000.0) return blackbody_spectrum(float(t));
    // The chromaticity of daylight at t (CIE 15:2004's daylight locus) ...
    const double x = t <= 7000.0 ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                                 : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
    const double y = -3.0 * x * x + 2.870 * x - 0.275;
    // ... gives the weights of the daylight basis S1 and S2 (CIE 15:2004, Judd et al. 1964).
    const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
    const double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m;
    const double m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m;
    std::array<float, 2 * kCieSSamples> pairs;
    for (int i = 0; i < kCieSSamples; ++i) {
        pairs[size_t(2 * i)] = kCieSLambda[i];
        const double s = double(kCieS0[i]) + m1 * double(kCieS1[i]) + m2 * double(kCieS2[i]);
        pairs[size_t(2 * i + 1)] = float(s * 0.01);
    }
    return dense_from_pairs(pairs);
}

}  // namespace candela
