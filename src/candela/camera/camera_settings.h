#pragma once
// The camera of the scene file (DESIGN.md: right-handed, vertical fov, image y downward).
#include "candela/math/vec.h"

namespace candela {

struct CameraSettings {
    Vec3f position{0, 0, 0};
    Vec3f look_at{0, 0, -1};
    Vec3f up{0, 1, 0};
    float fov_degrees = 40.0f;  // vertical
    int width = 512;
    int height = 512;
    float near = 0.0f;  // camera rays start this far along their direction
};

}  // namespace candela
