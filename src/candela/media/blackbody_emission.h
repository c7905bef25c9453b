#pragma once
// The emission of pbrt-v4's temperature grids (GridMedium, NanoVDBMedium): BlackbodySpectrum(T),
// Planck's law at T scaled to peak 1 at Wien's wavelength, taken as radiance without the
// photometric normalization pbrt-v4 gives lights and Le spectra.
//
// Units: pbrt-v4's film takes radiance L to XYZ = the integrals of the matching functions times L;
// candela's sensor divides those by kCieYIntegral (film/sensor.h) and so scales every normalized
// emitter up by it instead. An unnormalized emitter therefore needs kCieYIntegral times pbrt-v4's
// radiance to give pbrt-v4's image: both functions below include that factor.
//
// RGB mode takes the linear sRGB of that radiance from a table over temperature (4096 entries,
// 100 K to 10^7 K, equal steps of ln T), interpolating ln X, ln Y, ln Z linearly in ln T (the
// logarithms are smooth where the values themselves span hundreds of decades) and extrapolating
// the last step above 10^7 K (where the visible range is in Rayleigh-Jeans' tail and falls as
// T^-4 under the peak normalization). Its error against the exact integral is below 1e-3
// relative up to 2 10^7 K (tests/media/blackbody_emission_test.cpp), 2e-3 at 10^8 K.
#include <cmath>
#include <vector>

#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/math/rgb.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/cie_tables.h"

namespace candela {

// Below this temperature pbrt-v4's grid media emit nothing (`if (temp > 100)`).
inline constexpr float kMinEmittingKelvin = 100.0f;

// kCieYIntegral times pbrt-v4's BlackbodySpectrum(kelvin) at a path's four wavelengths (nm).
CANDELA_HD inline Color blackbody_radiance(float kelvin, const Color& lambda) {
    const double peak = planck(kWienDisplacement / double(kelvin) * 1e9, double(kelvin));
    const double k = double(kCieYIntegral) / peak;
    return map_channels(lambda, [&](float l) { return float(planck(double(l), double(kelvin)) * k); });
}

// The linear sRGB of blackbody_radiance, over temperature.
struct BlackbodyRgbTable {
    static constexpr int kSize = 4096;
    static constexpr float kMinKelvin = 100.0f, kMaxKelvin = 1e7f;
    std::vector<float> log_xyz;  // 3 kSize: ln X, ln Y, ln Z at T_i = kMinKelvin (kMax/kMin)^(i/(kSize-1))
    float rgb_from_xyz[3][3] = {};

    CANDELA_HD bool empty() const { return log_xyz.empty(); }
    // kelvin >= kMinKelvin.
    CANDELA_HD Rgb at(float kelvin) const {
        constexpr float kStepsPerLog = float(kSize - 1) / 11.5129254650f;  // ln(kMaxKelvin / kMinKelvin)
        const float x = std::log(kelvin / kMinKelvin) * kStepsPerLog;
        int i = int(x);
        i = i < 0 ? 0 : (i > kSize - 2 ? kSize - 2 : i);
        const float t = x - float(i);
        float xyz[3];
        for (int c = 0; c < 3; ++c) {
            const float a = log_xyz[size_t(3 * i + c)], b = log_xyz[size_t(3 * (i + 1) + c)];
            xyz[c] = std::exp(a + t * (b - a));
        }
        float rgb[3];
        for (int r = 0; r < 3; ++r)
            rgb[r] = rgb_from_xyz[r][0] * xyz[0] + rgb_from_xyz[r][1] * xyz[1] + rgb_from_xyz[r][2] * xyz[2];
        return Rgb(rgb[0], rgb[1], rgb[2]);
    }
};

// The table (computed in double from Planck's law and the CIE tables at 1 nm: about 1 M
// exponentials, a few milliseconds).
BlackbodyRgbTable make_blackbody_rgb_table();

// The exact value the table approximates: the linear sRGB of kCieYIntegral times
// BlackbodySpectrum(kelvin), integrated at 1 nm as spectrum_to_xyz does.
Rgb blackbody_rgb_exact(double kelvin);

}  // namespace candela
