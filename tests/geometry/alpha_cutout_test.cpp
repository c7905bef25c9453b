// Alpha cutouts (alpha_cutout.h): rays pass through surfaces with probability 1 - alpha, decided
// by a hash of the ray and primitive, in intersect() and occluded() alike.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A plane quad at z = 1 (shape 0) of the given alpha in front of an opaque one at z = 2
// (shape 1), both wide enough for every test ray; and a sphere of the given alpha at z = 10.
struct CutoutScene {
    std::vector<TriangleMesh> meshes = {make_quad({-10, -10, 1}, {20, 0, 0}, {0, 20, 0}),
                                        make_quad({-10, -10, 2}, {20, 0, 0}, {0, 20, 0})};
    std::vector<Sphere> spheres = {Sphere{{100, 0, 10}, 1.0, false}};
    std::vector<Shape> shapes = {{ShapeKind::kMesh, 0, 0, {}, false},
                                 {ShapeKind::kMesh, 1, 0, {}, false},
                                 {ShapeKind::kSphere, 0, 0, {}, false}};
    std::unique_ptr<Accelerator> accel;

    explicit CutoutScene(float alpha) {
        AlphaCutouts cutouts;
        cutouts.shape_alpha = {FloatParam{alpha}, FloatParam{1.0f}, FloatParam{alpha}};
        accel = std::make_unique<Accelerator>(meshes, spheres, shapes, cutouts);
    }
};

// A ray from near the origin, towards +z, a little off axis: each ray is different.
Ray random_ray(Rng& rng, Vec3f o = Vec3f(0.0f)) {
    Vec2f u = rng.next_vec2f();
    return Ray{o + Vec3f(u.x - 0.5f, u.y - 0.5f, 0.0f), normalize(Vec3f(0.2f * u.y - 0.1f, 0.2f * u.x - 0.1f, 1.0f))};
}

TEST(AlphaCutout, HashIsUniformAndDependsOnEveryInput) {
    const Vec3f o(0.1f, 0.2f, 0.3f), d(0.0f, 0.6f, 0.8f);
    const float h = alpha_hash(o, d, 3, 7);
    EXPECT_EQ(h, alpha_hash(o, d, 3, 7));
    EXPECT_NE(h, alpha_hash(Vec3f(0.1f, 0.2f, 0.30001f), d, 3, 7));
    EXPECT_NE(h, alpha_hash(o, Vec3f(0.0f, 0.6f, 0.80001f), 3, 7));
    EXPECT_NE(h, alpha_hash(o, d, 4, 7));
    EXPECT_NE(h, alpha_hash(o, d, 3, 8));
    // Uniform in [0, 1): the mean of n hashes is 1/2 with variance 1 / (12 n).
    Rng rng(1, 2);
    const int n = 100000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const float u = alpha_hash(Vec3f(rng.next_float()), Vec3f(0, 0, 1), 0, uint32_t(i));
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        sum += double(u);
    }
    EXPECT_LT(std::abs(sum / n - 0.5) / std::sqrt(1.0 / (12.0 * n)), 4.0);
    EXPECT_TRUE(alpha_stops(1.0f, 0x1.fffffep-1f));
    EXPECT_FALSE(alpha_stops(0.0f, 0.0f));
}

TEST(AlphaCutout, TransparentSurfacesAreInvisibleToEveryQuery) {
    CutoutScene scene(0.0f);
    Rng rng(2, 3);
    for (int i = 0; i < 1000; ++i) {
        const Ray r = random_ray(rng);
        auto hit = scene.accel->intersect(r);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->shape_id, 1u);
        EXPECT_FALSE(scene.accel->occluded(Ray{r.o, r.d, 0.0f, 1.5f}));  // would end past the plane
        // The sphere too (user geometry: the test is in its own intersection function).
        const Ray at_sphere{Vec3f(100, 0, 5) + (r.o * 0.5f), Vec3f(0, 0, 1)};
        auto past = scene.accel->intersect(at_sphere);
        EXPECT_FALSE(past && past->shape_id == 2u);
        EXPECT_FALSE(scene.accel->occluded(at_sphere));
    }
}

