#pragma once
// Blackbody emission (Planck's law) and the CIE daylight illuminants, as spectra.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// Wien's displacement constant b (m K): a blackbody's radiance peaks at lambda_max = b / T.
inline constexpr double kWienDisplacement = 2.8977721e-3;

// Planck's law: the spectral radiance of a blackbody at `kelvin` K, at wavelength `lambda_nm`
// nm, in W / (m^2 sr m) (per metre of wavelength), with pbrt-v4's constants (c, h, k_B of CODATA
// 2010); 0 for kelvin <= 0. Computed in double (pbrt-v4: float and an approximate exp).
CANDELA_HD inline double planck(double lambda_nm, double kelvin) {
    if (kelvin <= 0.0) return 0.0;
    constexpr double c = 299792458.0;      // speed of light, m/s
    constexpr double h = 6.62606957e-34;   // Planck's constant, J s
    constexpr double kb = 1.3806488e-23;   // Boltzmann's constant, J/K
    const double l = lambda_nm * 1e-9;
    const double l5 = l * l * l * l * l;
    return 2.0 * h * c * c / (l5 * (std::exp(h * c / (l * kb * kelvin)) - 1.0));
}

// The blackbody of `kelvin` (> 0) K scaled to peak 1 at Wien's lambda_max (pbrt-v4's
// BlackbodySpectrum): a colour, its brightness given elsewhere.
DenseSpectrum blackbody_spectrum(float kelvin);

// The CIE daylight illuminant (D series) of nominal colour temperature `kelvin` (> 0), as
// pbrt-v4's Spectra::D, which film white balance uses: the temperature is moved to the current
// second radiation constant (x 1.4388 / 1.4380, so 6500 gives D65 and 5000 D50), the chromaticity
// of daylight at it gives the weights of the basis S0, S1, S2 (CIE 15:2004), and the result is
// scaled by 1/100 (about 1 at 560 nm). Below 4000 K, where the D series is not defined, it is
// blackbody_spectrum of the moved temperature.
DenseSpectrum cie_daylight(float kelvin);

}  // namespace candela
