#pragma once
// Moving instances (motion blur): an instance whose placement changes over the shutter, traced by
// Embree's quaternion motion blur (rtcSetGeometryTransformQuaternion). The placement at time t is
// path.at(t) * placement: pbrt-v4's AnimatedTransform (math/animated_transform.h: translation and
// scale/shear interpolated linearly, rotation by slerp) times a fixed map from the object's space
// into the path's (the inverse start transform for a moving shape, whose geometry the loader has
// already placed at its start; the identity for a moving instance).
//
// Embree interpolates keys of the form p -> translation + R(q) (U p + shift), U upper triangular:
// translation, U and shift linearly and q by slerp. When the path's scale/shear is the same at both
// ends and its times contain the shutter, two keys (at the shutter's opening and close) give
// pbrt-v4's motion exactly: R(t) S P = R(t) Q U (QR of the constant S P), and R(t) Q is the slerp
// of R(open) Q and R(close) Q. Otherwise (a scale that changes, a motion that starts or stops
// within the shutter) kMotionSegments segments of keys sampled from the path approximate it.
// Hits are made with the transform Embree's interpolation gives (MotionKeys::at), not the path's,
// so that a hit point and the surface the next ray sees agree.
#include <array>
#include <cstdint>
#include <vector>

#include "candela/geometry/instance.h"
#include "candela/math/animated_transform.h"
#include "candela/math/transform.h"

namespace candela {

// Segments of the keys where two keys cannot be exact.
inline constexpr int kMotionSegments = 16;

// A moving instance's placement over time (scene data, independent of the shutter).
struct InstanceMotion {
    AnimatedTransform path;  // affine, invertible, of one handedness at both ends (the loader checks)
    Transform placement;     // the object's space into the path's
};

// One key in Embree's form.
struct MotionKey {
    Vec3d translation;
    Quaternion rotation;
    double upper[3][3] = {};  // upper triangular: scale on the diagonal, skew above
    Vec3d shift;
};

// The keys of a motion over the shutter: uniformly spaced, the first at the shutter's opening and
// the last at its close; Embree's ray time u in [0, 1] runs over them.
struct MotionKeys {
    std::vector<MotionKey> keys;
    // The placement (object to world) at ray time u, as Embree interpolates the keys: the segment
    // of u, its components linearly and the rotation along the shorter arc (normalized linear
    // interpolation when the rotations are within Embree's threshold, cos > 0.9995, slerp beyond).
    Transform at(float u) const;
};

MotionKeys make_motion_keys(const InstanceMotion& motion, const std::array<double, 2>& shutter);

// `instance` placed at ray time u by `keys` (both matrices in float, as make_instance makes them).
Instance instance_at(const Instance& instance, const MotionKeys& keys, float u);

}  // namespace candela
