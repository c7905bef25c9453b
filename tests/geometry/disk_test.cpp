// Disks (geometry/disk.h): the axes of the scene file's round disk, transforms (ellipses, mirrors,
// reverse_orientation), the precise intersection in double, pbrt-v4's (u, v) and its derivatives,
// and disks in the Embree accelerator: hit records, occlusion, bounds, alpha cutouts, and spawned
// rays that never hit the disk they leave.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/alpha_cutout.h"
#include "candela/geometry/disk.h"
#include "candela/geometry/disk_intersection.h"
#include "candela/geometry/ray_offset.h"
#include "candela/math/frame.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "support/quadric_points.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::expect_near;

TEST(Disk, RoundDiskFacingZHasPbrtsObjectAxes) {
    // pbrt-v4's Disk lies in z = height of its object space with phi measured from +x: a disk
    // facing +z must have u = 0 along +x.
    Disk d = make_round_disk({1, 2, 3}, {0, 0, 2}, 1.5);
    expect_near(d.axis_u, {1.5, 0, 0}, 0.0);
    expect_near(d.axis_v, {0, 1.5, 0}, 0.0);
    expect_near(d.normal, {0, 0, 1}, 0.0);
    EXPECT_DOUBLE_EQ(d.area(), kPiD * 2.25);
    Vec2<double> q = d.local(d.point(0.3, -0.4));
    EXPECT_NEAR(q.x, 0.3, 1e-15);
    EXPECT_NEAR(q.y, -0.4, 1e-15);
}

TEST(Disk, RoundDiskAxesAreOrthogonalRadiusLongAndRightHanded) {
    Rng rng(1, 2);
    for (int i = 0; i < 1000; ++i) {
        Vec3d n(sample_uniform_sphere(rng.next_vec2f()));
        Disk d = make_round_disk({0, 0, 0}, n * 3.0, 0.7);
        EXPECT_NEAR(length(d.axis_u), 0.7, 1e-12);
        EXPECT_NEAR(length(d.axis_v), 0.7, 1e-12);
        EXPECT_NEAR(dot(d.axis_u, d.axis_v), 0.0, 1e-12);
        expect_near(cross(d.axis_u, d.axis_v) / 0.49, normalize(n), 1e-9);
        EXPECT_NEAR(d.area(), kPiD * 0.49, 1e-12);
        // The dual basis gives back local coordinates.
        Vec2<double> q = d.local(d.point(-0.25, 0.5));
        EXPECT_NEAR(q.x, -0.25, 1e-12);
        EXPECT_NEAR(q.y, 0.5, 1e-12);
    }
}

TEST(Disk, UnevenScaleMakesAnEllipse) {
    Disk d = transform_disk(make_round_disk({0, 0, 0}, {0, 0, 1}, 1.0), Transform::scale({2, 0.5, 7}), false);
    EXPECT_NEAR(d.area(), kPiD * 2 * 0.5, 1e-12);
    expect_near(d.normal, {0, 0, 1}, 1e-15);
    // (1.8, 0, 0) is inside (x = 0.9), (0, 0.6, 0) outside (y = 1.2).
    EXPECT_TRUE(intersect_disk(d, {1.8, 0, 5}, {0, 0, -1}, 0.0, 1e30));
    EXPECT_FALSE(intersect_disk(d, {0, 0.6, 5}, {0, 0, -1}, 0.0, 1e30));
}

TEST(Disk, MirrorKeepsTheFrontSideAndReverseOrientationFlipsIt) {
    const Disk d = make_round_disk({0, 0, 1}, {0, 0, 1}, 1.0);
    // A mirror across the disk's own plane direction (z -> -z) moves the disk to z = -1; its
    // front side is carried along: it faces -z, as pbrt's rule keeps it (the normal transforms by
    // the inverse transpose).
    Disk mirrored = transform_disk(d, Transform::scale({1, 1, -1}), false);
    expect_near(mirrored.center, {0, 0, -1}, 0.0);
    expect_near(mirrored.normal, {0, 0, -1}, 0.0);
    // A mirror within the plane (x -> -x) leaves the front where it was.
    expect_near(transform_disk(d, Transform::scale({-1, 1, 1}), false).normal, {0, 0, 1}, 0.0);
    expect_near(transform_disk(d, Transform::scale({-1, 1, 1}), true).normal, {0, 0, -1}, 0.0);
    expect_near(transform_disk(d, Transform(), true).normal, {0, 0, -1}, 0.0);
}

