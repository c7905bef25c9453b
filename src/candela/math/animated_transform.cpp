#include "candela/math/animated_transform.h"

#include <algorithm>
#include <cmath>

#include "candela/math/constants.h"

namespace candela {

namespace {

using Matrix = Transform::Matrix;

Matrix transpose(const Matrix& m) {
    Matrix t{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) t[i][j] = m[j][i];
    return t;
}

Quaternion operator*(const Quaternion& q, double s) { return {q.v * s, q.w * s}; }
Quaternion operator+(const Quaternion& a, const Quaternion& b) { return {a.v + b.v, a.w + b.w}; }
Quaternion operator-(const Quaternion& a, const Quaternion& b) { return {a.v - b.v, a.w - b.w}; }
double length(const Quaternion& q) { return std::sqrt(dot(q, q)); }

double safe_asin(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }
// sin(x) / x, exact at 0 (the slerp of two equal rotations).
double sin_x_over_x(double x) { return 1.0 + x * x == 1.0 ? 1.0 : std::sin(x) / x; }

// The angle between two unit 4-vectors, accurate near 0 and pi (the acos of the dot is not).
double angle_between(const Quaternion& a, const Quaternion& b) {
    if (dot(a, b) < 0.0) return kPiD - 2.0 * safe_asin(length(a + b) / 2.0);
    return 2.0 * safe_asin(length(b - a) / 2.0);
}

bool same_matrix(const Transform& a, const Transform& b) { return a.matrix() == b.matrix(); }

}  // namespace

double dot(const Quaternion& a, const Quaternion& b) { return dot(a.v, b.v) + a.w * b.w; }

Quaternion quaternion_from_rotation(const Matrix& m) {
    // Shoemake's method: from the trace when it is positive (w is then the largest component),
    // else from the largest diagonal element, so that no division is by a small number.
    const double trace = m[0][0] + m[1][1] + m[2][2];
    Quaternion q;
    if (trace > 0.0) {
        double s = std::sqrt(trace + 1.0);
        q.w = s / 2.0;
        s = 0.5 / s;
        q.v = {(m[2][1] - m[1][2]) * s, (m[0][2] - m[2][0]) * s, (m[1][0] - m[0][1]) * s};
        return q;
    }
    const int next[3] = {1, 2, 0};
    int i = 0;
    if (m[1][1] > m[0][0]) i = 1;
    if (m[2][2] > m[i][i]) i = 2;
    const int j = next[i], k = next[j];
    double s = std::sqrt(std::max(0.0, (m[i][i] - (m[j][j] + m[k][k])) + 1.0));
    double c[3];
    c[i] = s * 0.5;
    if (s != 0.0) s = 0.5 / s;
    q.w = (m[k][j] - m[j][k]) * s;
    c[j] = (m[j][i] + m[i][j]) * s;
    c[k] = (m[k][i] + m[i][k]) * s;
    q.v = {c[0], c[1], c[2]};
    return q;
}

Transform rotation_from_quaternion(const Quaternion& q) {
    const double xx = q.v.x * q.v.x, yy = q.v.y * q.v.y, zz = q.v.z * q.v.z;
    const double xy = q.v.x * q.v.y, xz = q.v.x * q.v.z, yz = q.v.y * q.v.z;
    const double wx = q.v.x * q.w, wy = q.v.y * q.w, wz = q.v.z * q.w;
    Matrix m = Transform().matrix();
    m[0][0] = 1.0 - 2.0 * (yy + zz);
    m[0][1] = 2.0 * (xy - wz);
    m[0][2] = 2.0 * (xz + wy);
    m[1][0] = 2.0 * (xy + wz);
    m[1][1] = 1.0 - 2.0 * (xx + zz);
    m[1][2] = 2.0 * (yz - wx);
    m[2][0] = 2.0 * (xz - wy);
    m[2][1] = 2.0 * (yz + wx);
    m[2][2] = 1.0 - 2.0 * (xx + yy);
    return Transform(m);
}

Quaternion slerp(double t, const Quaternion& a, const Quaternion& b) {
    // sin((1-t) theta) / sin(theta) written with sin(x)/x, which stays exact as theta -> 0.
    const double theta = angle_between(a, b);
    const double inv = 1.0 / sin_x_over_x(theta);
    return a * ((1.0 - t) * sin_x_over_x((1.0 - t) * theta) * inv) + b * (t * sin_x_over_x(t * theta) * inv);
}

Decomposition decompose(const Transform& transform) {
    const Matrix& m = transform.matrix();
    Decomposition d;
    d.translation = {m[0][3], m[1][3], m[2][3]};
    Matrix linear = m;
    for (int i = 0; i < 3; ++i) linear[i][3] = linear[3][i] = 0.0;
    linear[3][3] = 1.0;
    // Polar decomposition: the average of R and its inverse transpose converges to the orthonormal
    // factor (Higham's Newton iteration); the stopping rule is pbrt-v4's, so both stop at the same
    // step on the same input.
    Matrix r = linear;
    for (int count = 0; count < 100; ++count) {
        const Matrix r_inv_t = transpose(Transform(r).inverse().matrix());
        Matrix next{};
        double norm = 0.0;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) next[i][j] = (r[i][j] + r_inv_t[i][j]) / 2.0;
        for (int i = 0; i < 3; ++i)
            norm = std::max(norm, std::abs(r[i][0] - next[i][0]) + std::abs(r[i][1] - next[i][1]) +
                                      std::abs(r[i][2] - next[i][2]));
        r = next;
        if (!(norm > 1e-4)) break;
    }
    d.rotation = r;
    d.scale = (Transform(r).inverse() * Transform(linear)).matrix();
    return d;
}

AnimatedTransform::AnimatedTransform(const Transform& start, double start_time, const Transform& end,
                                     double end_time)
    : start_(start), end_(end), start_time_(start_time), end_time_(end_time), animated_(!same_matrix(start, end)) {
    if (!animated_) return;
    const Transform* ends[2] = {&start_, &end_};
    for (int i = 0; i < 2; ++i) {
        const Decomposition d = decompose(*ends[i]);
        translation_[i] = d.translation;
        rotation_[i] = quaternion_from_rotation(d.rotation);
        scale_[i] = d.scale;
    }
    // q and -q are the same rotation: take the one on the shorter arc.
    if (dot(rotation_[0], rotation_[1]) < 0.0) rotation_[1] = rotation_[1] * -1.0;
}

Transform AnimatedTransform::at(double time) const {
    if (!animated_ || time <= start_time_) return start_;
    if (time >= end_time_) return end_;
    const Components c = components(time);
    return Transform::translate(c.translation) * rotation_from_quaternion(c.rotation) * Transform(c.scale);
}

AnimatedTransform::Components AnimatedTransform::components(double time) const {
    if (!animated_) {
        const Decomposition d = decompose(start_);
        return {d.translation, quaternion_from_rotation(d.rotation), d.scale};
    }
    const double t = std::clamp((time - start_time_) / (end_time_ - start_time_), 0.0, 1.0);
    Components c;
    c.translation = translation_[0] * (1.0 - t) + translation_[1] * t;
    c.rotation = slerp(t, rotation_[0], rotation_[1]);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) c.scale[i][j] = (1.0 - t) * scale_[0][i][j] + t * scale_[1][i][j];
    return c;
}

}  // namespace candela
