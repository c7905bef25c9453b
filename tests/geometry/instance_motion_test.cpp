// Moving instances (geometry/instance_motion.h): the keys Embree interpolates give pbrt-v4's
// AnimatedTransform exactly where two keys can, and closely where sixteen stand in for it; a hit on a
// moving instance is the hit of the instance standing still where the keys put it at the ray's
// time; rays leaving such hits do not hit the surface again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/instance_motion.h"
#include "candela/geometry/ray_offset.h"
#include "candela/math/constants.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"

namespace candela {
namespace CANDELA_UNITY_ID {

double max_difference(const Transform& a, const Transform& b) {
    double d = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) d = std::max(d, std::abs(a.matrix()[i][j] - b.matrix()[i][j]));
    return d;
}

double degrees(double d) { return d * kPiD / 180.0; }

// A turn of 150 degrees about a tilted axis and a slide, with a non-uniform scale the same at both ends.
AnimatedTransform rigid_path(double t0 = 0.0, double t1 = 1.0) {
    const Transform scale = Transform::scale({0.5, 1.0, 2.0});
    const Transform start = Transform::translate({1, 2, 3}) * Transform::rotate({0, 1, 0}, degrees(10)) * scale;
    const Transform end = Transform::translate({-1, 0, 4}) * Transform::rotate({1, 1, 0.3}, degrees(150)) * scale;
    return AnimatedTransform(start, t0, end, t1);
}

TEST(InstanceMotion, TwoKeysArePbrtsInterpolationOfARigidMotion) {
    const AnimatedTransform path = rigid_path();
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, Transform()}, {0.0, 1.0});
    ASSERT_EQ(keys.keys.size(), 2u);
    for (int i = 0; i <= 20; ++i) {
        const float u = float(i) / 20.0f;
        EXPECT_LT(max_difference(keys.at(u), path.at(double(u))), 1e-9) << "u = " << u;
    }
    // The control: a blend of the two matrices (what one plain Embree time step per end gives).
    const Transform::Matrix &a = path.start().matrix(), &b = path.end().matrix();
    Transform::Matrix blend{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) blend[i][j] = 0.5 * (a[i][j] + b[i][j]);
    EXPECT_GT(max_difference(Transform(blend), path.at(0.5)), 0.1);
}

TEST(InstanceMotion, APlacementRidesAlongThePath) {
    // A moving shape: its geometry placed at the start, taken back by the placement.
    const AnimatedTransform path = rigid_path();
    const Transform placement = path.start().inverse();
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, placement}, {0.0, 1.0});
    ASSERT_EQ(keys.keys.size(), 2u);
    for (int i = 0; i <= 20; ++i) {
        const float u = float(i) / 20.0f;
        EXPECT_LT(max_difference(keys.at(u), path.at(double(u)) * placement), 1e-9) << "u = " << u;
    }
}

TEST(InstanceMotion, TheShutterPicksItsPartOfTheMotion) {
    // Motion times [-1, 3], shutter [0.5, 2]: ray time u is time 0.5 + 1.5 u.
    const AnimatedTransform path = rigid_path(-1.0, 3.0);
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, Transform()}, {0.5, 2.0});
    ASSERT_EQ(keys.keys.size(), 2u);
    for (int i = 0; i <= 10; ++i) {
        const float u = float(i) / 10.0f;
        EXPECT_LT(max_difference(keys.at(u), path.at(0.5 + 1.5 * double(u))), 1e-9) << "u = " << u;
    }
}

TEST(InstanceMotion, AMotionWithinTheShutterHoldsStillOutsideIt) {
    // Times [0.5, 1] of shutter [0, 1]: sixteen segments, still over the first half.
    const AnimatedTransform path = rigid_path(0.5, 1.0);
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, Transform()}, {0.0, 1.0});
    ASSERT_EQ(keys.keys.size(), size_t(kMotionSegments) + 1);
    for (float u : {0.0f, 0.1f, 0.3f, 0.5f}) EXPECT_LT(max_difference(keys.at(u), path.start()), 1e-9) << u;
    EXPECT_LT(max_difference(keys.at(1.0f), path.end()), 1e-9);
    for (int k = 8; k <= kMotionSegments; ++k) {
        const float u = float(k) / float(kMotionSegments);
        EXPECT_LT(max_difference(keys.at(u), path.at(double(u))), 1e-9) << "at key " << k;
    }
}

