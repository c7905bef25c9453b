#pragma once
// A material parameter that may be a texture: a constant value, or the index of a texture in the
// scene's TextureSet (textures/texture_set.h) that gives the value at each shading point.
//
// A texture's values are not known when the scene loads (an image may hold anything), so a
// textured parameter carries its range and the texture's value is clamped into it where it is
// looked up (pbrt-v4 clamps an albedo texture's RGB to [0, 1] the same way). A constant is checked
// against the range when it is read and returned as it is.
#include <cstdint>
#include <limits>

#include "candela/math/color.h"

namespace candela {

inline constexpr uint32_t kNoTexture = 0xffffffffu;
inline constexpr float kUnbounded = std::numeric_limits<float>::infinity();

struct FloatParam {
    float value = 0.0f;             // the value where `texture` is kNoTexture
    uint32_t texture = kNoTexture;  // index into TextureSet
    float lo = -kUnbounded;         // a texture's value is clamped to [lo, hi]
    float hi = kUnbounded;

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

struct ColorParam {
    Rgb value;  // the constant, in linear RGB (both modes' textures work in RGB)
    uint32_t texture = kNoTexture;
    float lo = -kUnbounded;  // each channel of a texture's value is clamped to [lo, hi]
    float hi = kUnbounded;

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

}  // namespace candela
