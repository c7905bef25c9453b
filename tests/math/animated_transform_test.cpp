// AnimatedTransform against closed forms: a translation moves linearly, a rotation about an axis
// by theta is a rotation by t theta at time t (a blend of matrices would shrink it), scale blends
// linearly, and decomposition recomposes to the matrix it came from.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/math/animated_transform.h"
#include "candela/math/constants.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr double kTol = 1e-9;

::testing::AssertionResult matrix_near(const Transform& a, const Transform& b, double tol = kTol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!(std::abs(a.matrix()[i][j] - b.matrix()[i][j]) <= tol))
                return ::testing::AssertionFailure()
                       << "m[" << i << "][" << j << "]: " << a.matrix()[i][j] << " != " << b.matrix()[i][j];
    return ::testing::AssertionSuccess();
}

TEST(AnimatedTransform, TranslationIsLinearInTime) {
    const AnimatedTransform a(Transform::translate({1, 2, 3}), 2.0, Transform::translate({5, -2, 0}), 4.0);
    ASSERT_TRUE(a.animated());
    for (double time : {2.0, 2.5, 3.0, 3.7, 4.0}) {
        const double t = (time - 2.0) / 2.0;
        EXPECT_TRUE(matrix_near(a.at(time), Transform::translate({1 + 4 * t, 2 - 4 * t, 3 - 3 * t}))) << time;
    }
}

TEST(AnimatedTransform, ClampsOutsideItsTimes) {
    const AnimatedTransform a(Transform::translate({1, 0, 0}), 0.0, Transform::translate({3, 0, 0}), 1.0);
    EXPECT_EQ(a.at(-1.0).matrix(), a.start().matrix());
    EXPECT_EQ(a.at(2.0).matrix(), a.end().matrix());
}

TEST(AnimatedTransform, RotationAngleIsLinearInTime) {
    // 150 degrees about a tilted axis: at time t the transform is the rotation by t * 150 degrees.
    const Vec3d axis = normalize(Vec3d(1, 2, -0.5));
    const double theta = 150.0 * kPiD / 180.0;
    const AnimatedTransform a(Transform(), 0.0, Transform::rotate(axis, theta), 1.0);
    for (double t : {0.1, 0.25, 0.5, 0.8, 0.95})
        EXPECT_TRUE(matrix_near(a.at(t), Transform::rotate(axis, t * theta))) << t;
    // The control: halfway through, a linear blend of the matrices is not a rotation (it shrinks
    // points off the axis), so the test above can tell the two apart.
    const Vec3d p = normalize(cross(axis, Vec3d(0, 0, 1)));
    const Vec3d blended = (p + Transform::rotate(axis, theta).apply_point(p)) * 0.5;
    EXPECT_LT(length(blended), 0.3);
    EXPECT_NEAR(length(a.at(0.5).apply_point(p)), 1.0, kTol);
}

TEST(AnimatedTransform, RotationTakesTheShorterArc) {
    // From +100 to -100 degrees about z is 160 degrees the short way (through 180), not 200.
    const Vec3d z(0, 0, 1);
    const double d = kPiD / 180.0;
    const AnimatedTransform a(Transform::rotate(z, 100 * d), 0.0, Transform::rotate(z, -100 * d), 1.0);
    EXPECT_TRUE(matrix_near(a.at(0.5), Transform::rotate(z, 180 * d)));
    EXPECT_TRUE(matrix_near(a.at(0.25), Transform::rotate(z, 140 * d)));
}

TEST(AnimatedTransform, ScaleTranslationAndRotationInterpolateSeparately) {
    const Vec3d axis(0, 1, 0);
    const Transform start = Transform::translate({0, 0, 0}) * Transform::scale({1, 1, 1});
    const Transform end =
        Transform::translate({2, 4, 6}) * Transform::rotate(axis, kPiD / 2) * Transform::scale({3, 1, 5});
    const AnimatedTransform a(start, 0.0, end, 1.0);
    const double t = 0.3;
    const Transform expected = Transform::translate({2 * t, 4 * t, 6 * t}) * Transform::rotate(axis, t * kPiD / 2) *
                               Transform::scale({1 + 2 * t, 1, 1 + 4 * t});
    EXPECT_TRUE(matrix_near(a.at(t), expected));
}

TEST(Decompose, RecomposesTheMatrix) {
    // Rotation, non-uniform scale and shear: T * R * S gives back M, R is orthonormal, S symmetric.
    Transform::Matrix shear = Transform().matrix();
    shear[0][1] = 0.4;
    shear[2][0] = -0.3;
    const Transform m = Transform::translate({1, -2, 0.5}) * Transform::rotate(Vec3d(1, 1, 0), 0.7) *
                        Transform::scale({2, 0.5, 1.5}) * Transform(shear);
    const Decomposition d = decompose(m);
    const Transform r(d.rotation), s(d.scale);
    EXPECT_TRUE(matrix_near(Transform::translate(d.translation) * r * s, m, 1e-12));
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // The iteration stops at pbrt-v4's threshold (row change <= 1e-4); it converges
            // quadratically, so the step before is far below it.
            double rrt = 0;
            for (int k = 0; k < 3; ++k) rrt += d.rotation[i][k] * d.rotation[j][k];
            EXPECT_NEAR(rrt, i == j ? 1.0 : 0.0, 1e-8);
            EXPECT_NEAR(d.scale[i][j], d.scale[j][i], 1e-8);
        }
}

TEST(Quaternion, RoundTripsRotations) {
    // Every branch of the conversion: positive trace, and each diagonal element the largest.
    for (const auto& [axis, angle] : {std::pair{Vec3d(0, 0, 1), 0.3}, std::pair{Vec3d(1, 0, 0), 3.0},
                                      std::pair{Vec3d(0, 1, 0), 3.0}, std::pair{Vec3d(0, 0, 1), 3.0},
                                      std::pair{Vec3d(1, -2, 3), 2.5}}) {
        const Transform r = Transform::rotate(axis, angle);
        const Quaternion q = quaternion_from_rotation(r.matrix());
        EXPECT_NEAR(dot(q, q), 1.0, 1e-12);
        EXPECT_TRUE(matrix_near(rotation_from_quaternion(q), r, 1e-12));
    }
}

TEST(AnimatedTransform, EqualEndsAreNotAnimated) {
    const Transform m = Transform::rotate(Vec3d(0, 1, 0), 1.0);
    const AnimatedTransform a(m, 0.0, m, 1.0);
    EXPECT_FALSE(a.animated());
    EXPECT_EQ(a.at(0.5).matrix(), m.matrix());
}

}  // namespace
}  // namespace candela
