// Vector algebra against values worked out by hand.
#include <gtest/gtest.h>

#include "candela/math/vec.h"

namespace candela {
namespace CANDELA_UNITY_ID {

::testing::AssertionResult vec_eq(const Vec3f& a, const Vec3f& b, float tol) {
    if (std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") != (" << b.x
                                         << ", " << b.y << ", " << b.z << ") within " << tol;
}

const Vec3f kX(1.0f, 0.0f, 0.0f);
const Vec3f kY(0.0f, 1.0f, 0.0f);
const Vec3f kZ(0.0f, 0.0f, 1.0f);

TEST(Vec3, DotOfKnownVectors) {
    EXPECT_EQ(dot(Vec3f(1.0f, 2.0f, 3.0f), Vec3f(4.0f, -5.0f, 6.0f)), 12.0f);  // 4 - 10 + 18
    EXPECT_EQ(dot(kX, kY), 0.0f);
    EXPECT_EQ(dot(Vec3f(2.0f, 0.0f, 0.0f), Vec3f(-3.0f, 7.0f, 9.0f)), -6.0f);
    EXPECT_EQ(abs_dot(Vec3f(2.0f, 0.0f, 0.0f), Vec3f(-3.0f, 7.0f, 9.0f)), 6.0f);
    EXPECT_EQ(dot(Vec3d(0.5, 0.25, 2.0), Vec3d(2.0, 4.0, -1.0)), 0.0);  // 1 + 1 - 2
}

TEST(Vec3, CrossIsRightHanded) {
    EXPECT_EQ(cross(kX, kY), kZ);
    EXPECT_EQ(cross(kY, kZ), kX);
    EXPECT_EQ(cross(kZ, kX), kY);
    EXPECT_EQ(cross(kY, kX), -kZ);
    EXPECT_EQ(cross(kX, kZ), -kY);
    EXPECT_EQ(cross(Vec3d(1, 0, 0), Vec3d(0, 1, 0)), Vec3d(0, 0, 1));
}

TEST(Vec3, CrossOfKnownVectors) {
    // (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4)
    EXPECT_EQ(cross(Vec3f(1.0f, 2.0f, 3.0f), Vec3f(4.0f, 5.0f, 6.0f)), Vec3f(-3.0f, 6.0f, -3.0f));
    EXPECT_EQ(cross(Vec3f(4.0f, 5.0f, 6.0f), Vec3f(1.0f, 2.0f, 3.0f)), Vec3f(3.0f, -6.0f, 3.0f));
    EXPECT_EQ(cross(Vec3f(2.0f, -1.0f, 0.5f), Vec3f(4.0f, -2.0f, 1.0f)), Vec3f(0.0f));  // parallel
}

TEST(Vec3, LengthOfKnownVectors) {
    EXPECT_EQ(length_squared(Vec3f(1.0f, 2.0f, 2.0f)), 9.0f);
    EXPECT_EQ(length(Vec3f(1.0f, 2.0f, 2.0f)), 3.0f);
    EXPECT_EQ(length(Vec3f(0.0f, -4.0f, 3.0f)), 5.0f);
    EXPECT_EQ(length(Vec3d(2.0, 3.0, 6.0)), 7.0);
}

TEST(Vec3, NormalizeGivesUnitVectorInSameDirection) {
    EXPECT_TRUE(vec_eq(normalize(Vec3f(3.0f, 4.0f, 0.0f)), Vec3f(0.6f, 0.8f, 0.0f), 1e-7f));
    EXPECT_TRUE(vec_eq(normalize(Vec3f(0.0f, 0.0f, -2.0f)), Vec3f(0.0f, 0.0f, -1.0f), 0.0f));
    // Short vectors normalize too, as long as the squared length stays a normal float.
    EXPECT_TRUE(vec_eq(normalize(Vec3f(0.0f, 1e-15f, 0.0f)), kY, 1e-7f));
    EXPECT_TRUE(vec_eq(normalize(Vec3f(-2.0f, 4.0f, 4.0f)), Vec3f(-1.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f), 1e-7f));
    Vec3d d = normalize(Vec3d(1.0, 1.0, 1.0));
    EXPECT_NEAR(d.x, 1.0 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(length(d), 1.0, 1e-15);
}

TEST(Vec3, FaceForwardFlipsIntoHemisphereOfN) {
    Vec3f v(1.0f, 2.0f, 3.0f);
    EXPECT_EQ(face_forward(v, kZ), v);
    EXPECT_EQ(face_forward(v, -kZ), Vec3f(-1.0f, -2.0f, -3.0f));
    EXPECT_EQ(face_forward(-v, Vec3f(0.0f, 1.0f, 0.0f)), v);
    // Perpendicular to n: already on the boundary of the hemisphere, left alone.
    EXPECT_EQ(face_forward(kX, kZ), kX);
    EXPECT_EQ(face_forward(kX, -kZ), kX);
}

TEST(Vec3, MinMaxAreComponentwise) {
    Vec3f a(1.0f, 5.0f, -3.0f), b(2.0f, -1.0f, -4.0f);
    EXPECT_EQ(min(a, b), Vec3f(1.0f, -1.0f, -4.0f));
    EXPECT_EQ(max(a, b), Vec3f(2.0f, 5.0f, -3.0f));
    EXPECT_EQ(min(b, a), Vec3f(1.0f, -1.0f, -4.0f));
    EXPECT_EQ(max(b, a), Vec3f(2.0f, 5.0f, -3.0f));
    EXPECT_EQ(max_component(Vec3f(-1.0f, 7.0f, 3.0f)), 7.0f);
    EXPECT_EQ(max_component(Vec3f(-1.0f, -7.0f, -3.0f)), -1.0f);
    EXPECT_EQ(max_component(Vec3f(0.0f, 1.0f, 2.0f)), 2.0f);
    EXPECT_EQ(abs(Vec3f(-1.0f, 2.0f, -3.0f)), Vec3f(1.0f, 2.0f, 3.0f));
}

TEST(Vec3, ArithmeticIsComponentwise) {
    Vec3f a(1.0f, 2.0f, 3.0f), b(4.0f, 6.0f, 8.0f);
    EXPECT_EQ(a + b, Vec3f(5.0f, 8.0f, 11.0f));
    EXPECT_EQ(b - a, Vec3f(3.0f, 4.0f, 5.0f));
    EXPECT_EQ(a * b, Vec3f(4.0f, 12.0f, 24.0f));
    EXPECT_EQ(a * 2.0f, Vec3f(2.0f, 4.0f, 6.0f));
    EXPECT_EQ(2.0f * a, Vec3f(2.0f, 4.0f, 6.0f));
    EXPECT_EQ(b / 2.0f, Vec3f(2.0f, 3.0f, 4.0f));
    EXPECT_EQ(a[0], 1.0f);
    EXPECT_EQ(a[1], 2.0f);
    EXPECT_EQ(a[2], 3.0f);
    EXPECT_EQ(Vec3f(Vec3d(0.5, -1.5, 2.0)), Vec3f(0.5f, -1.5f, 2.0f));
}

}  // namespace
}  // namespace candela