TEST(AlphaCutout, OpaqueShapesAndAlphaOneAreUnchanged) {
    CutoutScene scene(1.0f);
    Rng rng(4, 5);
    for (int i = 0; i < 100; ++i) {
        const Ray r = random_ray(rng);
        auto hit = scene.accel->intersect(r);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->shape_id, 0u);
        EXPECT_TRUE(scene.accel->occluded(Ray{r.o, r.d, 0.0f, 1.5f}));
    }
    EXPECT_FALSE(AlphaCutouts{}.cuts(0));
}

// A textured alpha: a checkerboard of alpha 1 (color0) and 0 (color1) cells on the front
// quad, whose uv is ((x + 10) / 20, (y + 10) / 20): with uv_scale 40, cells of 1/2 in x and y.
TEST(AlphaCutout, TexturedAlphaCutsWhereTheTextureIsZero) {
    CutoutScene plain(1.0f);
    TextureSet textures;
    CheckerboardTexture checks;
    checks.color0 = ColorParam{Rgb(1.0f)};
    checks.color1 = ColorParam{Rgb(0.0f)};
    checks.uv.scale = Vec2f(40.0f, 40.0f);
    AlphaCutouts cutouts;
    cutouts.shape_alpha = {FloatParam{1.0f, textures.add(checks), 0.0f, 1.0f}, FloatParam{1.0f}, FloatParam{1.0f}};
    cutouts.textures = &textures;
    Accelerator accel(plain.meshes, plain.spheres, plain.shapes, cutouts);
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            // The centre of cell (i, j): s = 2 x + 20 = 16.5 + i, t = 16.5 + j, so
            // floor(s) + floor(t) is even (color0, opaque) when i + j is.
            const Vec3f o(-2.0f + 0.5f * float(i) + 0.25f, -2.0f + 0.5f * float(j) + 0.25f, 0.0f);
            const Ray r{o, Vec3f(0, 0, 1)};
            auto hit = accel.intersect(r);
            ASSERT_TRUE(hit);
            const bool opaque = (i + j) % 2 == 0;
            EXPECT_EQ(hit->shape_id, opaque ? 0u : 1u) << i << ", " << j;
            EXPECT_EQ(accel.occluded(Ray{r.o, r.d, 0.0f, 1.5f}), opaque);
        }
    }
}

// The fraction of n rays that stop at a surface of alpha 1/2 is binomial: mean 1/2, variance
// 1 / (4 n). For the sphere, a ray passing the near side meets the far one: it stops at the near
// side with probability 1/2, at the far side with 1/4, and passes with 1/4.
TEST(AlphaCutout, HalfTransparentSurfacesStopHalfTheRays) {
    CutoutScene scene(0.5f);
    Rng rng(6, 7);
    const int n = 20000;
    int plane_hits = 0, plane_occluded = 0, near_side = 0, far_side = 0, sphere_occluded = 0;
    for (int i = 0; i < n; ++i) {
        const Ray r = random_ray(rng);
        auto hit = scene.accel->intersect(r);
        ASSERT_TRUE(hit);
        plane_hits += hit->shape_id == 0u;
        const bool blocked = scene.accel->occluded(Ray{r.o, r.d, 0.0f, 1.5f});
        plane_occluded += blocked;
        EXPECT_EQ(blocked, hit->shape_id == 0u);  // the same ray gets the same answer from both

        const Vec2f u = rng.next_vec2f();
        const Ray at_sphere{Vec3f(100.0f + 0.5f * (u.x - 0.5f), 0.5f * (u.y - 0.5f), 5.0f), Vec3f(0, 0, 1)};
        auto s = scene.accel->intersect(at_sphere);
        if (s && s->shape_id == 2u) (s->p.z < 10.0f ? near_side : far_side) += 1;
        sphere_occluded += scene.accel->occluded(at_sphere);
    }
    auto z = [n](int count, double p) { return (count - n * p) / std::sqrt(n * p * (1.0 - p)); };
    EXPECT_LT(std::abs(z(plane_hits, 0.5)), 4.0);
    EXPECT_LT(std::abs(z(plane_occluded, 0.5)), 4.0);
    EXPECT_LT(std::abs(z(near_side, 0.5)), 4.0);
    EXPECT_LT(std::abs(z(far_side, 0.25)), 4.0);
    EXPECT_LT(std::abs(z(sphere_occluded, 0.75)), 4.0);
}

}  // namespace
}  // namespace candela
