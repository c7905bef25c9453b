#pragma once
// Where a texture is looked up: the shading point's surface coordinates, position and normal.
#include "candela/math/color.h"
#include "candela/math/vec.h"

namespace candela {

struct TextureContext {
    Vec2f uv;  // the surface's (u, v) (Accelerator::uv): v grows upward, as in OBJ and pbrt
    Vec3f p;   // world position
    // Spectral mode: the path's four wavelengths (nm), at which colours are evaluated; null in
    // RGB mode.
    const Color* lambda = nullptr;
    // The unit geometric normal (directionmix, pbrt-v4's TextureEvalContext::n); 0 where there
    // is none (alpha lookups during traversal).
    Vec3f n{0.0f, 0.0f, 0.0f};
};

}  // namespace candela
