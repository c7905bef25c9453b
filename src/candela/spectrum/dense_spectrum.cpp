#include "candela/spectrum/dense_spectrum.h"

#include "candela/core/check.h"
#include "candela/spectrum/cie_tables.h"

namespace candela {

DenseSpectrum dense_from_pairs(std::span<const float> p) {
    CANDELA_CHECK(p.size() >= 2 && p.size() % 2 == 0);
    const size_t n = p.size() / 2;
    DenseSpectrum s;
    size_t k = 0;  // the segment [k, k + 1] that holds lambda
    for (int i = 0; i < kDenseSamples; ++i) {
        const float lambda = float(kDenseLambdaMin + i);
        if (lambda <= p[0]) {
            s.v[size_t(i)] = p[1];
            continue;
        }
        if (lambda >= p[2 * (n - 1)]) {
            s.v[size_t(i)] = p[2 * (n - 1) + 1];
            continue;
        }
        while (p[2 * (k + 1)] < lambda) ++k;
        const float l0 = p[2 * k], l1 = p[2 * (k + 1)];
        const float t = (lambda - l0) / (l1 - l0);
        s.v[size_t(i)] = (1.0f - t) * p[2 * k + 1] + t * p[2 * (k + 1) + 1];
    }
    return s;
}

DenseSpectrum dense_constant(float value) {
    DenseSpectrum s;
    s.v.fill(value);
    return s;
}

namespace {
DenseSpectrum from_table(const float* t) {
    DenseSpectrum s;
    for (int i = 0; i < kDenseSamples; ++i) s.v[size_t(i)] = t[i];
    return s;
}
}  // namespace

static_assert(kCieSamples == kDenseSamples);
const DenseSpectrum& cie_x_bar() {
    static const DenseSpectrum s = from_table(kCieX);
    return s;
}
const DenseSpectrum& cie_y_bar() {
    static const DenseSpectrum s = from_table(kCieY);
    return s;
}
const DenseSpectrum& cie_z_bar() {
    static const DenseSpectrum s = from_table(kCieZ);
    return s;
}

Vec3d spectrum_to_xyz(const DenseSpectrum& s) {
    double x = 0.0, y = 0.0, z = 0.0;
    for (int i = 0; i < kDenseSamples; ++i) {
        const double v = s.v[size_t(i)];
        x += double(kCieX[i]) * v;
        y += double(kCieY[i]) * v;
        z += double(kCieZ[i]) * v;
    }
    return Vec3d(x, y, z) / double(kCieYIntegral);
}

double spectrum_to_photometric(const DenseSpectrum& s) {
    double y = 0.0;
    for (int i = 0; i < kDenseSamples; ++i) y += double(kCieY[i]) * double(s.v[size_t(i)]);
    return y;
}

const DenseSpectrum& d65_illuminant() {
    static const DenseSpectrum s = [] {
        DenseSpectrum d = dense_from_pairs(kCieIllumD65);
        d *= float(double(kCieYIntegral) / spectrum_to_photometric(d));
        return d;
    }();
    return s;
}

}  // namespace candela
