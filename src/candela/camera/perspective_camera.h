#pragma once
// A pinhole camera. Film positions are in pixels: x grows to the right, y downward, (0, 0) the
// top-left corner of the image. Right-handed: image right = normalize(cross(forward, up)).
#include "candela/camera/camera_frame.h"
#include "candela/camera/camera_model.h"
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/ray.h"

namespace candela {

class PerspectiveCamera {
  public:
    // The settings must be valid (the scene loader checks them): look_at != position, up not
    // parallel to the view direction, 0 < fov < 180. The lens settings are not read.
    explicit PerspectiveCamera(const CameraSettings& settings)
        : frame_(settings), screen_(settings, perspective_screen_window(settings)), near_(settings.near),
          width_(settings.width), height_(settings.height) {}

    // The ray through continuous film position `film` (pixels); unit direction, starting `near`
    // along it.
    CANDELA_HD Ray generate_ray(const Vec2f& film) const {
        Vec2f s = screen_(film);
        Vec3f d = normalize(frame_.forward + frame_.right * s.x + frame_.up * s.y);
        return Ray{frame_.position + d * near_, d, 0.0f, kInfinity};
    }
    // A pinhole has no lens: the sampler is not asked for anything.
    CANDELA_HD Ray generate_ray(const Vec2f& film, Sampler&) const { return generate_ray(film); }

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    CameraFrame frame_;
    FilmToScreen screen_;  // onto the plane at distance 1: tangents of the half angles
    float near_;
    int width_, height_;
};
static_assert(CameraModel<PerspectiveCamera>);

}  // namespace candela
