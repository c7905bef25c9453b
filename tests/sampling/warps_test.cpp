// Deterministic properties of the warps: outputs stay in their supports, each pdf is the inverse
// Jacobian determinant of its map (lajolla's check), and each pdf integrates to 1. The
// distributions themselves are tested by chi-square in warps_stat_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "candela/math/constants.h"
#include "candela/sampling/warps.h"
#include "support/chi2.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A grid of n x n sample points including the corners 0 and the largest float below 1.
std::vector<Vec2f> sample_grid(int n) {
    std::vector<Vec2f> us;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            auto coordinate = [n](int k) {
                if (k + 1 == n) return kOneMinusEpsilon;
                return static_cast<float>(k) / static_cast<float>(n - 1);
            };
            us.emplace_back(coordinate(i), coordinate(j));
        }
    return us;
}

// Interior points away from the seams where warps are not differentiable (the diagonals of the
// concentric and triangle maps, u = 0.5 of the tent), for finite differences.
const Vec2f kSmoothPoints[] = {{0.13f, 0.71f}, {0.62f, 0.27f}, {0.83f, 0.41f},
                               {0.35f, 0.91f}, {0.92f, 0.3f}, {0.21f, 0.05f}};
constexpr float kH = 1e-3f;  // central difference step

// |d map / du| for a map from the square into the plane.
template <class Map>
double planar_jacobian(const Map& map, Vec2f u) {
    Vec2f dx = map(Vec2f(u.x + kH, u.y)) - map(Vec2f(u.x - kH, u.y));
    Vec2f dy = map(Vec2f(u.x, u.y + kH)) - map(Vec2f(u.x, u.y - kH));
    double det = static_cast<double>(dx.x) * static_cast<double>(dy.y) -
                 static_cast<double>(dx.y) * static_cast<double>(dy.x);
    return std::abs(det) / (4.0 * static_cast<double>(kH) * static_cast<double>(kH));
}

// The solid angle per unit square area of a map from the square onto the sphere.
template <class Map>
double spherical_jacobian(const Map& map, Vec2f u) {
    Vec3d dx(map(Vec2f(u.x + kH, u.y)) - map(Vec2f(u.x - kH, u.y)));
    Vec3d dy(map(Vec2f(u.x, u.y + kH)) - map(Vec2f(u.x, u.y - kH)));
    return length(cross(dx, dy)) / (4.0 * static_cast<double>(kH) * static_cast<double>(kH));
}

TEST(Warps, SphereWarpsReturnUnitVectorsInTheirSupport) {
    for (Vec2f u : sample_grid(33)) {
        Vec3f s = sample_uniform_sphere(u), h = sample_uniform_hemisphere(u);
        Vec3f c = sample_cosine_hemisphere(u), k = sample_uniform_cone(u, 0.8f);
        for (Vec3f w : {s, h, c, k}) EXPECT_NEAR(length(w), 1.0f, 1e-6f);
        EXPECT_GE(h.z, 0.0f);
        EXPECT_GE(c.z, 0.0f);
        EXPECT_GE(k.z, 0.8f);
        EXPECT_GT(uniform_hemisphere_pdf(h), 0.0f);
        EXPECT_GT(uniform_cone_pdf(k, 0.8f), 0.0f);
    }
}

TEST(Warps, ConcentricDiskStaysInTheDiskAndMapsTheCentreToTheOrigin) {
    for (Vec2f u : sample_grid(33)) {
        ConcentricDiskSample d = sample_concentric_disk_and_radius(u);
        Vec2f p = sample_concentric_disk(u);
        EXPECT_EQ(p, d.p);
        EXPECT_LE(p.x * p.x + p.y * p.y, 1.0f + 1e-6f);
        // The radius the cosine warp lifts from is the point's own, to float rounding.
        EXPECT_NEAR(double(d.r), std::sqrt(double(p.x) * double(p.x) + double(p.y) * double(p.y)), 1e-6);
    }
    EXPECT_EQ(sample_concentric_disk(Vec2f(0.5f, 0.5f)), Vec2f(0.0f, 0.0f));
    Vec2f edge = sample_concentric_disk(Vec2f(kOneMinusEpsilon, 0.5f));  // middle of the right edge
    EXPECT_NEAR(edge.x, 1.0f, 1e-6f);
    EXPECT_NEAR(edge.y, 0.0f, 1e-6f);
}

