#pragma once
// A spectrum tabulated at every integer wavelength from 360 to 830 nm (pbrt-v4's
// DenselySampledSpectrum over its visible range). Every spectrum that is data (named, a list of
// pairs, a file, a blackbody, the CIE functions) is resampled into this form once, at load time;
// a lookup is then one rounding and one load, as in pbrt-v4 (which rounds to the nearest nm).
#include <array>
#include <cmath>
#include <span>

#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/math/vec.h"

namespace candela {

inline constexpr int kDenseLambdaMin = 360;
inline constexpr int kDenseLambdaMax = 830;
inline constexpr int kDenseSamples = kDenseLambdaMax - kDenseLambdaMin + 1;

// The index of the nearest tabulated nm in a 360-830 nm table (this one's, and the CIE
// tables', which share its layout), or -1 outside it. int(lambda + 0.5) is lround for the
// wavelengths that can be inside, and compiles inline; lroundf is a call.
CANDELA_HD inline int dense_index(float lambda) {
    const int i = int(lambda + 0.5f) - kDenseLambdaMin;
    return i < 0 || i >= kDenseSamples ? -1 : i;
}

struct DenseSpectrum {
    std::array<float, kDenseSamples> v{};

    // The value at the nearest tabulated nm; 0 outside [360, 830].
    CANDELA_HD float operator()(float lambda) const {
        const int i = dense_index(lambda);
        return i < 0 ? 0.0f : v[size_t(i)];
    }
    // The values at a path's four wavelengths.
    CANDELA_HD Color eval(const Color& lambda) const {
        Color c;
        for (int i = 0; i < kColorChannels; ++i) c.set(i, (*this)(lambda[i]));
        return c;
    }
    float max_value() const {
        float m = v[0];
        for (float x : v) m = x > m ? x : m;
        return m;
    }
    DenseSpectrum& operator*=(float s) {
        for (float& x : v) x *= s;
        return *this;
    }
};

// The piecewise-linear function through (nm, value) pairs (wavelengths strictly increasing),
// sampled at every nm; constant beyond the first and last pair (pbrt-v4's
// PiecewiseLinearSpectrum is 0 there; its tables all cover 360-830, and a user's short list is
// more useful extended than cut).
DenseSpectrum dense_from_pairs(std::span<const float> interleaved);
DenseSpectrum dense_constant(float value);

// The CIE 1931 matching functions as dense spectra (spectrum/cie_tables.h).
const DenseSpectrum& cie_x_bar();
const DenseSpectrum& cie_y_bar();
const DenseSpectrum& cie_z_bar();

// CIE XYZ of a spectrum: the sums of s times each matching function over 360-830 nm, divided by
// the integral of y-bar (pbrt-v4's SpectrumToXYZ): a constant spectrum 1 has Y = 1.
Vec3d spectrum_to_xyz(const DenseSpectrum& s);
// The sum of s times y-bar over 360-830 nm, not normalized (pbrt-v4's SpectrumToPhotometric).
double spectrum_to_photometric(const DenseSpectrum& s);

// CIE standard illuminant D65 scaled to luminance Y = 1 (pbrt-v4's stdillum-D65, normalized as
// its named illuminants are): the white of the sRGB colour space and of RGB illuminants.
const DenseSpectrum& d65_illuminant();

}  // namespace candela
