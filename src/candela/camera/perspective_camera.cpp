#include "candela/camera/perspective_camera.h"

#include <cmath>

#include "candela/math/constants.h"

namespace candela {

PerspectiveCamera::PerspectiveCamera(const CameraSettings& s)
    : position_(s.position),
      forward_(normalize(s.look_at - s.position)),
      right_(normalize(cross(forward_, s.up))),
      up_(cross(right_, forward_)),
      half_height_(std::tan(0.5f * radians(s.fov_degrees))),
      inv_width_(1.0f / float(s.width)),
      inv_height_(1.0f / float(s.height)),
      near_(s.near),
      width_(s.width),
      height_(s.height) {
    // Square pixels: the horizontal extent follows the aspect ratio.
    half_width_ = half_height_ * float(s.width) / float(s.height);
}

}  // namespace candela
