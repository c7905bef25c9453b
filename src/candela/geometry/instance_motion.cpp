#include "candela/geometry/instance_motion.h"

#include <algorithm>
#include <cmath>

#include "candela/core/check.h"

namespace candela {

namespace {

using Matrix = Transform::Matrix;

// Embree's threshold (its quaternion slerp): closer rotations are interpolated linearly and
// normalized.
constexpr double kNlerpCosine = 0.9995;

Quaternion scaled(const Quaternion& q, double s) { return {q.v * s, q.w * s}; }

Quaternion normalized(const Quaternion& q) { return scaled(q, 1.0 / std::sqrt(dot(q, q))); }

// True when the scale/shear parts agree to a relative 1e-9 (the polar decomposition of two ends
// with the same scale gives the same matrix to about that: it stops at a change of 1e-4, after
// which the iteration converges quadratically).
bool same_scale(const Matrix& a, const Matrix& b) {
    double size = 0.0, diff = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            size = std::max(size, std::abs(a[i][j]));
            diff = std::max(diff, std::abs(a[i][j] - b[i][j]));
        }
    return diff <= 1e-9 * size;
}

// The key of the placement translate(c.translation) R(c.rotation) c.scale `placement`: the linear
// part of N = scale * placement factored as Q U (Gram-Schmidt on its columns, Q a rotation), so
// that the key's rotation is R Q, its U is U and its shift Q^T N's translation.
MotionKey make_key(const AnimatedTransform::Components& c, const Transform& placement) {
    const Matrix n = (Transform(c.scale) * placement).matrix();
    Vec3d col[3], q[3];
    for (int j = 0; j < 3; ++j) col[j] = Vec3d(n[0][j], n[1][j], n[2][j]);
    MotionKey key;
    auto& u = key.upper;
    for (int j = 0; j < 3; ++j) {
        Vec3d v = col[j];
        for (int i = 0; i < j; ++i) {
            u[i][j] = dot(q[i], col[j]);
            v = v - q[i] * u[i][j];
        }
        u[j][j] = length(v);
        q[j] = v / u[j][j];
    }
    // A mirroring N (the loader lets none through, but rounding must not flip Q): the last axis
    // carries the sign in U, so that Q stays a rotation.
    if (dot(cross(q[0], q[1]), q[2]) < 0.0) {
        q[2] = -q[2];
        u[2][2] = -u[2][2];
    }
    const Matrix r = rotation_from_quaternion(c.rotation).matrix();
    Matrix rq = Transform().matrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rq[i][j] = r[i][0] * q[j].x + r[i][1] * q[j].y + r[i][2] * q[j].z;
    key.rotation = quaternion_from_rotation(rq);
    const Vec3d t(n[0][3], n[1][3], n[2][3]);
    key.shift = Vec3d(dot(q[0], t), dot(q[1], t), dot(q[2], t));
    key.translation = c.translation;
    return key;
}

}  // namespace

MotionKeys make_motion_keys(const InstanceMotion& motion, const std::array<double, 2>& shutter) {
    CANDELA_CHECK(shutter[1] > shutter[0]);
    AnimatedTransform path = motion.path;
    Transform placement = motion.placement;
    // A mirroring path has no rotation for a quaternion (pbrt-v4's decomposition leaves the mirror
    // in it): the mirror moves into the placement, which the keys' U then carries.
    if (path.start().swaps_handedness()) {
        const Transform mirror = Transform::scale(Vec3d(-1.0, 1.0, 1.0));
        path = AnimatedTransform(path.start() * mirror, path.start_time(), path.end() * mirror, path.end_time());
        placement = mirror * placement;
    }
    const AnimatedTransform::Components open = path.components(shutter[0]), close = path.components(shutter[1]);
    const bool exact = path.start_time() <= shutter[0] && path.end_time() >= shutter[1] &&
                       same_scale(open.scale, close.scale);
    const int segments = exact ? 1 : kMotionSegments;
    MotionKeys keys;
    for (int k = 0; k <= segments; ++k) {
        const double t = shutter[0] + (shutter[1] - shutter[0]) * double(k) / double(segments);
        keys.keys.push_back(make_key(k == 0 ? open : k == segments ? close : path.components(t), placement));
    }
    return keys;
}

Transform MotionKeys::at(float u) const {
    const int segments = int(keys.size()) - 1;
    const double s = double(std::clamp(u, 0.0f, 1.0f)) * double(segments);
    const int k = std::clamp(int(std::floor(s)), 0, segments - 1);
    const double f = s - double(k);
    const MotionKey &a = keys[size_t(k)], &b = keys[size_t(k) + 1];
    Quaternion qb = b.rotation;
    double cosine = dot(a.rotation, qb);
    if (cosine < 0.0) {
        qb = scaled(qb, -1.0);
        cosine = -cosine;
    }
    const Quaternion q = cosine > kNlerpCosine
                             ? normalized({a.rotation.v * (1.0 - f) + qb.v * f, a.rotation.w * (1.0 - f) + qb.w * f})
                             : slerp(f, a.rotation, qb);
    Matrix upper = Transform().matrix();
    for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j) upper[i][j] = a.upper[i][j] * (1.0 - f) + b.upper[i][j] * f;
        upper[i][3] = a.shift[i] * (1.0 - f) + b.shift[i] * f;
    }
    const Vec3d translation = a.translation * (1.0 - f) + b.translation * f;
    return Transform::translate(translation) * rotation_from_quaternion(q) * Transform(upper);
}

Instance instance_at(const Instance& instance, const MotionKeys& keys, float u) {
    Instance placed = make_instance(instance.object, keys.at(u));
    placed.motion = instance.motion;
    return placed;
}

}  // namespace candela