TEST(InstanceMotion, AChangingScaleIsFollowedClosely) {
    const Transform start = Transform::translate({0, 1, 0}) * Transform::scale({1, 1, 1});
    // A scale along axes turned 30 degrees about x: a symmetric S with shear terms, whose QR
    // factors turn as S changes.
    const Transform tilt = Transform::rotate({1, 0, 0}, degrees(30));
    const Transform end = Transform::translate({2, 1, 0}) * Transform::rotate({0, 0, 1}, degrees(90)) * tilt *
                          Transform::scale({3, 0.5, 1}) * tilt.inverse();
    const AnimatedTransform path(start, 0.0, end, 1.0);
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, Transform()}, {0.0, 1.0});
    ASSERT_EQ(keys.keys.size(), size_t(kMotionSegments) + 1);
    double worst = 0.0;
    for (int i = 0; i <= 160; ++i) {
        const float u = float(i) / 160.0f;
        worst = std::max(worst, max_difference(keys.at(u), path.at(double(u))));
    }
    std::printf("changing scale: worst matrix entry %.3g\n", worst);
    // Between keys 1/16 apart the error of interpolating the factors (not the path's) is
    // second order in the step: measured 1.1e-3 (of entries up to 3).
    EXPECT_LT(worst, 1e-2);
}

TEST(InstanceMotion, AMirroredPathStaysMirrored) {
    const Transform mirror = Transform::scale({-1, 1, 1});
    const AnimatedTransform path(Transform::translate({0, 0, 1}) * mirror, 0.0,
                                 Transform::translate({1, 0, 1}) * Transform::rotate({0, 1, 0}, degrees(40)) * mirror,
                                 1.0);
    const MotionKeys keys = make_motion_keys(InstanceMotion{path, Transform()}, {0.0, 1.0});
    EXPECT_LT(max_difference(keys.at(0.0f), path.start()), 1e-9);
    EXPECT_LT(max_difference(keys.at(1.0f), path.end()), 1e-9);
    for (float u : {0.25f, 0.5f, 0.75f}) {
        EXPECT_LT(keys.at(u).determinant(), 0.0);
        EXPECT_NEAR(std::abs(keys.at(u).determinant()), 1.0, 1e-9);
    }
}

// An object of a quad (shape 0) and a sphere (shape 1), placed once moving and once, for
// comparison, standing still where the moving one is at time u.
struct MovingWorld {
    std::vector<TriangleMesh> meshes{make_quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0})};
    std::vector<Sphere> spheres{Sphere{{3, 0, 0}, 0.75, false}};
    std::vector<Shape> shapes{{ShapeKind::kMesh, 0, 0, {}, false}, {ShapeKind::kSphere, 0, 0, {}, false}};
    std::vector<ObjectShapes> objects{{0, 2}};
    std::vector<Instance> instances;
    std::vector<InstanceMotion> motions;
    std::unique_ptr<Accelerator> accel;

    // Moving along `motion` (over shutter [0, 1]), or standing at `still`.
    explicit MovingWorld(const InstanceMotion& motion) : motions{motion} {
        Instance instance = make_instance(0, motion.path.start());
        instance.motion = 0;
        instances = {instance};
        accel = std::make_unique<Accelerator>(meshes, spheres, std::span<const Disk>{}, shapes, AlphaCutouts{},
                                              Instancing{objects, instances, motions, {0.0, 1.0}});
    }
    explicit MovingWorld(const Transform& still) {
        instances = {make_instance(0, still)};
        accel = std::make_unique<Accelerator>(meshes, spheres, std::span<const Disk>{}, shapes, AlphaCutouts{},
                                              Instancing{objects, instances});
    }
};

InstanceMotion test_motion() {
    const AnimatedTransform path(Transform::translate({0, 0, -5}), 0.0,
                                 Transform::translate({4, 1, -7}) * Transform::rotate({0.3, 1, 0.2}, degrees(120)),
                                 1.0);
    return InstanceMotion{path, Transform()};
}

TEST(InstanceMotion, AHitIsTheStillInstancesHitAtTheRaysTime) {
    const InstanceMotion motion = test_motion();
    const MovingWorld moving(motion);
    const MotionKeys keys = make_motion_keys(motion, {0.0, 1.0});
    Rng rng(7, 11);
    int hits = 0;
    double worst_point = 0.0, worst_normal = 0.0;
    for (int i = 0; i < 200; ++i) {
        const float u = rng.next_float();
        const Transform at = keys.at(u);
        const MovingWorld still(at);
        // Aim from near the origin at a point of the quad or the sphere as placed at time u.
        const Vec2f a = rng.next_vec2f() * 0.8f + Vec2f(0.1f, 0.1f);
        const Vec3d target = at.apply_point(i % 2 ? Vec3d(-1 + 2 * a.x, -1 + 2 * a.y, 0)
                                                  : Vec3d(3, 0, 0) + Vec3d(sample_uniform_sphere(a)) * 0.5);
        const Vec3f o(0.1f * rng.next_float(), 0.1f * rng.next_float(), 0.0f);
        Ray ray{o, normalize(Vec3f(target) - o)};
        ray.time = u;
        const std::optional<SurfaceHit> h = moving.accel->intersect(ray);
        Ray still_ray = ray;
        still_ray.time = 0.0f;
        const std::optional<SurfaceHit> s = still.accel->intersect(still_ray);
        ASSERT_EQ(h.has_value(), s.has_value()) << "ray " << i << " at u = " << u;
        if (!h) continue;
        ++hits;
        EXPECT_EQ(h->shape_id, s->shape_id);
        EXPECT_EQ(h->time, u);
        worst_point = std::max(worst_point, double(length(h->p - s->p) / std::max(1.0f, max_component(abs(s->p)))));
        worst_normal = std::max(worst_normal, double(length(h->ns - s->ns)));
        EXPECT_NEAR(moving.accel->uv(*h).x, still.accel->uv(*s).x, 1e-4f);
    }
    std::printf("moving instance: %d hits, worst point %.3g, worst normal %.3g\n", hits, worst_point, worst_normal);
    EXPECT_GT(hits, 150);
    // The same transform, so the same hits but for Embree's own interpolation of t (it traces the
    // moving instance in its float placement at u): measured 3.2e-6 and 3.9e-6.
    EXPECT_LT(worst_point, 1e-5);
    EXPECT_LT(worst_normal, 1e-5);
}

