#pragma once
// A material parameter that may be a texture: a constant value, or the index of a texture in the
// scene's TextureSet (textures/texture_set.h) that gives the value at each shading point.
#include <cstdint>

#include "candela/math/color.h"

namespace candela {

inline constexpr uint32_t kNoTexture = 0xffffffffu;

struct FloatParam {
    float value = 0.0f;             // the value where `texture` is kNoTexture
    uint32_t texture = kNoTexture;  // index into TextureSet

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

struct ColorParam {
    Color value;
    uint32_t texture = kNoTexture;

    CANDELA_HD bool is_textured() const { return texture != kNoTexture; }
};

}  // namespace candela
