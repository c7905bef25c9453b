#pragma once
// Geometry for the camera tests: where a camera ray meets a plane perpendicular to the view, and
// which film position sees a given point through a given lens point.
#include <gtest/gtest.h>

#include "candela/camera/camera.h"
#include "candela/camera/camera_frame.h"

namespace candela::test {

// The point where `ray` meets the plane `depth` along the frame's view direction (in double: the
// tests measure the camera's float rays, not their own rounding).
inline Vec3d hit_at_depth(const Ray& ray, const CameraFrame& frame, double depth) {
    const Vec3d o(ray.o), d(ray.d), f(frame.forward);
    const double t = (depth - dot(o - Vec3d(frame.position), f)) / dot(d, f);
    return o + d * t;
}

// The continuous film position (pixels) whose ray through lens sample `u_lens` passes through
// `p`. Where a ray meets the plane of p (perpendicular to the view) is an affine function of the
// film position for every camera here, so three rays determine it; the caller checks the answer.
template <class CameraT>
Vec2f film_position_seeing(const CameraT& camera, const CameraFrame& frame, const Vec3d& p, Vec2f u_lens,
                           int width, int height) {
    const double depth = dot(p - Vec3d(frame.position), Vec3d(frame.forward));
    auto lateral = [&](Vec2f film) {
        const Vec3d q = hit_at_depth(camera.generate_ray(film, u_lens), frame, depth) - Vec3d(frame.position);
        return Vec2<double>(dot(q, Vec3d(frame.right)), dot(q, Vec3d(frame.up)));
    };
    const Vec2<double> g0 = lateral({0, 0});
    const Vec2<double> gx = (lateral({float(width), 0}) - g0) * (1.0 / width);
    const Vec2<double> gy = (lateral({0, float(height)}) - g0) * (1.0 / height);
    const Vec3d q = p - Vec3d(frame.position);
    const Vec2<double> b = Vec2<double>(dot(q, Vec3d(frame.right)), dot(q, Vec3d(frame.up))) - g0;
    // Solve [gx gy] f = b by Cramer's rule.
    const double det = gx.x * gy.y - gy.x * gx.y;
    return {float((b.x * gy.y - gy.x * b.y) / det), float((gx.x * b.y - b.x * gx.y) / det)};
}

}  // namespace candela::test
