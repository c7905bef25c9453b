#pragma once
// The colour type that materials, textures and lights compute with and paths carry: four channel
// values, a small fixed-width vector the compiler keeps in one SSE register.
//
// - In RGB mode the channels are (r, g, b, r): the fourth repeats red, so that every per-channel
//   operation gives the three RGB channels exactly as three floats would, and the reductions
//   transport uses (max_component, is_black, is_finite) see the same three values. to_rgb()
//   reads the first three.
// - In spectral mode (spectrum/sampled_wavelengths.h) they are a path's values at its four
//   wavelengths (pbrt-v4's SampledSpectrum with NSpectrumSamples = 4).
//
// Code written against Color and the element-wise helpers below, never naming channels, works
// unchanged in both modes. A colour from three RGB values is an RGB-mode colour only
// (from_rgb); spectral mode makes colours from spectra (spectrum/).
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/rgb.h"

namespace candela {

inline constexpr int kColorChannels = 4;

// The four channels as one GCC/Clang vector: every arithmetic operator is one SSE instruction
// (mulps, addps, ...), which rounds each channel exactly as the scalar operation would, so RGB
// mode's channels are the bits that three floats gave. Aligned to 4 bytes, not the vector's 16:
// the padding 16-byte alignment adds to the structs that hold colours (lobes, light samples,
// lights) cost 5% on the Cornell box, unaligned loads nothing (bench/RESULTS.md, issue 14).
typedef float ColorLanes __attribute__((vector_size(16), aligned(4)));

struct Color {
    ColorLanes c = {0.0f, 0.0f, 0.0f, 0.0f};

    CANDELA_HD constexpr Color() = default;
    // The same value in every channel: grey in RGB mode, a constant spectrum in spectral mode.
    CANDELA_HD explicit constexpr Color(float v) : c{v, v, v, v} {}
    // An RGB-mode colour: (r, g, b, r). From an Rgb only explicitly (or by from_rgb), so that
    // spectral code cannot take an RGB triple for its four wavelengths' values by accident
    // (spectrum/ makes spectral colours).
    CANDELA_HD constexpr Color(float r, float g, float b) : c{r, g, b, r} {}
    CANDELA_HD explicit constexpr Color(const Rgb& v) : c{v.r, v.g, v.b, v.r} {}
    CANDELA_HD static constexpr Color from_channels(float c0, float c1, float c2, float c3) {
        Color x;
        x.c = ColorLanes{c0, c1, c2, c3};
        return x;
    }

    CANDELA_HD float operator[](int i) const { return c[i]; }
    CANDELA_HD void set(int i, float v) { c[i] = v; }

#define CANDELA_COLOR_OP(OP)                                                                      \
    CANDELA_HD constexpr Color operator OP(const Color& o) const {                                 \
        Color r;                                                                                   \
        r.c = c OP o.c;                                                                            \
        return r;                                                                                  \
    }                                                                                              \
    CANDELA_HD constexpr Color operator OP(float s) const {                                        \
        Color r;                                                                                   \
        r.c = c OP s;                                                                              \
        return r;                                                                                  \
    }                                                                                              \
    CANDELA_HD constexpr Color& operator OP##=(const Color& o) {                                   \
        c = c OP o.c;                                                                              \
        return *this;                                                                              \
    }                                                                                              \
    CANDELA_HD constexpr Color& operator OP##=(float s) {                                          \
        c = c OP s;                                                                                \
        return *this;                                                                              \
    }
    CANDELA_COLOR_OP(+)
    CANDELA_COLOR_OP(-)
    CANDELA_COLOR_OP(*)
    CANDELA_COLOR_OP(/)
#undef CANDELA_COLOR_OP

    CANDELA_HD bool operator==(const Color& o) const {
        return c[0] == o.c[0] && c[1] == o.c[1] && c[2] == o.c[2] && c[3] == o.c[3];
    }

    CANDELA_HD bool is_black() const {
        return c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f && c[3] == 0.0f;
    }
    CANDELA_HD float max_component() const {
        float a = c[0] > c[1] ? c[0] : c[1];  // a tree of maxss, no branch
        float b = c[2] > c[3] ? c[2] : c[3];
        return a > b ? a : b;
    }
    CANDELA_HD bool is_finite() const {
        return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]);
    }
};

