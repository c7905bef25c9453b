// Transforms against hand-computed values: right-handed rotations, composition order, inverses,
// handedness and the inverse-transpose rule for normals.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/math/constants.h"
#include "candela/math/transform.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr double kTol = 1e-12;
const double kQuarterTurn = kPiD / 2.0;

::testing::AssertionResult vec_eq(const Vec3d& a, const Vec3d& b, double tol = kTol) {
    if (std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") != (" << b.x
                                         << ", " << b.y << ", " << b.z << ") within " << tol;
}

::testing::AssertionResult matrix_eq(const Transform::Matrix& a, const Transform::Matrix& b,
                                     double tol = kTol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!(std::abs(a[i][j] - b[i][j]) <= tol))
                return ::testing::AssertionFailure()
                       << "m[" << i << "][" << j << "]: " << a[i][j] << " != " << b[i][j];
    return ::testing::AssertionSuccess();
}

const Transform::Matrix kIdentity = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

// A transform mixing every kind, so round trips exercise all of the matrix.
Transform general_transform() {
    return Transform::translate({1.5, -2.0, 0.25}) * Transform::rotate({1.0, 2.0, -0.5}, 0.7) *
           Transform::scale({2.0, 0.5, -3.0}) * Transform::rotate({0.0, 1.0, 1.0}, -1.1);
}

TEST(Transform, TranslateMovesPointsButNotVectorsOrNormals) {
    Transform t = Transform::translate({1.0, 2.0, 3.0});
    EXPECT_TRUE(vec_eq(t.apply_point(Vec3d(1.0, 1.0, 1.0)), {2.0, 3.0, 4.0}));
    EXPECT_TRUE(vec_eq(t.apply_vector(Vec3d(1.0, 1.0, 1.0)), {1.0, 1.0, 1.0}));
    EXPECT_TRUE(vec_eq(t.apply_normal(Vec3d(0.0, 0.0, 1.0)), {0.0, 0.0, 1.0}));
    Vec3f pf = t.apply_point(Vec3f(-1.0f, 0.0f, 0.5f));
    EXPECT_EQ(pf, Vec3f(0.0f, 2.0f, 3.5f));
}

TEST(Transform, ScaleScalesPointsAndVectorsAndDividesNormals) {
    Transform s = Transform::scale({2.0, 3.0, 4.0});
    EXPECT_TRUE(vec_eq(s.apply_point(Vec3d(1.0, -1.0, 0.5)), {2.0, -3.0, 2.0}));
    EXPECT_TRUE(vec_eq(s.apply_vector(Vec3d(1.0, 1.0, 1.0)), {2.0, 3.0, 4.0}));
    EXPECT_TRUE(vec_eq(s.apply_normal(Vec3d(1.0, 1.0, 1.0)), {0.5, 1.0 / 3.0, 0.25}));
}

TEST(Transform, RotateAboutYIsCounterClockwiseRightHanded) {
    Transform r = Transform::rotate({0.0, 1.0, 0.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(1.0, 0.0, 0.0)), {0.0, 0.0, -1.0}));
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(0.0, 0.0, 1.0)), {1.0, 0.0, 0.0}));
    EXPECT_TRUE(vec_eq(r.apply_point(Vec3d(1.0, 5.0, 0.0)), {0.0, 5.0, -1.0}));
    // The axis need not be unit length.
    Transform r5 = Transform::rotate({0.0, 5.0, 0.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(r5.apply_vector(Vec3d(1.0, 0.0, 0.0)), {0.0, 0.0, -1.0}));
}

TEST(Transform, RotateAboutXAndZIsCounterClockwiseRightHanded) {
    Transform rz = Transform::rotate({0.0, 0.0, 1.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(rz.apply_vector(Vec3d(1.0, 0.0, 0.0)), {0.0, 1.0, 0.0}));
    EXPECT_TRUE(vec_eq(rz.apply_vector(Vec3d(0.0, 1.0, 0.0)), {-1.0, 0.0, 0.0}));
    Transform rx = Transform::rotate({1.0, 0.0, 0.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(rx.apply_vector(Vec3d(0.0, 1.0, 0.0)), {0.0, 0.0, 1.0}));
    EXPECT_TRUE(vec_eq(rx.apply_vector(Vec3d(0.0, 0.0, 1.0)), {0.0, -1.0, 0.0}));
    // About -z the sense reverses.
    Transform rmz = Transform::rotate({0.0, 0.0, -1.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(rmz.apply_vector(Vec3d(1.0, 0.0, 0.0)), {0.0, -1.0, 0.0}));
    // 30 degrees about z: (cos 30, sin 30, 0).
    Transform r30 = Transform::rotate({0.0, 0.0, 2.0}, kPiD / 6.0);
    EXPECT_TRUE(vec_eq(r30.apply_vector(Vec3d(1.0, 0.0, 0.0)), {std::sqrt(3.0) / 2.0, 0.5, 0.0}));
}

TEST(Transform, RotateAboutDiagonalCyclesTheAxes) {
    // A third of a turn about (1,1,1) maps x -> y -> z -> x.
    Transform r = Transform::rotate({1.0, 1.0, 1.0}, 2.0 * kPiD / 3.0);
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(1.0, 0.0, 0.0)), {0.0, 1.0, 0.0}));
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(0.0, 1.0, 0.0)), {0.0, 0.0, 1.0}));
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(0.0, 0.0, 1.0)), {1.0, 0.0, 0.0}));
    EXPECT_TRUE(vec_eq(r.apply_vector(Vec3d(2.0, 2.0, 2.0)), {2.0, 2.0, 2.0}));  // the axis stays
}

