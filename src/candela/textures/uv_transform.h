#pragma once
// A texture's own scale and offset of the surface's (u, v): (s, t) = (su u + du, sv v + dv), as
// pbrt's UVMapping (uscale, vscale, udelta, vdelta). The scene file's `uv_scale`, `uv_offset`.
#include "candela/core/platform.h"
#include "candela/math/vec.h"

namespace candela {

struct UvTransform {
    Vec2f scale{1.0f, 1.0f};
    Vec2f offset{0.0f, 0.0f};

    CANDELA_HD Vec2f apply(Vec2f uv) const {
        return Vec2f(scale.x * uv.x + offset.x, scale.y * uv.y + offset.y);
    }
};

}  // namespace candela
