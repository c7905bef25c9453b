#pragma once
// Transforms of the scene file (affine, or projective where a format allows), kept in double (they are applied once, at load time).
// Points and vectors transform by the matrix, normals by its inverse transpose.
#include <array>

#include "candela/math/vec.h"

namespace candela {

class Transform {
  public:
    using Matrix = std::array<std::array<double, 4>, 4>;  // row-major; m[row][col]

    Transform();  // identity
    // Any m is accepted; check invertible() before relying on inverse() or apply_normal().
    explicit Transform(const Matrix& m);

    static Transform translate(const Vec3d& t);
    static Transform scale(const Vec3d& s);
    // Rotation by angle (radians) about axis (any nonzero length), counter-clockwise when the axis
    // points at the viewer (right-handed).
    static Transform rotate(const Vec3d& axis, double angle_radians);

    // The transform that applies `first`, then `*this`.
    Transform operator*(const Transform& first) const;
    Transform inverse() const;

    Vec3d apply_point(const Vec3d& p) const;
    Vec3d apply_vector(const Vec3d& v) const;
    // Not normalized: a normal transforms by the inverse transpose of the linear part.
    Vec3d apply_normal(const Vec3d& n) const;
    Vec3f apply_point(const Vec3f& p) const { return Vec3f(apply_point(Vec3d(p))); }
    Vec3f apply_vector(const Vec3f& v) const { return Vec3f(apply_vector(Vec3d(v))); }
    Vec3f apply_normal(const Vec3f& n) const { return Vec3f(apply_normal(Vec3d(n))); }

    // Determinant of the upper-left 3x3 (linear) part.
    double determinant() const;
    // True when the transform mirrors space (negative determinant): it reverses triangle winding.
    bool swaps_handedness() const { return determinant() < 0.0; }
    // False when the linear part is singular (a zero scale), nearly so (condition number > 1e12),
    // or not finite.
    bool invertible() const;
    bool is_identity() const;
    // True when the last row is [0, 0, 0, 1]; otherwise the transform is projective (points are
    // divided by w, vectors and normals take the upper 3x3 of the matrix and of its inverse).
    bool is_affine() const { return m_[3][0] == 0.0 && m_[3][1] == 0.0 && m_[3][2] == 0.0 && m_[3][3] == 1.0; }

    const Matrix& matrix() const { return m_; }

  private:
    Matrix m_;
    Matrix inv_;
};

}  // namespace candela
