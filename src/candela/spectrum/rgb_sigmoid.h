#pragma once
// A smooth bounded spectrum from three numbers: the sigmoid of a quadratic in the wavelength
// (Jakob & Hanika 2019, "A Low-Dimensional Function Space for Efficient Spectral Upsampling",
// eq. 3; pbrt-v4's RGBSigmoidPolynomial). Its values lie in [0, 1], so it can be a reflectance;
// rgb_to_spectrum.h finds the coefficients whose colour under D65 is a given sRGB value.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/color.h"

namespace candela {

// The sigmoid s(x) = 1/2 + x / (2 sqrt(1 + x^2)) (Jakob & Hanika eq. 4), which maps the reals
// onto (0, 1) with algebraic tails, s ~ 1 / (4 x^2) as x -> -inf. Evaluated as
// q = 1 / (2 r (r + |x|)), r = sqrt(1 + x^2), which equals 1/2 - |x| / (2r) without its
// cancellation ((r + |x|)(r - |x|) = 1): s = q for x < 0, 1 - q otherwise. So values near 0 (the
// dark channels of saturated colours) keep their relative precision, and infinite x, or
// |x| > 1.8e19 where x^2 overflows, gives exactly 0 or 1 (pbrt-v4 special-cases infinities and
// returns 1/2 where x^2 overflows). Every step rounds monotonically, so s is non-decreasing in
// float too. The choice multiplies by 0 or 1 rather than branching, so that it vectorizes.
CANDELA_HD inline float rgb_sigmoid_s(float x) {
    const float r = std::sqrt(1.0f + x * x);
    const float q = 1.0f / (2.0f * r * (r + std::abs(x)));
    const float positive = x < 0.0f ? 0.0f : 1.0f;
    return (1.0f - positive) * q + positive * (1.0f - q);
}

struct RgbSigmoid {
    // x(lambda) = c0 lambda^2 + c1 lambda + c2, lambda in nm.
    float c0 = 0, c1 = 0, c2 = 0;

    CANDELA_HD float polynomial(float lambda_nm) const { return (c0 * lambda_nm + c1) * lambda_nm + c2; }
    // The spectrum's value at lambda (nm), in [0, 1].
    CANDELA_HD float operator()(float lambda_nm) const { return rgb_sigmoid_s(polynomial(lambda_nm)); }
    // The values at a path's four wavelengths: rgb_sigmoid_s's operations in the same order,
    // so the same bits, written on whole Colors (one divps; the square roots per channel).
    CANDELA_HD Color eval(const Color& lambda) const {
        const Color x = (lambda * c0 + Color(c1)) * lambda + Color(c2);
        const Color r = sqrt_nonnegative_channels(Color(1.0f) + x * x);
        Color abs_x, positive;
        abs_x.c = x.c < 0.0f ? -x.c : x.c;
        positive.c = x.c < 0.0f ? ColorLanes{0.0f, 0.0f, 0.0f, 0.0f} : ColorLanes{1.0f, 1.0f, 1.0f, 1.0f};
        const Color q = Color(1.0f) / (Color(2.0f) * r * (r + abs_x));
        return (Color(1.0f) - positive) * q + positive * (Color(1.0f) - q);
    }
    // The largest value over 360-830 nm: at an end, or at the quadratic's vertex if it lies
    // inside (s increases with x, so the extremes of x are those of s; pbrt-v4's MaxValue).
    CANDELA_HD float max_value() const {
        const float a = (*this)(360.0f), b = (*this)(830.0f);
        float m = a > b ? a : b;
        if (c0 != 0.0f) {
            const float vertex = -c1 / (2.0f * c0);
            if (vertex >= 360.0f && vertex <= 830.0f) {
                const float v = (*this)(vertex);
                m = v > m ? v : m;
            }
        }
        return m;
    }
};

}  // namespace candela
