#pragma once
// A transform that moves over the shutter, interpolated as pbrt-v4's AnimatedTransform does: each
// end is decomposed into translation T, rotation R and scale/shear S (M = T R S, R from the polar
// decomposition of the linear part); T and S are interpolated linearly and R by quaternion slerp
// along the shortest arc. A linear blend of the matrices would shrink a rotating object midway.
#include "candela/math/transform.h"
#include "candela/math/vec.h"

namespace candela {

// A rotation as a unit quaternion (v, w) = (axis sin(theta/2), cos(theta/2)).
struct Quaternion {
    Vec3d v{0.0, 0.0, 0.0};
    double w = 1.0;
};

double dot(const Quaternion& a, const Quaternion& b);
// The quaternion of a rotation matrix (the upper 3x3 of r, which must be orthonormal, det +1).
Quaternion quaternion_from_rotation(const Transform::Matrix& r);
// The rotation matrix of a unit quaternion.
Transform rotation_from_quaternion(const Quaternion& q);
// Spherical interpolation from a (t = 0) to b (t = 1) along the great arc between them (no
// flip to the shorter arc: the caller chooses the sign of b).
Quaternion slerp(double t, const Quaternion& a, const Quaternion& b);

// M = translate(translation) * rotation * scale, for an affine M whose linear part is invertible.
struct Decomposition {
    Vec3d translation;
    Transform::Matrix rotation;  // orthonormal (a mirror stays in it, as in pbrt-v4)
    Transform::Matrix scale;     // symmetric: scale and shear
};
// Polar decomposition of the linear part by the iteration R <- (R + R^-T) / 2, as pbrt-v4
// (Transform::Decompose): at most 100 steps, until the rows change by <= 1e-4.
Decomposition decompose(const Transform& m);

class AnimatedTransform {
  public:
    AnimatedTransform() = default;  // identity, not moving
    explicit AnimatedTransform(const Transform& fixed) : start_(fixed), end_(fixed) {}
    // start_time < end_time; both transforms affine and invertible.
    AnimatedTransform(const Transform& start, double start_time, const Transform& end, double end_time);

    // False when the two ends are the same matrix: then at() is start() at every time.
    bool animated() const { return animated_; }
    // The transform at `time`: start() at or before start_time, end() at or after end_time.
    Transform at(double time) const;
    // The interpolated parts at `time`: at(time) is translate(translation) * rotation * scale.
    struct Components {
        Vec3d translation;
        Quaternion rotation;
        Transform::Matrix scale;
    };
    Components components(double time) const;

    const Transform& start() const { return start_; }
    const Transform& end() const { return end_; }
    double start_time() const { return start_time_; }
    double end_time() const { return end_time_; }

  private:
    Transform start_, end_;
    double start_time_ = 0.0, end_time_ = 1.0;
    bool animated_ = false;
    Vec3d translation_[2];
    Quaternion rotation_[2];
    Transform::Matrix scale_[2];
};

}  // namespace candela
