#pragma once
// CIE 1931 xy chromaticity of a spectrum, for the spectrum tests.
#include "candela/spectrum/dense_spectrum.h"

namespace candela::test {

struct Xy {
    double x, y;
};

inline Xy chromaticity(const DenseSpectrum& s) {
    const Vec3d c = spectrum_to_xyz(s);
    const double sum = c.x + c.y + c.z;
    return {c.x / sum, c.y / sum};
}

}  // namespace candela::test