TEST(Transform, ProductAppliesRightOperandFirst) {
    Transform t = Transform::translate({1.0, 0.0, 0.0});
    Transform s = Transform::scale({2.0, 2.0, 2.0});
    // Scale, then translate: (1,1,1) -> (2,2,2) -> (3,2,2).
    EXPECT_TRUE(vec_eq((t * s).apply_point(Vec3d(1.0, 1.0, 1.0)), {3.0, 2.0, 2.0}));
    // Translate, then scale: (1,1,1) -> (2,1,1) -> (4,2,2).
    EXPECT_TRUE(vec_eq((s * t).apply_point(Vec3d(1.0, 1.0, 1.0)), {4.0, 2.0, 2.0}));
    // Rotate a quarter turn about y, then lift: (1,0,0) -> (0,0,-1) -> (0,0,4).
    Transform lifted = Transform::translate({0.0, 0.0, 5.0}) * Transform::rotate({0.0, 1.0, 0.0}, kQuarterTurn);
    EXPECT_TRUE(vec_eq(lifted.apply_point(Vec3d(1.0, 0.0, 0.0)), {0.0, 0.0, 4.0}));
    // The product's inverse undoes both, in reverse order: (3,2,2) -> (2,2,2) -> (1,1,1).
    EXPECT_TRUE(vec_eq((t * s).inverse().apply_point(Vec3d(3.0, 2.0, 2.0)), {1.0, 1.0, 1.0}));
}

TEST(Transform, ProductNormalsUseTheProductInverse) {
    // Scale x by 2, then rotate a quarter turn about z. The normal of the plane x + y = 0
    // (tangent (1,-1,0)) becomes, after scaling, perpendicular to (2,-1,0), i.e. along (1,2,0);
    // after the rotation, along (-2,1,0).
    Transform m = Transform::rotate({0.0, 0.0, 1.0}, kQuarterTurn) * Transform::scale({2.0, 1.0, 1.0});
    Vec3d n = m.apply_normal(Vec3d(1.0, 1.0, 0.0));
    EXPECT_TRUE(vec_eq(normalize(n), normalize(Vec3d(-2.0, 1.0, 0.0))));
}

TEST(Transform, InverseOfKnownTransforms) {
    Transform::Matrix expect_translate = kIdentity;
    expect_translate[0][3] = -1.0;
    expect_translate[1][3] = -2.0;
    expect_translate[2][3] = -3.0;
    EXPECT_TRUE(matrix_eq(Transform::translate({1.0, 2.0, 3.0}).inverse().matrix(), expect_translate));
    Transform::Matrix expect_scale = kIdentity;
    expect_scale[0][0] = 0.5;
    expect_scale[1][1] = 0.25;
    expect_scale[2][2] = -0.125;
    EXPECT_TRUE(matrix_eq(Transform::scale({2.0, 4.0, -8.0}).inverse().matrix(), expect_scale));
    // A rotation's inverse is the rotation by the opposite angle.
    EXPECT_TRUE(matrix_eq(Transform::rotate({1.0, -2.0, 3.0}, 0.9).inverse().matrix(),
                          Transform::rotate({1.0, -2.0, 3.0}, -0.9).matrix()));
}

