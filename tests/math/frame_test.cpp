// Frame::from_normal must give an orthonormal, right-handed basis for every unit normal,
// including the poles where the Duff et al. construction switches sign.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "candela/math/constants.h"
#include "candela/math/frame.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr float kTol = 2e-6f;

::testing::AssertionResult vec_eq(const Vec3f& a, const Vec3f& b, float tol) {
    if (std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") != (" << b.x
                                         << ", " << b.y << ", " << b.z << ") within " << tol;
}

// Checks every property a shading frame promises, with a message naming the normal.
void expect_orthonormal_right_handed(const Vec3f& n) {
    SCOPED_TRACE(::testing::Message() << "n = (" << n.x << ", " << n.y << ", " << n.z << ")");
    Frame f = Frame::from_normal(n);
    EXPECT_EQ(f.n, n);
    EXPECT_NEAR(double(length(f.s)), 1.0, double(kTol));
    EXPECT_NEAR(double(length(f.t)), 1.0, double(kTol));
    EXPECT_NEAR(double(dot(f.s, f.t)), 0.0, double(kTol));
    EXPECT_NEAR(double(dot(f.s, f.n)), 0.0, double(kTol));
    EXPECT_NEAR(double(dot(f.t, f.n)), 0.0, double(kTol));
    EXPECT_TRUE(vec_eq(cross(f.s, f.t), f.n, kTol));
    EXPECT_TRUE(vec_eq(cross(f.t, f.n), f.s, kTol));
    EXPECT_TRUE(vec_eq(cross(f.n, f.s), f.t, kTol));
    EXPECT_TRUE(is_finite(f.s) && is_finite(f.t));
}

// Uniform directions on the sphere (Archimedes: z uniform in [-1, 1], azimuth uniform).
std::vector<Vec3f> random_unit_vectors(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3f> out;
    for (int i = 0; i < count; ++i) {
        double z = 2.0 * u(rng) - 1.0, phi = 2.0 * kPiD * u(rng);
        double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        out.push_back(Vec3f(normalize(Vec3d(r * std::cos(phi), r * std::sin(phi), z))));
    }
    return out;
}

TEST(Frame, PlusZGivesTheStandardBasis) {
    Frame f = Frame::from_normal(Vec3f(0.0f, 0.0f, 1.0f));
    EXPECT_TRUE(vec_eq(f.s, Vec3f(1.0f, 0.0f, 0.0f), 0.0f));
    EXPECT_TRUE(vec_eq(f.t, Vec3f(0.0f, 1.0f, 0.0f), 0.0f));
}

TEST(Frame, MinusZIsOrthonormalAndRightHanded) {
    Frame f = Frame::from_normal(Vec3f(0.0f, 0.0f, -1.0f));
    // s and t span the xy plane and cross(s, t) must be -z, so one of them is mirrored.
    EXPECT_TRUE(vec_eq(cross(f.s, f.t), Vec3f(0.0f, 0.0f, -1.0f), 0.0f));
    expect_orthonormal_right_handed(Vec3f(0.0f, 0.0f, -1.0f));
}

TEST(Frame, AxisAndEquatorNormalsAreOrthonormalAndRightHanded) {
    for (Vec3f n : {Vec3f(1.0f, 0.0f, 0.0f), Vec3f(-1.0f, 0.0f, 0.0f), Vec3f(0.0f, 1.0f, 0.0f),
                    Vec3f(0.0f, -1.0f, 0.0f), Vec3f(1.0f, 0.0f, -0.0f), Vec3f(0.0f, -1.0f, -0.0f),
                    Vec3f(0.0f, 0.0f, 1.0f), Vec3f(0.0f, 0.0f, -1.0f),
                    normalize(Vec3f(1.0f, 1.0f, 0.0f)), normalize(Vec3f(-1.0f, 1.0f, -0.0f))})
        expect_orthonormal_right_handed(n);
}

TEST(Frame, NearPoleNormalsAreOrthonormalAndRightHanded) {
    // Normals within 1e-1 ... 1e-7 of either pole, at several azimuths.
    for (float pole : {1.0f, -1.0f})
        for (int k = 1; k <= 7; ++k)
            for (int a = 0; a < 8; ++a) {
                double eps = std::pow(10.0, -k), phi = 2.0 * kPiD * a / 8.0;
                double z = double(pole) * (1.0 - eps);
                double r = std::sqrt(1.0 - z * z);
                expect_orthonormal_right_handed(
                    Vec3f(normalize(Vec3d(r * std::cos(phi), r * std::sin(phi), z))));
            }
    expect_orthonormal_right_handed(normalize(Vec3f(1e-4f, -1e-4f, -1.0f)));
    expect_orthonormal_right_handed(normalize(Vec3f(-3e-8f, 2e-8f, -1.0f)));
    expect_orthonormal_right_handed(normalize(Vec3f(3e-8f, 1e-30f, 1.0f)));
}

TEST(Frame, RandomNormalsAreOrthonormalAndRightHanded) {
    for (const Vec3f& n : random_unit_vectors(5000, 7u)) expect_orthonormal_right_handed(n);
}

TEST(Frame, BasisVectorsMapToLocalAxes) {
    for (const Vec3f& n : random_unit_vectors(200, 11u)) {
        Frame f = Frame::from_normal(n);
        EXPECT_TRUE(vec_eq(f.to_local(f.s), Vec3f(1.0f, 0.0f, 0.0f), kTol));
        EXPECT_TRUE(vec_eq(f.to_local(f.t), Vec3f(0.0f, 1.0f, 0.0f), kTol));
        EXPECT_TRUE(vec_eq(f.to_local(n), Vec3f(0.0f, 0.0f, 1.0f), kTol));
        EXPECT_TRUE(vec_eq(f.to_world(Vec3f(0.0f, 0.0f, 1.0f)), n, 0.0f));
        EXPECT_TRUE(vec_eq(f.to_world(Vec3f(1.0f, 0.0f, 0.0f)), f.s, 0.0f));
    }
}

TEST(Frame, ToLocalAndToWorldRoundTrip) {
    std::vector<Vec3f> normals = random_unit_vectors(500, 3u);
    normals.push_back(Vec3f(0.0f, 0.0f, -1.0f));
    normals.push_back(Vec3f(0.0f, 0.0f, 1.0f));
    std::vector<Vec3f> vs = random_unit_vectors(500, 5u);
    for (size_t i = 0; i < normals.size(); ++i) {
        Frame f = Frame::from_normal(normals[i]);
        Vec3f v = vs[i % vs.size()] * 3.0f;
        Vec3f local = f.to_local(v);
        EXPECT_NEAR(double(length(local)), 3.0, 1e-5);  // a rotation keeps lengths
        EXPECT_NEAR(double(local.z), double(dot(v, normals[i])), 1e-5);  // z is the cosine to n
        EXPECT_TRUE(vec_eq(f.to_world(local), v, 1e-5f));
        EXPECT_TRUE(vec_eq(f.to_local(f.to_world(v)), v, 1e-5f));
    }
}

}  // namespace
}  // namespace candela
