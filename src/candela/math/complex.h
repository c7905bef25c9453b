#pragma once
// A complex number in float: just what the Fresnel equations of conductors need (pbrt-v4's
// pstd::complex), without std::complex, whose operations a GPU backend may not compile.
#include <cmath>

#include "candela/core/platform.h"

namespace candela {

struct Complex {
    float re = 0.0f;
    float im = 0.0f;

    CANDELA_HD constexpr Complex() = default;
    CANDELA_HD constexpr Complex(float re_, float im_ = 0.0f) : re(re_), im(im_) {}

    CANDELA_HD constexpr Complex operator-() const { return {-re, -im}; }
    CANDELA_HD constexpr Complex operator+(Complex o) const { return {re + o.re, im + o.im}; }
    CANDELA_HD constexpr Complex operator-(Complex o) const { return {re - o.re, im - o.im}; }
    CANDELA_HD constexpr Complex operator*(Complex o) const {
        return {re * o.re - im * o.im, re * o.im + im * o.re};
    }
    CANDELA_HD constexpr Complex operator/(Complex o) const {
        float scale = 1.0f / (o.re * o.re + o.im * o.im);
        return {scale * (re * o.re + im * o.im), scale * (im * o.re - re * o.im)};
    }
};

// |z|^2 (std::norm).
CANDELA_HD constexpr float norm(Complex z) { return z.re * z.re + z.im * z.im; }

// The principal square root (real part >= 0): sqrt((|z| + re) / 2) + i sign(im) sqrt((|z| - re) / 2),
// with the smaller part from im / (2 t) so that it does not cancel.
CANDELA_HD inline Complex sqrt(Complex z) {
    float n = std::sqrt(norm(z));
    if (n == 0.0f) return {0.0f, 0.0f};
    float t1 = std::sqrt(0.5f * (n + std::abs(z.re)));
    float t2 = 0.5f * z.im / t1;
    if (z.re >= 0.0f) return {t1, t2};
    return {std::abs(t2), std::copysign(t1, z.im)};
}

}  // namespace candela