CANDELA_HD constexpr Color operator*(float s, const Color& x) { return x * s; }

// RGB mode: the colour of an RGB value, and the RGB value of a colour.
CANDELA_HD constexpr Color from_rgb(const Rgb& v) { return Color(v.r, v.g, v.b); }
CANDELA_HD inline Rgb to_rgb(const Color& x) { return Rgb(x.c[0], x.c[1], x.c[2]); }

// Applies f to every channel.
template <class F>
CANDELA_HD inline Color map_channels(const Color& x, F&& f) {
    return Color::from_channels(f(x.c[0]), f(x.c[1]), f(x.c[2]), f(x.c[3]));
}
// Applies f to the channels of a and b pairwise.
template <class F>
CANDELA_HD inline Color map_channels(const Color& a, const Color& b, F&& f) {
    return Color::from_channels(f(a.c[0], b.c[0]), f(a.c[1], b.c[1]), f(a.c[2], b.c[2]), f(a.c[3], b.c[3]));
}

// Element-wise quotient; a channel divided by 0 gives 0 (a black denominator means "no light").
CANDELA_HD inline Color safe_div(const Color& a, const Color& b) {
    return map_channels(a, b, [](float x, float y) { return y != 0.0f ? x / y : 0.0f; });
}
// The square root of every channel, which must be >= 0: one sqrtps where the compiler targets
// SSE (correctly rounded, the same bits as std::sqrt per channel), else per channel.
CANDELA_HD inline Color sqrt_nonnegative_channels(const Color& x) {
#if defined(__SSE__) && !defined(__CUDA_ARCH__)
    Color r;
    r.c = __builtin_ia32_sqrtps(x.c);
    return r;
#else
    return map_channels(x, [](float v) { return std::sqrt(v); });
#endif
}
// The square root of every channel, negative channels taken as 0.
CANDELA_HD inline Color sqrt_channels(const Color& x) {
    Color clamped;
    clamped.c = x.c > 0.0f ? x.c : ColorLanes{0.0f, 0.0f, 0.0f, 0.0f};
    return sqrt_nonnegative_channels(clamped);
}
CANDELA_HD inline Color exp_channels(const Color& x) {
    return map_channels(x, [](float v) { return std::exp(v); });
}
CANDELA_HD inline Color clamp_channels(const Color& x, float lo, float hi) {
    return map_channels(x, [lo, hi](float v) { return v < lo ? lo : (v > hi ? hi : v); });
}
// The smallest channel value.
CANDELA_HD inline float min_component(const Color& x) {
    float a = x.c[0] < x.c[1] ? x.c[0] : x.c[1];
    float b = x.c[2] < x.c[3] ? x.c[2] : x.c[3];
    return a < b ? a : b;
}
// The mean of the channels (spectral mode's Average), exactly the value of a constant colour (a
// sum of equal values divided by their count may differ from it in the last bit).
CANDELA_HD inline float channel_average(const Color& x) {
    if (x.c[0] == x.c[1] && x.c[1] == x.c[2] && x.c[2] == x.c[3]) return x.c[0];
    return (x.c[0] + x.c[1] + x.c[2] + x.c[3]) / 4.0f;
}

// Rgb helpers for texture values (textures hold RGB in both modes).
CANDELA_HD inline Rgb clamp_channels(const Rgb& x, float lo, float hi) {
    auto f = [lo, hi](float v) { return v < lo ? lo : (v > hi ? hi : v); };
    return Rgb(f(x.r), f(x.g), f(x.b));
}
// The mean of the three channels, exactly the value of a grey.
CANDELA_HD inline float channel_average(const Rgb& x) {
    return x.r == x.g && x.g == x.b ? x.r : (x.r + x.g + x.b) / 3.0f;
}

}  // namespace candela
