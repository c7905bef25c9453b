#pragma once
// The colour type that materials, textures and lights compute with. It is linear RGB today
// (math/rgb.h); the spectral mode (issue 14) makes it the values of a path's four wavelengths.
// Code written against `Color` and the element-wise helpers below, never reading .r/.g/.b,
// works unchanged for both: a colour is a small fixed-width vector of channel values.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/rgb.h"

namespace candela {

using Color = Rgb;

// Applies f to every channel.
template <class F>
CANDELA_HD inline Color map_channels(const Color& c, F&& f) {
    return Color(f(c.r), f(c.g), f(c.b));
}
// Applies f to the channels of a and b pairwise.
template <class F>
CANDELA_HD inline Color map_channels(const Color& a, const Color& b, F&& f) {
    return Color(f(a.r, b.r), f(a.g, b.g), f(a.b, b.b));
}

// Element-wise quotient; a channel divided by 0 gives 0 (a black denominator means "no light").
CANDELA_HD inline Color safe_div(const Color& a, const Color& b) {
    return map_channels(a, b, [](float x, float y) { return y != 0.0f ? x / y : 0.0f; });
}
CANDELA_HD inline Color sqrt_channels(const Color& c) {
    return map_channels(c, [](float x) { return std::sqrt(x > 0.0f ? x : 0.0f); });
}
CANDELA_HD inline Color exp_channels(const Color& c) {
    return map_channels(c, [](float x) { return std::exp(x); });
}
CANDELA_HD inline Color clamp_channels(const Color& c, float lo, float hi) {
    return map_channels(c, [lo, hi](float x) { return x < lo ? lo : (x > hi ? hi : x); });
}
// The smallest channel value.
CANDELA_HD inline float min_component(const Color& c) {
    float m = c.r < c.g ? c.r : c.g;
    return m < c.b ? m : c.b;
}
// The mean of the channels, exactly the value of a grey colour (a sum of three equal values
// divided by 3 may differ from it in the last bit): how a colour is read as one number.
CANDELA_HD inline float channel_average(const Color& c) {
    return c.r == c.g && c.g == c.b ? c.r : (c.r + c.g + c.b) / 3.0f;
}

}  // namespace candela
