#include "candela/spectrum/spectrum_rgb.h"

#include "candela/spectrum/color_space.h"

namespace candela {

Rgb reflectance_rgb(const DenseSpectrum& s) {
    // The product in float, as the D65 table is: a constant 1 gives D65's very values, so the
    // XYZ is the colour space's white exactly and only its matrix product rounds.
    const DenseSpectrum& d65 = d65_illuminant();
    DenseSpectrum lit;
    for (int i = 0; i < kDenseSamples; ++i) lit.v[size_t(i)] = s.v[size_t(i)] * d65.v[size_t(i)];
    return xyz_to_linear_srgb(spectrum_to_xyz(lit));
}

Rgb emission_rgb(const DenseSpectrum& s) {
    const Vec3d xyz = spectrum_to_xyz(s);
    if (!(xyz.y > 0.0)) return Rgb(0.0f);
    return xyz_to_linear_srgb(xyz / xyz.y);
}

}  // namespace candela