// The concentric map's own cos and sin agree with the double-precision functions to float
// rounding (a few 1e-8) over the whole range, endpoints included.
TEST(Warps, SelectIsTheTernaryBitForBit) {
    // Comparisons with NaN are false, with -0 and +0 equal; the selected value keeps its bits.
    const float values[] = {0.0f, -0.0f, 1.0f, -2.5f, 1e-40f, kInfinity, std::numeric_limits<float>::quiet_NaN()};
    for (float x : values)
        for (float y : values)
            for (float a : values)
                for (float b : values)
                    EXPECT_EQ(std::bit_cast<uint32_t>(select(greater(x, y), a, b)),
                              std::bit_cast<uint32_t>(x > y ? a : b))
                        << x << " > " << y;
}

TEST(Warps, ConcentricDiskMatchesShirleyChiusMapWithLibraryTrigonometry) {
    // The branch-free form against the textbook one (Shirley and Chiu 1997, with std::cos/sin).
    for (Vec2f u : sample_grid(101)) {
        double a = 2.0 * double(u.x) - 1.0, b = 2.0 * double(u.y) - 1.0, r, phi;
        if (a == 0.0 && b == 0.0) {
            r = 0.0, phi = 0.0;
        } else if (std::abs(a) > std::abs(b)) {
            r = a, phi = 0.25 * kPiD * (b / a);
        } else {
            r = b, phi = 0.5 * kPiD - 0.25 * kPiD * (a / b);
        }
        Vec2f p = sample_concentric_disk(u);
        EXPECT_NEAR(p.x, r * std::cos(phi), 3e-7) << u.x << ", " << u.y;
        EXPECT_NEAR(p.y, r * std::sin(phi), 3e-7) << u.x << ", " << u.y;
    }
}

TEST(Warps, QuarterPiCosSinMatchesTheLibrary) {
    double worst = 0.0;
    for (int k = -100000; k <= 100000; ++k) {
        float t = float(k) / 100000.0f;
        Vec2f cs = cos_sin_quarter_pi(t);
        double angle = 0.25 * kPiD * double(t);
        worst = std::max({worst, std::abs(double(cs.x) - std::cos(angle)), std::abs(double(cs.y) - std::sin(angle))});
    }
    EXPECT_LT(worst, 1.2e-7);  // two float ulps at 1 (the float angle itself is off by one ulp)
    EXPECT_EQ(cos_sin_quarter_pi(0.0f), Vec2f(1.0f, 0.0f));
}

TEST(Warps, TriangleBarycentricsAreNonNegativeAndSumToOne) {
    for (Vec2f u : sample_grid(33)) {
        Vec3f b = sample_uniform_triangle(u);
        EXPECT_GE(b.x, 0.0f);
        EXPECT_GE(b.y, 0.0f);
        EXPECT_GE(b.z, -1e-7f);
        EXPECT_NEAR(b.x + b.y + b.z, 1.0f, 1e-6f);
    }
    // The square's corners (0,0), (1,0), (0,1) go to vertices 2, 0 and 1.
    EXPECT_EQ(sample_uniform_triangle(Vec2f(0.0f, 0.0f)), Vec3f(0.0f, 0.0f, 1.0f));
    Vec3f b = sample_uniform_triangle(Vec2f(kOneMinusEpsilon, 0.0f));
    EXPECT_NEAR(b.x, 1.0f, 1e-6f);
    b = sample_uniform_triangle(Vec2f(0.0f, kOneMinusEpsilon));
    EXPECT_NEAR(b.y, 1.0f, 1e-6f);
}

TEST(Warps, TentStaysWithinItsRadiusAndIsSymmetric) {
    EXPECT_FLOAT_EQ(sample_tent(0.0f, 2.0f), -2.0f);
    EXPECT_FLOAT_EQ(sample_tent(0.5f, 2.0f), 0.0f);
    EXPECT_NEAR(sample_tent(kOneMinusEpsilon, 2.0f), 2.0f, 1e-3f);
    EXPECT_LT(sample_tent(kOneMinusEpsilon, 2.0f), 2.0f);
    for (float u : {0.1f, 0.25f, 0.4f})
        EXPECT_NEAR(sample_tent(u, 1.5f), -sample_tent(1.0f - u, 1.5f), 1e-6f);
    EXPECT_EQ(tent_pdf(2.0f, 2.0f), 0.0f);
    EXPECT_EQ(tent_pdf(-3.0f, 2.0f), 0.0f);
    EXPECT_FLOAT_EQ(tent_pdf(0.0f, 2.0f), 0.5f);
}

TEST(Warps, PdfsAreZeroOutsideTheirSupport) {
    EXPECT_EQ(uniform_hemisphere_pdf(Vec3f(0.0f, 0.6f, -0.8f)), 0.0f);
    EXPECT_EQ(cosine_hemisphere_pdf(Vec3f(0.0f, 0.6f, -0.8f)), 0.0f);
    EXPECT_EQ(uniform_cone_pdf(Vec3f(0.0f, 0.6f, 0.8f), 0.9f), 0.0f);
    EXPECT_EQ(concentric_disk_pdf(Vec2f(0.8f, 0.7f)), 0.0f);
    EXPECT_FLOAT_EQ(uniform_sphere_pdf(Vec3f(0.0f, 0.0f, -1.0f)), 1.0f / (4.0f * kPi));
    EXPECT_FLOAT_EQ(uniform_triangle_pdf(0.25f), 4.0f);
}

