#pragma once
// Linear RGB radiance, reflectance or pixel value (Rec. 709 primaries, as the scene file).
#include <cmath>

#include "candela/core/platform.h"

namespace candela {

struct Rgb {
    float r = 0, g = 0, b = 0;
    CANDELA_HD constexpr Rgb() = default;
    CANDELA_HD constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    CANDELA_HD explicit constexpr Rgb(float v) : r(v), g(v), b(v) {}

    CANDELA_HD constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    CANDELA_HD constexpr Rgb operator+(Rgb o) const { return {r + o.r, g + o.g, b + o.b}; }
    CANDELA_HD constexpr Rgb operator-(Rgb o) const { return {r - o.r, g - o.g, b - o.b}; }
    CANDELA_HD constexpr Rgb operator*(Rgb o) const { return {r * o.r, g * o.g, b * o.b}; }
    CANDELA_HD constexpr Rgb operator*(float s) const { return {r * s, g * s, b * s}; }
    CANDELA_HD constexpr Rgb operator/(float s) const { return {r / s, g / s, b / s}; }
    CANDELA_HD constexpr Rgb& operator+=(Rgb o) { r += o.r; g += o.g; b += o.b; return *this; }
    CANDELA_HD constexpr Rgb& operator*=(Rgb o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    CANDELA_HD constexpr Rgb& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
    CANDELA_HD constexpr bool operator==(const Rgb&) const = default;

    CANDELA_HD constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
    CANDELA_HD constexpr float max_component() const {
        float m = r > g ? r : g;  // two maxss, no branch (vec.h's max_component)
        return m > b ? m : b;
    }
    CANDELA_HD constexpr float average() const { return (r + g + b) / 3.0f; }
    // Rec. 709 luminance.
    CANDELA_HD constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    CANDELA_HD bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

CANDELA_HD constexpr Rgb operator*(float s, Rgb c) { return c * s; }

}  // namespace candela