TEST(InstanceMotion, RaysLeavingAMovingSurfaceDoNotHitItAgain) {
    const InstanceMotion motion = test_motion();
    const MovingWorld moving(motion);
    const MotionKeys keys = make_motion_keys(motion, {0.0, 1.0});
    Rng rng(3, 5);
    int hits = 0, again = 0;
    double worst_gap = 0.0;  // Embree's t against the keys' point, relative to |p|
    for (int i = 0; i < 20000; ++i) {
        const float u = rng.next_float();
        const Transform at = keys.at(u);
        const Vec2f a = rng.next_vec2f() * 0.98f + Vec2f(0.01f, 0.01f);
        const Vec3d target = at.apply_point(i % 2 ? Vec3d(-1 + 2 * a.x, -1 + 2 * a.y, 0)
                                                  : Vec3d(3, 0, 0) + Vec3d(sample_uniform_sphere(a)) * 0.75);
        const Vec3f o(0.0f, 0.0f, 1.0f);
        Ray ray{o, normalize(Vec3f(target) - o)};
        ray.time = u;
        const std::optional<SurfaceHit> h = moving.accel->intersect(ray);
        if (!h) continue;
        ++hits;
        worst_gap = std::max(worst_gap, double(length(ray.at(h->t) - h->p) / max_component(abs(h->p))));
        // Back to the side the ray came from, grazing: neither the plane nor the sphere (convex) can be
        // met again. On through the plane (not the sphere, whose far side is there): nor can it.
        const Vec3f n = h->front_face(ray.d) ? h->ng : -h->ng;
        Ray out = spawn_ray(*h, normalize(n + ray.d * 0.999f));
        EXPECT_EQ(out.time, u);
        if (const std::optional<SurfaceHit> next = moving.accel->intersect(out); next && next->shape_id == h->shape_id)
            ++again;
        if (h->shape_id == 0) {
            const Ray through = spawn_ray(*h, normalize(ray.d + n * 1e-3f));
            if (const std::optional<SurfaceHit> next = moving.accel->intersect(through); next && next->shape_id == 0)
                ++again;
        }
    }
    std::printf("moving instance: %d hits, Embree's point from the keys' by at most %.3g |p|\n", hits, worst_gap);
    EXPECT_GT(hits, 15000);
    EXPECT_EQ(again, 0);
}

TEST(InstanceMotion, TheRaysTimeChoosesWhereTheInstanceIs) {
    const InstanceMotion motion{AnimatedTransform(Transform(), 0.0, Transform::translate({6, 0, 0}), 1.0), Transform()};
    const MovingWorld moving(motion);
    // Rays down -z at height 0.9, above the sphere: the quad at z = 0 spans x in [-1, 1] at time 0,
    // [5, 7] at time 1.
    auto hits_at = [&](float x, float u) {
        Ray ray{{x, 0.9f, 5.0f}, {0.0f, 0.0f, -1.0f}};
        ray.time = u;
        return moving.accel->intersect(ray).has_value();
    };
    EXPECT_TRUE(hits_at(0.0f, 0.0f));
    EXPECT_FALSE(hits_at(0.0f, 1.0f));
    EXPECT_TRUE(hits_at(6.0f, 1.0f));
    EXPECT_FALSE(hits_at(6.0f, 0.0f));
    EXPECT_TRUE(hits_at(3.0f, 0.5f));
    // Shadow rays too.
    Ray shadow{{3.0f, 0.9f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    shadow.time = 0.5f;
    EXPECT_TRUE(moving.accel->occluded(shadow));
    shadow.time = 0.0f;
    EXPECT_FALSE(moving.accel->occluded(shadow));
}

}  // namespace
}  // namespace candela