TEST(Transform, InverseRoundTripsPointsVectorsAndNormals) {
    Transform m = general_transform();
    Transform inv = m.inverse();
    for (Vec3d p : {Vec3d(0.0, 0.0, 0.0), Vec3d(1.0, 2.0, 3.0), Vec3d(-7.5, 0.25, 100.0)}) {
        EXPECT_TRUE(vec_eq(inv.apply_point(m.apply_point(p)), p, 1e-12 * (1.0 + length(p))));
        EXPECT_TRUE(vec_eq(m.apply_point(inv.apply_point(p)), p, 1e-12 * (1.0 + length(p))));
        EXPECT_TRUE(vec_eq(inv.apply_vector(m.apply_vector(p)), p, 1e-12 * (1.0 + length(p))));
        EXPECT_TRUE(vec_eq(inv.apply_normal(m.apply_normal(p)), p, 1e-12 * (1.0 + length(p))));
    }
    EXPECT_TRUE(matrix_eq((m * inv).matrix(), kIdentity));
    EXPECT_TRUE(matrix_eq((inv * m).matrix(), kIdentity));
    EXPECT_TRUE(matrix_eq(inv.inverse().matrix(), m.matrix(), 0.0));
}

TEST(Transform, GeneralMatrixIsInvertedWithPivoting) {
    // Zero diagonal: elimination must swap rows. Swapping x and y is its own inverse.
    Transform::Matrix swap_xy = {{{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    Transform sw(swap_xy);
    EXPECT_TRUE(sw.invertible());
    EXPECT_TRUE(matrix_eq(sw.inverse().matrix(), swap_xy));
    // A shear with a translation, inverse worked by hand:
    // [1 2 0 3; 0 1 0 0; 0 0 1 -1] inverts to [1 -2 0 -3; 0 1 0 0; 0 0 1 1].
    Transform::Matrix shear = {{{1, 2, 0, 3}, {0, 1, 0, 0}, {0, 0, 1, -1}, {0, 0, 0, 1}}};
    Transform::Matrix shear_inv = {{{1, -2, 0, -3}, {0, 1, 0, 0}, {0, 0, 1, 1}, {0, 0, 0, 1}}};
    Transform sh(shear);
    EXPECT_TRUE(matrix_eq(sh.inverse().matrix(), shear_inv));
    EXPECT_EQ(sh.determinant(), 1.0);
    EXPECT_TRUE(vec_eq(sh.apply_point(Vec3d(1.0, 1.0, 1.0)), {6.0, 1.0, 0.0}));
}

TEST(Transform, DeterminantOfKnownTransforms) {
    EXPECT_EQ(Transform().determinant(), 1.0);
    EXPECT_EQ(Transform::translate({4.0, 5.0, 6.0}).determinant(), 1.0);
    EXPECT_EQ(Transform::scale({2.0, 3.0, 4.0}).determinant(), 24.0);
    EXPECT_EQ(Transform::scale({-2.0, 3.0, 4.0}).determinant(), -24.0);
    EXPECT_NEAR(Transform::rotate({1.0, 2.0, 3.0}, 1.3).determinant(), 1.0, kTol);
    EXPECT_NEAR((Transform::scale({2.0, 3.0, 4.0}) * Transform::rotate({0.0, 1.0, 0.0}, 0.4)).determinant(), 24.0,
                1e-12);
    EXPECT_NEAR(general_transform().determinant(), -3.0, 1e-12);  // 2 * 0.5 * -3
}

TEST(Transform, SwapsHandednessOnlyForAnOddNumberOfMirrors) {
    EXPECT_TRUE(Transform::scale({-1.0, 1.0, 1.0}).swaps_handedness());
    EXPECT_TRUE(Transform::scale({1.0, 1.0, -2.0}).swaps_handedness());
    EXPECT_FALSE(Transform::scale({-1.0, -1.0, 1.0}).swaps_handedness());
    EXPECT_TRUE(Transform::scale({-1.0, -1.0, -1.0}).swaps_handedness());
    EXPECT_FALSE(Transform::rotate({0.0, 1.0, 0.0}, 2.0).swaps_handedness());
    EXPECT_FALSE(Transform::rotate({1.0, 0.0, 0.0}, kPiD).swaps_handedness());
    EXPECT_FALSE(Transform::translate({-1.0, -1.0, -1.0}).swaps_handedness());
    EXPECT_FALSE(Transform().swaps_handedness());
    EXPECT_TRUE(Transform({{{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}).swaps_handedness());
    EXPECT_TRUE(general_transform().swaps_handedness());
}

TEST(Transform, NormalsStayPerpendicularToTangentsUnderNonUniformScale) {
    // The plane x + y + z = c: tangents (1,-1,0) and (0,1,-1), normal (1,1,1) = cross(t1, t2).
    const Vec3d t1(1.0, -1.0, 0.0), t2(0.0, 1.0, -1.0), n(1.0, 1.0, 1.0);
    for (const Transform& m :
         {Transform::scale({1.0, 4.0, 0.25}), Transform::scale({-3.0, 0.5, 2.0}),
          Transform::rotate({0.3, -1.0, 2.0}, 0.8) * Transform::scale({5.0, 1.0, 0.1}),
          general_transform()}) {
        Vec3d mt1 = m.apply_vector(t1), mt2 = m.apply_vector(t2), mn = m.apply_normal(n);
        EXPECT_NEAR(dot(mn, mt1), 0.0, 1e-12);
        EXPECT_NEAR(dot(mn, mt2), 0.0, 1e-12);
        // The transformed normal is parallel to the transformed tangents' cross product, scaled
        // by the determinant: cross(M a, M b) = det(M) M^-T cross(a, b).
        EXPECT_TRUE(vec_eq(cross(mt1, mt2), mn * m.determinant(), 1e-12));
    }
    // Transforming the normal as a vector would be wrong, and this case shows it.
    Transform s = Transform::scale({1.0, 4.0, 0.25});
    EXPECT_GT(std::abs(dot(s.apply_vector(n), s.apply_vector(t1))), 1.0);
}

TEST(Transform, RotationTransformsNormalsLikeVectors) {
    Transform r = Transform::rotate({2.0, -1.0, 0.5}, 2.2);
    for (Vec3d v : {Vec3d(1.0, 0.0, 0.0), Vec3d(0.3, -0.7, 2.0)})
        EXPECT_TRUE(vec_eq(r.apply_normal(v), r.apply_vector(v)));
}

TEST(Transform, ZeroScaleIsNotInvertible) {
    EXPECT_FALSE(Transform::scale({0.0, 1.0, 1.0}).invertible());
    EXPECT_FALSE(Transform::scale({1.0, 1.0, 0.0}).invertible());
    EXPECT_FALSE(Transform::scale({0.0, 0.0, 0.0}).invertible());
    EXPECT_FALSE((Transform::rotate({1.0, 1.0, 0.0}, 0.5) * Transform::scale({1.0, 0.0, 1.0})).invertible());
    EXPECT_FALSE(Transform(Transform::Matrix{}).invertible());
    // Rank 2 without a zero on the diagonal: rows 0 and 1 are parallel.
    EXPECT_FALSE(Transform({{{1, 2, 3, 0}, {2, 4, 6, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}).invertible());
    // Singular, but rounding in the elimination leaves a tiny nonzero pivot and a finite inverse.
    const Transform rank2({{{1, 2, 3, 0}, {4, 5, 6, 0}, {7, 8, 9, 0}, {0, 0, 0, 1}}});
    EXPECT_FALSE(rank2.invertible());
    // Rotated, its determinant rounds to about 1e-14 instead of 0: still singular.
    for (double angle : {0.1, 0.137, 1.0, 2.5})
        EXPECT_FALSE((Transform::rotate({1.0, 2.0, 3.0}, angle) * rank2).invertible()) << angle;
    // Overall scale does not matter, and strong anisotropy is still invertible.
    EXPECT_TRUE(Transform::scale({1e-6, 1e-6, 1e-6}).invertible());
    EXPECT_TRUE(Transform::scale({1e8, 1e8, 1e8}).invertible());
    EXPECT_TRUE((Transform::rotate({1.0, 2.0, 3.0}, 0.1) * Transform::scale({1e4, 1e-4, 3.0}) *
                 Transform::rotate({0.0, 1.0, -1.0}, 0.3)).invertible());
    EXPECT_TRUE(Transform().invertible());
    EXPECT_TRUE(Transform::translate({1.0, 2.0, 3.0}).invertible());
    EXPECT_TRUE(Transform::scale({1e-3, 1.0, -2.0}).invertible());
    EXPECT_TRUE(general_transform().invertible());
}

TEST(Transform, IsIdentityOnlyForTheIdentity) {
    EXPECT_TRUE(Transform().is_identity());
    EXPECT_TRUE(Transform::translate({0.0, 0.0, 0.0}).is_identity());
    EXPECT_TRUE(Transform::scale({1.0, 1.0, 1.0}).is_identity());
    EXPECT_TRUE(Transform::rotate({0.0, 0.0, 1.0}, 0.0).is_identity());
    EXPECT_TRUE((Transform::scale({2.0, 4.0, 0.5}) * Transform::scale({0.5, 0.25, 2.0})).is_identity());
    EXPECT_TRUE(Transform(kIdentity).is_identity());
    EXPECT_FALSE(Transform::translate({1e-9, 0.0, 0.0}).is_identity());
    EXPECT_FALSE(Transform::scale({1.0, -1.0, 1.0}).is_identity());
    EXPECT_FALSE(Transform::rotate({0.0, 1.0, 0.0}, 1e-6).is_identity());
}

}  // namespace
}  // namespace candela
