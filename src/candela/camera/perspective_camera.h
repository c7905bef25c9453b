#pragma once
// A pinhole camera. Film positions are in pixels: x grows to the right, y downward, (0, 0) the
// top-left corner of the image. Right-handed: image right = normalize(cross(forward, up)).
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/ray.h"

namespace candela {

class PerspectiveCamera {
  public:
    // The settings must be valid (the scene loader checks them): look_at != position, up not
    // parallel to the view direction, 0 < fov < 180.
    explicit PerspectiveCamera(const CameraSettings& settings);

    // The ray through continuous film position `film` (pixels); unit direction, starting `near`
    // along it.
    CANDELA_HD Ray generate_ray(const Vec2f& film) const {
        float sx = (2.0f * film.x * inv_width_ - 1.0f) * half_width_;
        float sy = (1.0f - 2.0f * film.y * inv_height_) * half_height_;
        Vec3f d = normalize(forward_ + right_ * sx + up_ * sy);
        return Ray{position_ + d * near_, d, 0.0f, kInfinity};
    }

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    Vec3f position_, forward_, right_, up_;
    float half_width_, half_height_;  // tangent of the half angles
    float inv_width_, inv_height_;
    float near_;
    int width_, height_;
};

}  // namespace candela