TEST(DiskIntersection, HitsInsideTheRimOnly) {
    Disk d = make_round_disk({0, 1, 0}, {0, -1, 0}, 2.0);
    auto t = intersect_disk(d, {1.9, 3, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 2.0);
    // From behind, too: a disk is hit from both sides.
    EXPECT_TRUE(intersect_disk(d, {0, -3, 0}, {0, 2, 0}, 0.0, 1e30));
    EXPECT_FALSE(intersect_disk(d, {1.5, 3, 1.5}, {0, -1, 0}, 0.0, 1e30));  // r = 2.12
    EXPECT_FALSE(intersect_disk(d, {0, 1, -5}, {0, 0, 1}, 0.0, 1e30));       // in the plane
    EXPECT_FALSE(intersect_disk(d, {0, 3, 0}, {0, 1, 0}, 0.0, 1e30));        // going away
    EXPECT_FALSE(intersect_disk(d, {0, 3, 0}, {0, -1, 0}, 0.0, 2.0));        // t = tmax
    EXPECT_FALSE(intersect_disk(d, {0, 3, 0}, {0, -1, 0}, 2.0, 5.0));        // t = tmin
}

TEST(DiskIntersection, StaysPreciseFarFromTheOrigin) {
    // A disk of radius 1 at 1e5 seen from 1e5 further away: the hit lands on the plane within
    // double rounding, far below a float step there (2^-7).
    Disk d = make_round_disk({1e5, 2e5, -3e5}, {1, 1, 1}, 1.0);
    Vec3d target = d.point(0.6, -0.7);
    Vec3d o = target + normalize(Vec3d(0.3, 0.8, 0.5)) * 1e5;
    Vec3d dir = normalize(target - o);
    auto t = intersect_disk(d, o, dir, 0.0, 1e30);
    ASSERT_TRUE(t);
    Vec3d p = o + dir * *t;
    EXPECT_LT(std::abs(dot(p - d.center, d.normal)), 1e-9);
    expect_near(project_to_disk_plane(d, p), target, 1e-9);
}

TEST(DiskUv, FollowsPbrtsParameterisation) {
    Disk d = make_round_disk({0, 0, 0}, {0, 0, 1}, 2.0);
    auto uv = [&](double x, double y) { return disk_uv(d, {x, y, 0}); };
    EXPECT_FLOAT_EQ(uv(1, 0).x, 0.0f);  // u = phi / 2pi, phi from +x
    EXPECT_FLOAT_EQ(uv(1, 0).y, 0.5f);  // v = 1 - r / radius
    EXPECT_FLOAT_EQ(uv(0, 1).x, 0.25f);
    EXPECT_FLOAT_EQ(uv(-1, 0).x, 0.5f);
    EXPECT_FLOAT_EQ(uv(0, -2).x, 0.75f);
    EXPECT_FLOAT_EQ(uv(0, -2).y, 0.0f);
    EXPECT_FLOAT_EQ(uv(0, 0).y, 1.0f);
    // Just below phi = 2pi, u wraps to 0 rather than reaching 1.
    EXPECT_LT(uv(1, -1e-12).x, 1.0f);
}

TEST(DiskShadingGeometry, DerivativesAreThoseOfTheParameterisation) {
    // An ellipse, tilted: P(u, v) = center + (1 - v) (cos 2pi u axis_u + sin 2pi u axis_v).
    const Disk d = transform_disk(make_round_disk({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0),
                                  Transform::translate({1.0, -2.0, 0.5}) * Transform::rotate({1.0, 2.0, 0.0}, 0.7) *
                                      Transform::scale({1.5, 0.6, 1.0}),
                                  false);
    auto point = [&](double u, double v) {
        return d.point((1.0 - v) * std::cos(2.0 * kPiD * u), (1.0 - v) * std::sin(2.0 * kPiD * u));
    };
    for (auto [u, v] : {std::pair{0.1, 0.3}, std::pair{0.45, 0.8}, std::pair{0.9, 0.05}}) {
        const ShadingGeometry g = disk_shading_geometry(d, point(u, v));
        EXPECT_NEAR(g.uv.x, u, 1e-6);
        EXPECT_NEAR(g.uv.y, v, 1e-6);
        const double h = 1e-6;
        const Vec3d dpdu = (point(u + h, v) - point(u - h, v)) / (2.0 * h);
        const Vec3d dpdv = (point(u, v + h) - point(u, v - h)) / (2.0 * h);
        expect_near(Vec3d(g.dpdu), dpdu, 1e-5);
        expect_near(Vec3d(g.dpdv), dpdv, 1e-5);
        EXPECT_GT(dot(Vec3d(cross(g.dpdu, g.dpdv)), d.normal), 0.0);
        EXPECT_EQ(g.dndu, Vec3f(0.0f));
        EXPECT_EQ(g.dndv, Vec3f(0.0f));
    }
    // At the centre u is undefined: a unit frame around the normal stands in.
    const ShadingGeometry c = disk_shading_geometry(d, d.center);
    EXPECT_NEAR(dot(Vec3d(normalize(cross(c.dpdu, c.dpdv))), d.normal), 1.0, 1e-6);
}

// A scene of disks only, shape i = disk i, of the given alphas (none: all opaque).
struct DiskScene {
    std::vector<Disk> disks;
    std::vector<Shape> shapes;
    std::unique_ptr<Accelerator> accel;

    explicit DiskScene(std::vector<Disk> d, std::vector<float> alphas = {}) : disks(std::move(d)) {
        for (uint32_t i = 0; i < disks.size(); ++i) shapes.push_back({ShapeKind::kDisk, i, 0, {}, false});
        AlphaCutouts cutouts;
        for (float a : alphas) cutouts.shape_alpha.push_back(FloatParam{a});
        accel = std::make_unique<Accelerator>(std::span<const TriangleMesh>{}, std::span<const Sphere>{}, disks, shapes,
                                              cutouts);
    }
};

TEST(AcceleratorDisk, CutOutDisksLetRaysThroughWithProbabilityOneMinusAlpha) {
    // Two parallel disks; the near one (z = 1) of alpha 0, then 0.5; the far one (z = 2) opaque.
    const std::vector<Disk> disks = {make_round_disk({0, 0, 1}, {0, 0, -1}, 5.0), make_round_disk({0, 0, 2}, {0, 0, -1}, 5.0)};
    Rng rng(6, 1);
    DiskScene clear(disks, {0.0f, 1.0f});
    for (int i = 0; i < 200; ++i) {
        const Vec2f u = rng.next_vec2f();
        const Ray r{{u.x - 0.5f, u.y - 0.5f, 0.0f}, {0, 0, 1}};
        auto hit = clear.accel->intersect(r);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->shape_id, 1u);
        EXPECT_FALSE(clear.accel->occluded(Ray{r.o, r.d, 0.0f, 1.5f}));
    }
    DiskScene half(disks, {0.5f, 1.0f});
    const int n = 20000;
    int stopped = 0;
    for (int i = 0; i < n; ++i) {
        const Vec2f u = rng.next_vec2f();
        const Ray r{{u.x - 0.5f, u.y - 0.5f, 0.0f}, normalize(Vec3f(0.1f * u.y, -0.1f * u.x, 1.0f))};
        auto hit = half.accel->intersect(r);
        ASSERT_TRUE(hit);
        const bool near = hit->shape_id == 0u;
        stopped += near;
        // intersect() and occluded() agree on the same ray.
        EXPECT_EQ(half.accel->occluded(Ray{r.o, r.d, 0.0f, 1.5f}), near);
    }
    // Binomial(n, 1/2): standard deviation sqrt(n) / 2; 5 of them.
    EXPECT_NEAR(stopped, n / 2, 5.0 * std::sqrt(double(n)) / 2.0);
}

TEST(AcceleratorDisk, HitCarriesPointNormalUvAndIds) {
    DiskScene scene({make_round_disk({0, 0, 0}, {0, 0, 1}, 1.0),
                     transform_disk(make_round_disk({0, 0, 3}, {0, 0, 1}, 1.0), Transform(), true)});
    auto hit = scene.accel->intersect(Ray{{0.5f, 0.0f, 1.0f}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shape_id, 0u);
    EXPECT_EQ(hit->prim_id, 0u);
    EXPECT_FLOAT_EQ(hit->t, 1.0f);
    EXPECT_EQ(hit->p, Vec3f(0.5f, 0.0f, 0.0f));
    EXPECT_EQ(hit->ng, Vec3f(0, 0, 1));
    EXPECT_EQ(hit->ns, hit->ng);
    EXPECT_GT(hit->p_error.x, 0.0f);
    EXPECT_FLOAT_EQ(scene.accel->uv(*hit).x, 0.0f);
    EXPECT_FLOAT_EQ(scene.accel->uv(*hit).y, 0.5f);
    // The reversed disk above faces -z.
    auto up = scene.accel->intersect(Ray{{0.0f, 0.5f, 1.0f}, {0, 0, 1}});
    ASSERT_TRUE(up);
    EXPECT_EQ(up->shape_id, 1u);
    EXPECT_EQ(up->ng, Vec3f(0, 0, -1));
    EXPECT_FLOAT_EQ(scene.accel->uv(*up).x, 0.25f);
    EXPECT_FALSE(scene.accel->intersect(Ray{{1.1f, 0.0f, 1.0f}, {0, 0, -1}}));
}

TEST(AcceleratorDisk, OcclusionAndBounds) {
    DiskScene scene({transform_disk(make_round_disk({0, 0, 0}, {0, 0, 1}, 1.0), Transform::scale({3, 1, 1}), false)});
    EXPECT_TRUE(scene.accel->occluded(Ray{{2.9f, 0, 1}, {0, 0, -1}, 0.0f, 2.0f}));
    EXPECT_FALSE(scene.accel->occluded(Ray{{2.9f, 0, 1}, {0, 0, -1}, 0.0f, 0.9f}));
    EXPECT_FALSE(scene.accel->occluded(Ray{{0, 1.1f, 1}, {0, 0, -1}, 0.0f, 2.0f}));
    Bounds3f b = scene.accel->bounds();
    EXPECT_LE(b.lo.x, -3.0f);
    EXPECT_GE(b.hi.x, 3.0f);
    EXPECT_LE(b.lo.y, -1.0f);
    EXPECT_GE(b.hi.y, 1.0f);
    EXPECT_LE(b.lo.z, 0.0f);
    EXPECT_GE(b.hi.z, 0.0f);
    EXPECT_LT(b.hi.x, 3.001f);  // and tight
}

// Rays spawned from disk hits into random directions on both sides: a disk is planar, so any
// hit on it again is a self-hit.
int count_disk_self_hits(const DiskScene& scene, const std::vector<Ray>& probes, int rays, uint64_t seed) {
    Rng rng(seed, 1);
    int self_hits = 0;
    for (int i = 0; i < rays; ++i) {
        auto hit = scene.accel->intersect(probes[size_t(i) % probes.size()]);
        if (!hit) continue;
        Vec3f w = Frame::from_normal(hit->ng).to_world(sample_uniform_sphere(rng.next_vec2f()));
        auto next = scene.accel->intersect(spawn_ray(*hit, w));
        if (next && next->shape_id == hit->shape_id) ++self_hits;
    }
    return self_hits;
}

TEST(AcceleratorDisk, SpawnedRaysNeverHitTheirOwnDisk) {
    // A tilted disk far from the origin, a huge one (smallpt-sized), and a floor through the
    // origin with denormals flushed, as render threads run.
    enable_flush_denormals();
    DiskScene scene({make_round_disk({-12345, 678, 4321}, {0.3, -0.5, 0.8}, 0.5),
                     make_round_disk({1e5, 40, 80}, {-1, 0.01, 0}, 1e5), make_round_disk({0, 0, 0}, {0, 1, 0}, 500)});
    Rng rng(7, 3);
    std::vector<Ray> probes;
    for (int i = 0; i < 4096; ++i) {
        Vec2f u = rng.next_vec2f();
        Vec3f d = sample_uniform_sphere(u);
        if (i % 3 == 0) {
            Vec3f target = Vec3f(scene.disks[0].point(0.9 * (double(u.x) - 0.5), 0.9 * (double(u.y) - 0.5)));
            probes.push_back(Ray{target - d * 3.0f, d});
        } else if (i % 3 == 1) {
            probes.push_back(Ray{Vec3f(50.0f, 40.8f, 81.6f), normalize(Vec3f(1.0f, 0.0f, 0.0f) * 0.9f + d * 0.1f)});
        } else {
            Vec3f target(400.0f * u.x - 200.0f, 0.0f, 400.0f * u.y - 200.0f);
            probes.push_back(Ray{Vec3f(3, 273, 5), normalize(target - Vec3f(3, 273, 5))});
        }
    }
    EXPECT_EQ(count_disk_self_hits(scene, probes, 300000, 23), 0);
}

}  // namespace
}  // namespace candela
