// Ray traversal through Embree: hit records (distance, point, normals, uv, ids), occlusion, and
// spawned rays that never hit the surface they leave.
#include <gtest/gtest.h>

#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/ray_offset.h"
#include "candela/math/frame.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A scene of the given meshes and spheres, shape i = mesh i, then the spheres.
struct TestScene {
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<Shape> shapes;
    std::unique_ptr<Accelerator> accel;

    TestScene(std::vector<TriangleMesh> m, std::vector<Sphere> s) : meshes(std::move(m)), spheres(std::move(s)) {
        for (uint32_t i = 0; i < meshes.size(); ++i) shapes.push_back({ShapeKind::kMesh, i, 0, {}, false});
        for (uint32_t i = 0; i < spheres.size(); ++i) shapes.push_back({ShapeKind::kSphere, i, 0, {}, false});
        accel = std::make_unique<Accelerator>(meshes, spheres, shapes);
    }
};

TEST(Accelerator, TriangleHitCarriesDistancePointNormalUvAndIds) {
    // Unit quad in the z = 2 plane, facing -z (towards a camera at the origin looking +z).
    TriangleMesh quad = make_quad({-1, -1, 2}, {0, 2, 0}, {2, 0, 0});
    TestScene scene({quad}, {});
    auto hit = scene.accel->intersect(Ray{{0.5f, -0.5f, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2.0f);
    EXPECT_NEAR(hit->p.x, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->p.y, -0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(hit->p.z, 2.0f);
    EXPECT_NEAR(hit->ng.z, -1.0f, 1e-6f);  // cross((0,2,0), (2,0,0)) = (0,0,-4)
    EXPECT_EQ(hit->ns, hit->ng);
    // uv = (s, t) along (edge1, edge2): s = (y+1)/2, t = (x+1)/2.
    EXPECT_NEAR(scene.accel->uv(*hit).x, 0.25f, 1e-6f);
    EXPECT_NEAR(scene.accel->uv(*hit).y, 0.75f, 1e-6f);
    EXPECT_EQ(hit->shape_id, 0u);
    EXPECT_TRUE(hit->front_face(Vec3f(0, 0, 1)));
    EXPECT_FALSE(scene.accel->intersect(Ray{{5, 5, 0}, {0, 0, 1}}));
}

TEST(Accelerator, VertexNormalsSetShadingNormalAndFlipGeometricNormal) {
    TriangleMesh tri;
    tri.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};  // winding normal +z
    tri.indices = {0, 1, 2};
    // Vertex normals towards -z, tilted differently: the geometric normal must follow them.
    tri.normals = {normalize(Vec3f(0.3f, 0, -1)), normalize(Vec3f(0, 0.3f, -1)), Vec3f(0, 0, -1)};
    TestScene scene({tri}, {});
    auto hit = scene.accel->intersect(Ray{{0.25f, 0.25f, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->ng.z, -1.0f, 1e-6f);
    EXPECT_LT(hit->ns.z, 0.0f);
    EXPECT_NEAR(length(hit->ns), 1.0f, 1e-6f);
    EXPECT_GT(hit->ns.x, 0.0f);  // interpolated, not the face normal
}

// A small mesh's hits read its normal table, a large one's compute the normal: both must report
// winding_normal of the triangle hit, bit for bit (light samples on emitting meshes use it too).
TEST(Accelerator, HitNormalsAreTheWindingNormalsWithOrWithoutTheTable) {
    // Grids of n x n cells (two triangles each) in the plane z = 1 + (x + y) / 8, around the
    // z axis; the first below the table's size, the second above it.
    auto tilted_grid = [](int n) {
        TriangleMesh m;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                float x = -1.0f + 2.0f * float(i) / float(n), y = -1.0f + 2.0f * float(j) / float(n);
                m.positions.push_back({x, y, 1.0f + 0.125f * (x + y) + 0.01f * float((i * 7 + j * 3) % 5)});
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
                m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
            }
        return m;
    };
    for (int n : {8, 200}) {
        TriangleMesh grid = tilted_grid(n);
        ASSERT_EQ(grid.triangle_count() > kMaxTrianglesWithNormalTable, n == 200);
        TestScene scene({grid}, {});
        Rng rng(7, uint64_t(n));
        for (int k = 0; k < 500; ++k) {
            Vec2f u = rng.next_vec2f();
            auto hit = scene.accel->intersect(Ray{{1.6f * u.x - 0.8f, 1.6f * u.y - 0.8f, -1.0f}, {0, 0, 1}});
            ASSERT_TRUE(hit);
            const uint32_t* v = &grid.indices[3 * size_t(hit->prim_id)];
            Vec3f expected = winding_normal(grid.positions[v[0]], grid.positions[v[1]], grid.positions[v[2]]);
            EXPECT_EQ(hit->ng, expected) << "grid " << n << ", triangle " << hit->prim_id;
            EXPECT_EQ(hit->ns, expected);
        }
    }
}

TEST(Accelerator, SphereHitAndReverseOrientation) {
    TestScene scene({}, {Sphere{{0, 0, 5}, 1.0, false}, Sphere{{0, 0, -5}, 1.0, true}});
    auto hit = scene.accel->intersect(Ray{{0, 0, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
    EXPECT_EQ(hit->shape_id, 0u);
    EXPECT_NEAR(hit->ng.z, -1.0f, 1e-6f);  // outside faces the ray
    auto back = scene.accel->intersect(Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(back);
    EXPECT_EQ(back->shape_id, 1u);
    EXPECT_NEAR(back->ng.z, -1.0f, 1e-6f);  // reversed: its front is the inside, facing -z here
    EXPECT_FALSE(back->front_face(Vec3f(0, 0, -1)));
}

TEST(Accelerator, UvIsComputedOnDemandInEachShapesConvention) {
    // A mesh with vertex uvs interpolates them; a sphere follows pbrt's with +y up,
    // u = atan2(-z, x) / 2pi, v = 1 - acos(y) / pi of the outward normal.
    TriangleMesh tri;
    tri.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    tri.indices = {0, 1, 2};
    tri.uvs = {{0.5f, 0.5f}, {1.0f, 0.5f}, {0.5f, 1.0f}};
    TestScene scene({tri}, {Sphere{{10, 0, 0}, 1.0, false}});
    auto hit = scene.accel->intersect(Ray{{0.25f, 0.5f, 0}, {0, 0, 1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(scene.accel->uv(*hit).x, 0.625f, 1e-6f);
    EXPECT_NEAR(scene.accel->uv(*hit).y, 0.75f, 1e-6f);
    // The sphere seen from -z: the hit's normal is -z, u = 1/4, v = 1/2.
    auto on_sphere = scene.accel->intersect(Ray{{10, 0, -20}, {0, 0, 1}});
    ASSERT_TRUE(on_sphere);
    EXPECT_EQ(on_sphere->shape_id, 1u);
    EXPECT_NEAR(scene.accel->uv(*on_sphere).x, 0.25f, 1e-6f);
    EXPECT_NEAR(scene.accel->uv(*on_sphere).y, 0.5f, 1e-6f);
    // From above: the top pole is v = 1, as an image's top row.
    auto top = scene.accel->intersect(Ray{{10, 20, 0}, {0, -1, 0}});
    ASSERT_TRUE(top);
    EXPECT_NEAR(scene.accel->uv(*top).y, 1.0f, 1e-6f);
}

TEST(Accelerator, OcclusionRespectsTmax) {
    TestScene scene({}, {Sphere{{0, 0, 5}, 1.0, false}});
    EXPECT_TRUE(scene.accel->occluded(Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 10.0f}));
    EXPECT_FALSE(scene.accel->occluded(Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 3.9f}));
    EXPECT_FALSE(scene.accel->occluded(Ray{{0, 0, 0}, {0, 1, 0}, 0.0f, 10.0f}));
    Bounds3f b = scene.accel->bounds();
    EXPECT_LE(b.lo.z, 4.0f);
    EXPECT_GE(b.hi.z, 6.0f);
}

// Whether `next`, found by a ray leaving `hit` in direction w, is the surface hit again where it
// was left. A triangle is planar, so any hit on the same triangle is one. A sphere is convex: a
// ray leaving outwards must not hit it at all, and one leaving inwards must travel the whole chord
// 2 r |cos| before it does.
bool is_self_hit(const TestScene& scene, const SurfaceHit& hit, const Vec3f& w, const SurfaceHit& next) {
    if (next.shape_id != hit.shape_id) return false;
    const Shape& shape = scene.shapes[hit.shape_id];
    if (shape.kind == ShapeKind::kMesh) return next.prim_id == hit.prim_id;
    const Sphere& s = scene.spheres[shape.index];
    // The side is the one spawn_ray picks: by the hit's geometric normal (outward here).
    float cos_out = dot(w, hit.ng);
    if (cos_out >= 0.0f) return true;
    double chord = 2.0 * s.radius * double(-cos_out);
    return double(next.t) < 0.5 * chord;
}

// Spawns rays from the hits of `probes` into uniformly random directions on both sides of the
// surface and counts those that hit the surface again where they left it.
int count_self_hits(const TestScene& scene, const std::vector<Ray>& probes, int rays, uint64_t seed) {
    Rng rng(seed, 1);
    int self_hits = 0;
    for (int i = 0; i < rays; ++i) {
        auto hit = scene.accel->intersect(probes[size_t(i) % probes.size()]);
        if (!hit) continue;
        Vec3f w = Frame::from_normal(hit->ng).to_world(sample_uniform_sphere(rng.next_vec2f()));
        auto next = scene.accel->intersect(spawn_ray(*hit, w));
        if (next && is_self_hit(scene, *hit, w, *next)) ++self_hits;
    }
    return self_hits;
}

TEST(Accelerator, SpawnedRaysNeverHitTheirOwnSphere) {
    // A small sphere far from the origin and one of smallpt's huge walls.
    TestScene scene({}, {Sphere{{1000, -2000, 3000}, 0.5, false}, Sphere{{1e5 + 1, 40.8, 81.6}, 1e5, false}});
    Rng rng(3, 9);
    std::vector<Ray> probes;
    for (int i = 0; i < 4096; ++i) {
        Vec3f d = sample_uniform_sphere(rng.next_vec2f());
        // Aim at the small sphere from outside, and at the wall from inside smallpt's box.
        if (i % 2 == 0)
            probes.push_back(Ray{Vec3f(1000, -2000, 3000) - d * 5.0f, d});
        else
            probes.push_back(Ray{Vec3f(50.0f, 40.8f, 81.6f), Vec3f(-1.0f, 0.0f, 0.0f) * 0.9f + d * 0.1f});
    }
    for (Ray& r : probes) r.d = normalize(r.d);
    EXPECT_EQ(count_self_hits(scene, probes, 500000, 11), 0);
}

TEST(Accelerator, SpawnedRaysLeavePlanesThroughTheOriginWithDenormalsFlushed) {
    // Render threads flush denormals to zero (Embree asks for it). A floor at y = 0 (the Cornell
    // box's) has hit points with an exact y, so the offset must not be a denormal step that the
    // flush would undo.
    enable_flush_denormals();
    TriangleMesh floor = make_quad({552.8f, 0, 0}, {-552.8f, 0, 0}, {0, 0, 559.2f});
    TriangleMesh wall = make_quad({0, 0, 559.2f}, {0, 0, -559.2f}, {0, 548.8f, 0});
    TestScene scene({floor, wall}, {});
    Rng rng(17, 4);
    std::vector<Ray> probes;
    for (int i = 0; i < 4096; ++i) {
        Vec2f u = rng.next_vec2f();
        // From inside the box towards the floor and the wall.
        Vec3f target = i % 2 ? Vec3f(550.0f * u.x, 0.0f, 559.0f * u.y) : Vec3f(0.0f, 548.0f * u.x, 559.0f * u.y);
        probes.push_back(Ray{Vec3f(278, 273, 280), normalize(target - Vec3f(278, 273, 280))});
    }
    EXPECT_EQ(count_self_hits(scene, probes, 200000, 19), 0);
}

TEST(Accelerator, SpawnedRaysNeverHitTheirOwnTriangle) {
    // A closed box (12 triangles) at large coordinates, so ulps are big.
    TriangleMesh box;
    const float s = 0.5f;
    Vec3f c(-12345.0f, 678.0f, 4321.0f);
    for (int i = 0; i < 8; ++i) box.positions.push_back(c + Vec3f(i & 1 ? s : -s, i & 2 ? s : -s, i & 4 ? s : -s));
    box.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                   2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    TestScene scene({box}, {});
    Rng rng(5, 2);
    std::vector<Ray> probes;
    for (int i = 0; i < 4096; ++i) {
        Vec3f d = sample_uniform_sphere(rng.next_vec2f());
        probes.push_back(Ray{c - d * 3.0f, d});
    }
    EXPECT_EQ(count_self_hits(scene, probes, 500000, 13), 0);
}

}  // namespace
}  // namespace candela
