#include "candela/camera/moving_camera.h"

#include "candela/camera/camera_frame.h"

namespace candela {

Transform world_from_camera(const CameraBasis& b) {
    const Vec3d r(b.right), u(b.up), p(b.position);
    // A look_at frame (right = forward x up) is a mirror as the columns right, up, forward: the
    // rotation of the decomposition must be proper (a quaternion), so such a frame is written with
    // the backward axis instead; both ends of a motion have the same handedness (the loader checks).
    const Vec3d f = dot(cross(r, u), Vec3d(b.forward)) < 0.0 ? -Vec3d(b.forward) : Vec3d(b.forward);
    return Transform(Transform::Matrix{{{r.x, u.x, f.x, p.x}, {r.y, u.y, f.y, p.y}, {r.z, u.z, f.z, p.z}, {0, 0, 0, 1}}});
}

namespace {

CameraBasis start_basis(const CameraSettings& s) {
    const CameraFrame f(s);
    return {f.position, f.right, f.up, f.forward};
}

}  // namespace

MovingCamera::MovingCamera(const CameraSettings& settings)
    : still_(make_static_camera(settings)), moves_(settings.motion.has_value()), shutter_(settings.shutter),
      width_(settings.width), height_(settings.height) {
    if (!moves_) return;
    const Transform start = world_from_camera(start_basis(settings));
    camera_from_start_ = start.inverse();
    world_from_camera_ = AnimatedTransform(start, settings.motion->start_time, world_from_camera(settings.motion->end),
                                           settings.motion->end_time);
}

Ray MovingCamera::generate_ray(const Vec2f& film, double time, Sampler& sampler) const {
    Ray ray = visit([&](const auto& camera) { return camera.generate_ray(film, sampler); }, still_);
    ray.time = float((time - shutter_[0]) / (shutter_[1] - shutter_[0]));
    if (!moves_) return ray;
    // From the start frame to the frame at `time`; double, as the frames are, so that a time at
    // the start gives back the still camera's ray to float precision.
    const Transform moved = world_from_camera_.at(time) * camera_from_start_;
    ray.o = Vec3f(moved.apply_point(Vec3d(ray.o)));
    ray.d = Vec3f(normalize(moved.apply_vector(Vec3d(ray.d))));
    return ray;
}

}  // namespace candela
