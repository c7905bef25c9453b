// The surface's parametrization at hits (shading_geometry.h, Accelerator::shading): triangle
// derivatives from uvs, the fallback frame, and the sphere's analytic derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/shading_geometry.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"

namespace candela {
namespace CANDELA_UNITY_ID {

void expect_near(const Vec3f& a, const Vec3f& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(ShadingGeometry, TriangleDpduAndDpdvComeFromTheUvs) {
    // p = p0 + (p1 - p0) u + (p2 - p0) v when the uvs are (0,0), (1,0), (0,1).
    const Vec3f p[3] = {{1, 2, 3}, {3, 2, 3}, {1, 5, 3}};
    const Vec2f uvs[3] = {{0, 0}, {1, 0}, {0, 1}};
    ShadingGeometry g = triangle_shading_geometry(p, uvs, nullptr, Vec2f(0.25f, 0.5f), Vec3f(0, 0, 1));
    expect_near(g.dpdu, Vec3f(2, 0, 0), 1e-6f);
    expect_near(g.dpdv, Vec3f(0, 3, 0), 1e-6f);
    EXPECT_NEAR(g.uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(g.uv.y, 0.5f, 1e-6f);
    EXPECT_EQ(g.dndu, Vec3f(0.0f));

    // A general map: uv = M (x, y) + offset on the plane z = 3, so dp/d(u, v) = M^-1:
    // u = 0.5 x + 0.25 y, v = -0.5 x + y, det M = 0.625, M^-1 = [[1.6, -0.4], [0.8, 0.8]].
    auto uv_of = [](const Vec3f& q) { return Vec2f(0.5f * q.x + 0.25f * q.y + 0.1f, -0.5f * q.x + q.y - 0.2f); };
    const Vec2f mapped[3] = {uv_of(p[0]), uv_of(p[1]), uv_of(p[2])};
    g = triangle_shading_geometry(p, mapped, nullptr, Vec2f(0.25f, 0.5f), Vec3f(0, 0, 1));
    expect_near(g.dpdu, Vec3f(1.6f, 0.8f, 0), 1e-5f);
    expect_near(g.dpdv, Vec3f(-0.4f, 0.8f, 0), 1e-5f);
}

TEST(ShadingGeometry, FallbackFrameIsOrthonormalAroundTheNormal) {
    Rng rng(3, 1);
    const Vec3f p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Vec2f same[3] = {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};      // degenerate
    const Vec2f collinear[3] = {{0.0f, 0.0f}, {1.0f, 1.0f}, {2.0f, 2.0f}};  // degenerate
    for (int i = 0; i < 1000; ++i) {
        const Vec3f n = sample_uniform_sphere(rng.next_vec2f());
        for (const Vec2f* uvs : {static_cast<const Vec2f*>(nullptr), &same[0], &collinear[0]}) {
            ShadingGeometry g = triangle_shading_geometry(p, uvs, nullptr, Vec2f(0.2f, 0.3f), n);
            EXPECT_NEAR(length(g.dpdu), 1.0f, 1e-5f);
            EXPECT_NEAR(length(g.dpdv), 1.0f, 1e-5f);
            EXPECT_NEAR(dot(g.dpdu, g.dpdv), 0.0f, 1e-5f);
            EXPECT_NEAR(dot(g.dpdu, n), 0.0f, 1e-5f);
            expect_near(cross(g.dpdu, g.dpdv), n, 1e-5f);
        }
    }
    // Without uvs, uv is the barycentrics (Accelerator::uv's rule).
    ShadingGeometry g = triangle_shading_geometry(p, nullptr, nullptr, Vec2f(0.2f, 0.3f), Vec3f(0, 0, 1));
    EXPECT_EQ(g.uv, Vec2f(0.2f, 0.3f));
}

TEST(ShadingGeometry, TriangleNormalDerivativesComeFromTheVertexNormals) {
    // Normals n(u, v) = n0 + (n1 - n0) u + (n2 - n0) v with uvs (0,0), (1,0), (0,1).
    const Vec3f p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Vec2f uvs[3] = {{0, 0}, {1, 0}, {0, 1}};
    const Vec3f normals[3] = {normalize(Vec3f(0, 0, 1)), normalize(Vec3f(0.2f, 0, 1)), normalize(Vec3f(0, -0.3f, 1))};
    ShadingGeometry g = triangle_shading_geometry(p, uvs, normals, Vec2f(0.1f, 0.1f), Vec3f(0, 0, 1));
    expect_near(g.dndu, normals[1] - normals[0], 1e-6f);
    expect_near(g.dndv, normals[2] - normals[0], 1e-6f);
}

// p(u, v) of sphere_shading_geometry's parametrization, for finite differences.
Vec3d sphere_point(double u, double v, double r) {
    const double phi = 2.0 * kPiD * u, theta = kPiD * (1.0 - v);
    return Vec3d(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)) * r;
}

TEST(ShadingGeometry, SphereDerivativesMatchFiniteDifferencesAndFaceOutwards) {
    const double r = 2.5, h = 1e-6;
    Rng rng(5, 2);
    for (int i = 0; i < 200; ++i) {
        const Vec2f uv0(rng.next_float(), 0.05f + 0.9f * rng.next_float());
        const double u0 = double(uv0.x), v0 = double(uv0.y);
        const Vec3d p = sphere_point(u0, v0, r);
        const ShadingGeometry g = sphere_shading_geometry(p / r, r, false);
        EXPECT_NEAR(g.uv.x, uv0.x, 1e-5f);
        EXPECT_NEAR(g.uv.y, uv0.y, 1e-5f);
        const Vec3d du = (sphere_point(u0 + h, v0, r) - sphere_point(u0 - h, v0, r)) / (2 * h);
        const Vec3d dv = (sphere_point(u0, v0 + h, r) - sphere_point(u0, v0 - h, r)) / (2 * h);
        expect_near(g.dpdu, Vec3f(du), 1e-3f);
        expect_near(g.dpdv, Vec3f(dv), 1e-3f);
        EXPECT_GT(dot(cross(g.dpdu, g.dpdv), Vec3f(p)), 0.0f);  // outwards, as pbrt's sphere
        expect_near(g.dndu, g.dpdu * float(1.0 / r), 1e-5f);
        const ShadingGeometry reversed = sphere_shading_geometry(p / r, r, true);
        expect_near(reversed.dndu, g.dpdu * float(-1.0 / r), 1e-5f);
    }
    // At a pole dpdu vanishes: the fallback frame stands in.
    const ShadingGeometry pole = sphere_shading_geometry(Vec3d(0, 1, 0), r, false);
    EXPECT_NEAR(length(pole.dpdu), 1.0f, 1e-6f);
    expect_near(cross(pole.dpdu, pole.dpdv), Vec3f(0, 1, 0), 1e-6f);
}

TEST(ShadingGeometry, AcceleratorShadingAgreesWithUvAndTheShapes) {
    TriangleMesh tri;
    tri.positions = {{0, 0, 1}, {2, 0, 1}, {0, 2, 1}};
    tri.indices = {0, 1, 2};
    tri.uvs = {{0, 0}, {0, 1}, {1, 0}};  // u along y, v along x: mirrored (cross(dpdu, dpdv) = -z)
    std::vector<TriangleMesh> meshes = {tri};
    std::vector<Sphere> spheres = {Sphere{{10, 0, 0}, 2.0, false}};
    std::vector<Shape> shapes = {{ShapeKind::kMesh, 0, 0, {}, false}, {ShapeKind::kSphere, 0, 0, {}, false}};
    Accelerator accel(meshes, spheres, shapes);
    auto hit = accel.intersect(Ray{{0.5f, 0.25f, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    ShadingGeometry g = accel.shading(*hit);
    EXPECT_EQ(g.uv, accel.uv(*hit));
    expect_near(g.dpdu, Vec3f(0, 2, 0), 1e-6f);
    expect_near(g.dpdv, Vec3f(2, 0, 0), 1e-6f);
    auto on_sphere = accel.intersect(Ray{{10, 0.5f, -20}, {0, 0, 1}});
    ASSERT_TRUE(on_sphere);
    ShadingGeometry s = accel.shading(*on_sphere);
    EXPECT_NEAR(s.uv.x, accel.uv(*on_sphere).x, 1e-6f);
    EXPECT_NEAR(s.uv.y, accel.uv(*on_sphere).y, 1e-6f);
    EXPECT_NEAR(dot(s.dpdu, on_sphere->ng), 0.0f, 1e-4f);
    EXPECT_GT(dot(cross(s.dpdu, s.dpdv), on_sphere->ng), 0.0f);
}

}  // namespace
}  // namespace candela
