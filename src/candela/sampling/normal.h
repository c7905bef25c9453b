#pragma once
// The normal distribution by inversion: erfinv, standard and truncated normal samples with their
// densities. Inversion (rather than Box-Muller) maps one uniform to one value monotonically, so
// stratified uniforms stay stratified and the Gaussian pixel filter is sampled exactly.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"

namespace candela {

// The inverse error function on (-1, 1), relative error below ~1e-6 (Giles 2011, "Approximating
// the erfinv function", GPU Computing Gems Jade, single-precision version). At x = +-1 it returns
// a finite +-3.92 (just beyond erfinv of the floats nearest +-1, +-3.83) instead of infinity.
CANDELA_HD inline float erfinv(float x) {
    // w = -log(1 - x^2); the fma keeps 1 - x^2 accurate near |x| = 1. The floor 2^-24 is below
    // 1 - x^2 = 2^-23 of the float nearest 1, and keeps w within the tail polynomial's range.
    float w = -std::log(std::fmax(std::fma(x, -x, 1.0f), 0x1p-24f));
    float p;
    if (w < 5.0f) {
        w = w - 2.5f;
        p = 2.81022636e-08f;
        p = 3.43273939e-07f + p * w;
        p = -3.5233877e-06f + p * w;
        p = -4.39150654e-06f + p * w;
        p = 0.00021858087f + p * w;
        p = -0.00125372503f + p * w;
        p = -0.00417768164f + p * w;
        p = 0.246640727f + p * w;
        p = 1.50140941f + p * w;
    } else {
        w = std::sqrt(w) - 3.0f;
        p = -0.000200214257f;
        p = 0.000100950558f + p * w;
        p = 0.00134934322f + p * w;
        p = -0.00367342844f + p * w;
        p = 0.00573950773f + p * w;
        p = -0.0076224613f + p * w;
        p = 0.00943887047f + p * w;
        p = 1.00167406f + p * w;
        p = 2.83297682f + p * w;
    }
    return p * x;
}

// A standard normal value from u in [0, 1): Phi^-1(u) = sqrt(2) erfinv(2u - 1). The argument is
// clamped to |2u - 1| <= 1 - 2^-24, so u = 0 gives about -5.4 (not -infinity); the largest u
// below 1 gives about +5.3.
CANDELA_HD inline float sample_standard_normal(float u) {
    float t = clamp(2.0f * u - 1.0f, -kOneMinusEpsilon, kOneMinusEpsilon);
    return 1.41421356237309504880f * erfinv(t);
}
// Per unit length: exp(-x^2 / 2) / sqrt(2 pi).
CANDELA_HD inline float standard_normal_pdf(float x) {
    return 0.39894228040143267794f * std::exp(-0.5f * x * x);
}

// A value of the normal N(0, sigma^2) conditioned on |x| <= radius, from u in [0, 1), by inverting
// its CDF exactly: x = sigma sqrt(2) erfinv(erf(radius / (sigma sqrt(2))) (2u - 1)).
CANDELA_HD inline float sample_truncated_normal(float u, float sigma, float radius) {
    constexpr float kSqrt2 = 1.41421356237309504880f;
    float mass = std::erf(radius / (sigma * kSqrt2));  // P(|x| <= radius) of the untruncated normal
    float x = sigma * kSqrt2 * erfinv(mass * (2.0f * u - 1.0f));
    return clamp(x, -radius, radius);  // erfinv's last-bit error must not leave the support
}
// Per unit length: the normal density renormalised to [-radius, radius], 0 outside.
CANDELA_HD inline float truncated_normal_pdf(float x, float sigma, float radius) {
    constexpr float kSqrt2 = 1.41421356237309504880f;
    if (std::abs(x) > radius) return 0.0f;
    float mass = std::erf(radius / (sigma * kSqrt2));
    return standard_normal_pdf(x / sigma) / (sigma * mass);
}

}  // namespace candela