// pdf * |Jacobian| = 1: the density is the inverse of how much the map stretches area.
::testing::AssertionResult is_inverse_jacobian(float pdf, double jacobian) {
    double product = static_cast<double>(pdf) * jacobian;
    if (std::abs(product - 1.0) <= 2e-3) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "pdf " << pdf << " * |Jacobian| " << jacobian << " = "
                                         << product << ", expected 1";
}

TEST(Warps, PlanarPdfsAreTheInverseJacobianOfTheirMaps) {
    // A triangle of area 0.5 * |cross(p1 - p0, p2 - p0)| = 0.285.
    const Vec2f p0(0.1f, 0.2f), p1(0.9f, 0.35f), p2(0.3f, 0.95f);
    auto to_triangle = [&](Vec2f u) {
        Vec3f b = sample_uniform_triangle(u);
        return p0 * b.x + p1 * b.y + p2 * b.z;
    };
    for (Vec2f u : kSmoothPoints) {
        SCOPED_TRACE(::testing::Message() << "u = (" << u.x << ", " << u.y << ")");
        EXPECT_TRUE(is_inverse_jacobian(concentric_disk_pdf(sample_concentric_disk(u)),
                                        planar_jacobian(sample_concentric_disk, u)));
        EXPECT_TRUE(
            is_inverse_jacobian(uniform_triangle_pdf(0.285f), planar_jacobian(to_triangle, u)));
        double tent_slope =
            static_cast<double>(sample_tent(u.x + kH, 0.7f) - sample_tent(u.x - kH, 0.7f)) /
            (2.0 * static_cast<double>(kH));
        EXPECT_TRUE(is_inverse_jacobian(tent_pdf(sample_tent(u.x, 0.7f), 0.7f), tent_slope));
    }
}

TEST(Warps, SphericalPdfsAreTheInverseJacobianOfTheirMaps) {
    for (Vec2f u : kSmoothPoints) {
        SCOPED_TRACE(::testing::Message() << "u = (" << u.x << ", " << u.y << ")");
        EXPECT_TRUE(is_inverse_jacobian(uniform_sphere_pdf(sample_uniform_sphere(u)),
                                        spherical_jacobian(sample_uniform_sphere, u)));
        EXPECT_TRUE(is_inverse_jacobian(uniform_hemisphere_pdf(sample_uniform_hemisphere(u)),
                                        spherical_jacobian(sample_uniform_hemisphere, u)));
        EXPECT_TRUE(is_inverse_jacobian(cosine_hemisphere_pdf(sample_cosine_hemisphere(u)),
                                        spherical_jacobian(sample_cosine_hemisphere, u)));
        for (float cos_max : {0.3f, 0.9f, -0.5f}) {
            auto cone = [cos_max](Vec2f v) { return sample_uniform_cone(v, cos_max); };
            EXPECT_TRUE(is_inverse_jacobian(uniform_cone_pdf(cone(u), cos_max),
                                            spherical_jacobian(cone, u)))
                << "cos_theta_max " << cos_max;
        }
    }
}

TEST(Warps, PdfsIntegrateToOne) {
    using test::integrate_pdf;
    test::SphericalDomain sphere;
    EXPECT_NEAR(integrate_pdf(sphere, uniform_sphere_pdf), 1.0, 1e-5);
    EXPECT_NEAR(integrate_pdf(sphere, uniform_hemisphere_pdf), 1.0, 1e-5);
    EXPECT_NEAR(integrate_pdf(sphere, cosine_hemisphere_pdf), 1.0, 1e-5);
    for (float cos_max : {0.5f, 0.95f, -0.3f}) {
        auto pdf = [cos_max](Vec3f w) { return uniform_cone_pdf(w, cos_max); };
        EXPECT_NEAR(integrate_pdf(sphere, pdf), 1.0, 1e-4) << "cos_theta_max " << cos_max;
    }
    test::PlanarDomain square{{-1.0, -1.0}, {1.0, 1.0}};
    EXPECT_NEAR(integrate_pdf(square, concentric_disk_pdf), 1.0, 1e-4);
    test::PlanarDomain line{{-1.0, 0.0}, {1.0, 1.0}};
    EXPECT_NEAR(integrate_pdf(line, [](Vec2f p) { return tent_pdf(p.x, 0.8f); }), 1.0, 1e-5);
}

}  // namespace
}  // namespace candela
