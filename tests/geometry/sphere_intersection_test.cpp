// Precision of ray-sphere intersection where a naive float quadratic fails: smallpt's walls are
// spheres of radius 1e5 whose centres lie 1e5 away from the rays.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/sphere_intersection.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// Reference: the same quadratic solved in long double with the textbook formula, which is exact
// enough at 64-bit mantissa for these magnitudes.
std::optional<long double> reference_hit(const Sphere& s, const Vec3f& o, const Vec3f& d) {
    long double fx = (long double)o.x - s.center.x, fy = (long double)o.y - s.center.y,
                fz = (long double)o.z - s.center.z;
    long double a = (long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z;
    long double b = fx * d.x + fy * d.y + fz * d.z;
    long double c = fx * fx + fy * fy + fz * fz - (long double)s.radius * s.radius;
    long double disc = b * b - a * c;
    if (disc < 0) return std::nullopt;
    long double sq = std::sqrt(disc);
    long double t0 = (-b - sq) / a, t1 = (-b + sq) / a;
    if (t0 > 0) return t0;
    if (t1 > 0) return t1;
    return std::nullopt;
}

TEST(SphereIntersection, HugeSmallptWallsMatchHighPrecisionReference) {
    // smallpt's left wall and floor; rays from inside its box in random directions.
    const Sphere walls[] = {{{1e5 + 1, 40.8, 81.6}, 1e5, false}, {{50, 1e5, 81.6}, 1e5, false},
                            {{50, 40.8, -1e5 + 170}, 1e5, false}};
    Rng rng(7, 3);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Sphere& s = walls[i % 3];
        Vec3f o(10.0f + 80.0f * rng.next_float(), 5.0f + 70.0f * rng.next_float(), 20.0f + 120.0f * rng.next_float());
        Vec3f d = normalize(Vec3f(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
        auto t = intersect_sphere(s, Vec3d(o), Vec3d(d), 0.0, 1e30);
        auto ref = reference_hit(s, o, d);
        ASSERT_EQ(t.has_value(), ref.has_value()) << "ray " << i;
        if (!t) continue;
        ++hits;
        EXPECT_NEAR(*t, double(*ref), 1e-4 * double(*ref)) << "ray " << i;
    }
    EXPECT_GT(hits, 5000);  // the test must exercise hits, not only misses
}

TEST(SphereIntersection, DistanceToWallIsExactAlongAxis) {
    // smallpt's box lies inside all six wall spheres; the left wall's surface near the box is the
    // plane x = 1. A ray from x = 50 along -x leaves the sphere there, at t = 49 (a float
    // quadratic is off by whole units at this scale).
    Sphere wall{{1e5 + 1, 40.8, 81.6}, 1e5, false};
    auto t = intersect_sphere(wall, Vec3d(50, 40.8, 81.6), Vec3d(-1, 0, 0), 0.0, 1e30);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 49.0, 1e-9);
}

TEST(SphereIntersection, ReturnsNearestRootAboveTmin) {
    Sphere s{{0, 0, 0}, 2.0, false};
    auto t = intersect_sphere(s, Vec3d(-5, 0, 0), Vec3d(1, 0, 0), 0.0, 100.0);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 3.0);
    // From inside, the far root.
    t = intersect_sphere(s, Vec3d(0, 0, 0), Vec3d(0, 1, 0), 0.0, 100.0);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 2.0);
    // tmax before the sphere: no hit; sphere behind: no hit.
    EXPECT_FALSE(intersect_sphere(s, Vec3d(-5, 0, 0), Vec3d(1, 0, 0), 0.0, 2.9));
    EXPECT_FALSE(intersect_sphere(s, Vec3d(-5, 0, 0), Vec3d(-1, 0, 0), 0.0, 100.0));
    // Unnormalized direction: t scales inversely.
    t = intersect_sphere(s, Vec3d(-5, 0, 0), Vec3d(2, 0, 0), 0.0, 100.0);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 1.5);
}

TEST(SphereIntersection, ProjectionLandsOnSurface) {
    Sphere s{{1e5 + 1, 40.8, 81.6}, 1e5, false};
    Vec3d p = project_to_sphere(s, Vec3d(1.3, 20.0, 60.0));
    EXPECT_NEAR(length(p - s.center), 1e5, 1e-9);
}

}  // namespace
}  // namespace candela
