#pragma once
// Where a texture is looked up: the shading point's surface coordinates and position.
#include "candela/math/vec.h"

namespace candela {

struct TextureContext {
    Vec2f uv;  // the surface's (u, v) (Accelerator::uv): v grows upward, as in OBJ and pbrt
    Vec3f p;   // world position
};

}  // namespace candela
