#include "candela/media/blackbody_emission.h"

#include "candela/spectrum/color_space.h"

namespace candela {

namespace {

// The integrals of the matching functions times kCieYIntegral x BlackbodySpectrum(kelvin), over
// 360-830 nm at 1 nm, divided by kCieYIntegral (spectrum_to_xyz): the two factors cancel.
Vec3d blackbody_xyz(double kelvin) {
    const double peak = planck(kWienDisplacement / kelvin * 1e9, kelvin);
    Vec3d xyz(0.0);
    for (int i = 0; i < kCieSamples; ++i) {
        const double v = planck(double(kCieLambdaMin) + double(i), kelvin) / peak;
        xyz += Vec3d(double(kCieX[i]), double(kCieY[i]), double(kCieZ[i])) * v;
    }
    return xyz;
}

}  // namespace

Rgb blackbody_rgb_exact(double kelvin) { return xyz_to_linear_srgb(blackbody_xyz(kelvin)); }

BlackbodyRgbTable make_blackbody_rgb_table() {
    BlackbodyRgbTable t;
    t.log_xyz.resize(size_t(3 * BlackbodyRgbTable::kSize));
    const double log_range = std::log(double(BlackbodyRgbTable::kMaxKelvin) / double(BlackbodyRgbTable::kMinKelvin));
    for (int i = 0; i < BlackbodyRgbTable::kSize; ++i) {
        const double kelvin =
            double(BlackbodyRgbTable::kMinKelvin) * std::exp(log_range * double(i) / double(BlackbodyRgbTable::kSize - 1));
        const Vec3d xyz = blackbody_xyz(kelvin);
        for (int c = 0; c < 3; ++c) t.log_xyz[size_t(3 * i + c)] = float(std::log(xyz[c]));
    }
    const Matrix3d& m = srgb_color_space().rgb_from_xyz;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) t.rgb_from_xyz[r][c] = float(m.m[r][c]);
    return t;
}

}  // namespace candela
