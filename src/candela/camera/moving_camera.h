#pragma once
// A camera in a scene where something moves during the shutter (motion blur): the camera, or
// shapes (geometry/instance_motion.h). Each sample draws its time t uniformly in the shutter
// (pbrt-v4's CameraBase::SampleTime), which the ray carries (Ray::time, as a fraction of the
// shutter) to the shapes it meets; the still camera makes its ray at the start frame, and if the
// camera moves the ray is carried to the frame at t: world_from_camera(t) * camera_from_world(start).
// Only scenes where something moves pay for it: the still cameras are separate alternatives.
#include "candela/camera/camera_model.h"
#include "candela/camera/camera_settings.h"
#include "candela/camera/static_camera.h"
#include "candela/math/animated_transform.h"
#include "candela/math/ray.h"
#include "candela/sampling/sampler.h"

namespace candela {

// The matrix of a camera frame (camera space to world): columns right, up, forward and position,
// or backward in place of forward when that makes the frame right-handed.
Transform world_from_camera(const CameraBasis& basis);

class MovingCamera {
  public:
    // The camera of `settings`, moving if settings.motion is set (else only its rays' times vary).
    explicit MovingCamera(const CameraSettings& settings);

    // The time of shutter sample u in [0, 1).
    double time(float u) const { return shutter_[0] + double(u) * (shutter_[1] - shutter_[0]); }
    // The ray of film position `film` at `time`; a lens point from `sampler` if the camera has a lens.
    Ray generate_ray(const Vec2f& film, double time, Sampler& sampler) const;
    // Draws the time (one 1D request), then as the still camera (its lens point).
    Ray generate_ray(const Vec2f& film, Sampler& sampler) const {
        const double t = time(sampler.next_float());
        return generate_ray(film, t, sampler);
    }

    int width() const { return width_; }
    int height() const { return height_; }

  private:
    StaticCamera still_;       // at the start frame
    Transform camera_from_start_;  // world to camera space, at the start frame
    AnimatedTransform world_from_camera_;
    bool moves_ = false;  // settings.motion: the frame changes over the shutter
    std::array<double, 2> shutter_;
    int width_, height_;
};
static_assert(CameraModel<MovingCamera>);

}  // namespace candela
