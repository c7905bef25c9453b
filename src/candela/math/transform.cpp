#include "candela/math/transform.h"

#include <cmath>

#include "candela/math/constants.h"

namespace candela {

namespace {
using Matrix = Transform::Matrix;

Matrix identity_matrix() {
    Matrix m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1.0;
    return m;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

// Gauss-Jordan elimination with partial pivoting. A singular matrix yields NaNs, which
// Transform::invertible() reports.
Matrix invert(const Matrix& m) {
    Matrix a = m;
    Matrix inv = identity_matrix();
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        std::swap(inv[col], inv[pivot]);
        double p = a[col][col];
        if (p == 0.0) {
            Matrix nan{};
            for (auto& row : nan) row.fill(std::nan(""));
            return nan;
        }
        for (int j = 0; j < 4; ++j) {
            a[col][j] /= p;
            inv[col][j] /= p;
        }
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            double f = a[r][col];
            for (int j = 0; j < 4; ++j) {
                a[r][j] -= f * a[col][j];
                inv[r][j] -= f * inv[col][j];
            }
        }
    }
    return inv;
}
}  // namespace

Transform::Transform() : m_(identity_matrix()), inv_(identity_matrix()) {}

Transform::Transform(const Matrix& m) : m_(m), inv_(invert(m)) {}

Transform Transform::translate(const Vec3d& t) {
    Matrix m = identity_matrix();
    m[0][3] = t.x;
    m[1][3] = t.y;
    m[2][3] = t.z;
    return Transform(m);
}

Transform Transform::scale(const Vec3d& s) {
    Matrix m = identity_matrix();
    m[0][0] = s.x;
    m[1][1] = s.y;
    m[2][2] = s.z;
    return Transform(m);
}

// Rodrigues' rotation formula as a matrix (pbrt-v4's Rotate).
Transform Transform::rotate(const Vec3d& axis, double angle) {
    Vec3d a = normalize(axis);
    double s = std::sin(angle), c = std::cos(angle);
    Matrix m = identity_matrix();
    m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
    m[0][1] = a.x * a.y * (1 - c) - a.z * s;
    m[0][2] = a.x * a.z * (1 - c) + a.y * s;
    m[1][0] = a.x * a.y * (1 - c) + a.z * s;
    m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
    m[1][2] = a.y * a.z * (1 - c) - a.x * s;
    m[2][0] = a.x * a.z * (1 - c) - a.y * s;
    m[2][1] = a.y * a.z * (1 - c) + a.x * s;
    m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
    return Transform(m);
}

Transform Transform::operator*(const Transform& first) const {
    Transform t;
    t.m_ = multiply(m_, first.m_);
    t.inv_ = multiply(first.inv_, inv_);
    return t;
}

Transform Transform::inverse() const {
    Transform t;
    t.m_ = inv_;
    t.inv_ = m_;
    return t;
}

Vec3d Transform::apply_point(const Vec3d& p) const {
    Vec3d r;
    for (int i = 0; i < 3; ++i) r[i] = m_[i][0] * p.x + m_[i][1] * p.y + m_[i][2] * p.z + m_[i][3];
    double w = m_[3][0] * p.x + m_[3][1] * p.y + m_[3][2] * p.z + m_[3][3];
    return w == 1.0 ? r : r / w;
}

Vec3d Transform::apply_vector(const Vec3d& v) const {
    Vec3d r;
    for (int i = 0; i < 3; ++i) r[i] = m_[i][0] * v.x + m_[i][1] * v.y + m_[i][2] * v.z;
    return r;
}

Vec3d Transform::apply_normal(const Vec3d& n) const {
    // (M^-1)^T n: column i of the inverse dotted with n.
    Vec3d r;
    for (int i = 0; i < 3; ++i) r[i] = inv_[0][i] * n.x + inv_[1][i] * n.y + inv_[2][i] * n.z;
    return r;
}

double Transform::determinant() const {
    const Matrix& m = m_;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Transform::invertible() const {
    double det = determinant();
    if (!std::isfinite(det) || det == 0.0) return false;
    for (const auto& row : inv_)
        for (double v : row)
            if (!std::isfinite(v)) return false;
    // A singular matrix rarely stays exactly singular once rounded: a rotated rank-2 matrix has a
    // determinant of ~1e-14 and a finite inverse of ~1e16. Its condition number
    // |M| |M^-1| (Frobenius, linear part) is ~1/epsilon = 1e16 or more; any sensible scene
    // transform's is far below 1e12, whatever its overall scale.
    constexpr double kMaxCondition = 1e12;
    double norm2 = 0.0, inv_norm2 = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            norm2 += sqr(m_[i][j]);
            inv_norm2 += sqr(inv_[i][j]);
        }
    return std::sqrt(norm2) * std::sqrt(inv_norm2) < kMaxCondition;
}

bool Transform::is_identity() const { return m_ == identity_matrix(); }

}  // namespace candela
