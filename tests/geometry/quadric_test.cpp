// Clipped quadrics (geometry/quadric.h): pbrt-v4's cylinder, partial sphere and partial disk.
// Intersections against closed forms (hit distance, (u, v), normal) with phi and z cutoffs, from
// outside and inside; pbrt-v4's parameter clamping; the derivatives against finite differences of
// the parameterisation; and the quadrics in the Embree accelerator: hit records, bounds that
// contain the surface, spawned rays that do not hit their own surface again.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/quadric_intersection.h"
#include "candela/geometry/ray_offset.h"
#include "candela/lights/quadric_emitter.h"
#include "candela/math/frame.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "support/quadric_points.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::expect_near;
using test::quadric_point_of_uv;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(QuadricIntersection, CylinderFromOutsideHitsTheNearSide) {
    const Quadric q = make_cylinder_quadric(1.0, -1.0, 1.0, 360.0, Transform(), false);
    auto hit = intersect_quadric(q, {3, 0, 0.2}, {-1, 0, 0}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    expect_near(hit->p, {1, 0, 0.2}, 1e-12);
    expect_near(quadric_normal(q, hit->p), {1, 0, 0}, 1e-12);
    const Vec2f uv = quadric_uv(q, hit->p, hit->phi);
    EXPECT_NEAR(uv.x, 0.0f, 1e-6f);
    EXPECT_NEAR(uv.y, 0.6f, 1e-6f);  // (0.2 - (-1)) / 2
    // Above zmax and below zmin it misses; a ray along the axis misses.
    EXPECT_FALSE(intersect_quadric(q, {3, 0, 1.2}, {-1, 0, 0}, 0.0, kInf));
    EXPECT_FALSE(intersect_quadric(q, {3, 0, -1.2}, {-1, 0, 0}, 0.0, kInf));
    EXPECT_FALSE(intersect_quadric(q, {0.5, 0, -5}, {0, 0, 1}, 0.0, kInf));
    // tmax before the surface.
    EXPECT_FALSE(intersect_quadric(q, {3, 0, 0.2}, {-1, 0, 0}, 0.0, 1.9));
}

TEST(QuadricIntersection, CylinderPhiCutRejectsTheNearHitAndTakesTheFarOne) {
    // phimax 90: the near crossing at phi = 150 degrees is cut away; the far one, at 30, is kept.
    const Quadric q = make_cylinder_quadric(1.0, -1.0, 1.0, 90.0, Transform(), false);
    const double x = std::sqrt(0.75);
    auto hit = intersect_quadric(q, {-3, 0.5, 0}, {1, 0, 0}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3 + x, 1e-12);
    expect_near(hit->p, {x, 0.5, 0}, 1e-12);
    EXPECT_NEAR(quadric_uv(q, hit->p, hit->phi).x, 30.0 / 90.0, 1e-6);
    // Both crossings cut away (phi 210 and 330 degrees).
    EXPECT_FALSE(intersect_quadric(q, {-3, -0.5, 0}, {1, 0, 0}, 0.0, kInf));
    // z cut: entering through the open top (outside the z range), leaving through the side.
    auto inside = intersect_quadric(make_cylinder_quadric(1.0, -1.0, 1.0, 360.0, Transform(), false), {0, 0, 2},
                                    normalize(Vec3d(1, 0, -1)), 0.0, kInf);
    ASSERT_TRUE(inside);
    expect_near(inside->p, {1, 0, 1}, 1e-9);
}

TEST(QuadricIntersection, CylinderFromInsideHitsTheWallItLooksAt) {
    const Quadric q = make_cylinder_quadric(2.0, 0.0, 3.0, 360.0, Transform(), true);
    auto hit = intersect_quadric(q, {0, 0, 1}, {0, 1, 0}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    // Reversed: the front is the inside, facing the origin.
    expect_near(quadric_normal(q, hit->p), {0, -1, 0}, 1e-12);
    EXPECT_NEAR(quadric_uv(q, hit->p, hit->phi).x, 0.25f, 1e-6f);
    EXPECT_NEAR(quadric_uv(q, hit->p, hit->phi).y, 1.0f / 3.0f, 1e-6f);
}

TEST(QuadricIntersection, PartialSphereZCutSeesThroughTheCapToTheFarSide) {
    // zmax 0.5: from above, the near crossing (z = 1) is cut away and the far one (z = -1) is hit.
    const Quadric q = make_sphere_quadric(1.0, -1.0, 0.5, 360.0, Transform(), false);
    auto hit = intersect_quadric(q, {0, 0, 5}, {0, 0, -1}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.0, 1e-12);
    EXPECT_NEAR(hit->p.z, -1.0, 1e-9);
    // On the pole pbrt-v4 moves x to 1e-5 r, where phi is defined.
    EXPECT_EQ(hit->p.x, 1e-5);
    expect_near(quadric_normal(q, hit->p), {0, 0, -1}, 2e-5);
    // v = (theta - theta_zmin) / (theta_zmax - theta_zmin): 0 at z_min (theta = pi).
    EXPECT_NEAR(quadric_uv(q, hit->p, hit->phi).y, 0.0f, 1e-6f);
    // A sideways ray at z = 0.7 only meets the cut-away cap.
    EXPECT_FALSE(intersect_quadric(q, {-3, 0, 0.7}, {1, 0, 0}, 0.0, kInf));
    // At z = 0: theta = pi / 2, v = (pi/2 - pi) / (pi/3 - pi) = 3/4; phi 180 -> u = 1/2.
    auto side = intersect_quadric(q, {-3, 0, 0}, {1, 0, 0}, 0.0, kInf);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 2.0, 1e-12);
    const Vec2f uv = quadric_uv(q, side->p, side->phi);
    EXPECT_NEAR(uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(uv.y, 0.75f, 1e-6f);
}

TEST(QuadricIntersection, PartialSpherePhiCutAndInside) {
    const Quadric q = make_sphere_quadric(2.0, -2.0, 2.0, 180.0, Transform(), false);
    // From inside at the centre, looking towards -y (phi = 270, cut away): nothing; towards +y: hit.
    EXPECT_FALSE(intersect_quadric(q, {0, 0, 0}, {0, -1, 0}, 0.0, kInf));
    auto hit = intersect_quadric(q, {0, 0, 0}, {0, 1, 0}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    expect_near(quadric_normal(q, hit->p), {0, 1, 0}, 1e-12);
    // From outside through the cut half: the far (kept) side is hit from within.
    auto far = intersect_quadric(q, {0.5, -5, 0}, {0, 1, 0}, 0.0, kInf);
    ASSERT_TRUE(far);
    EXPECT_GT(far->p.y, 0.0);
    EXPECT_NEAR(far->t, 5 + std::sqrt(4 - 0.25), 1e-12);
}

TEST(QuadricIntersection, PartialDiskRespectsInnerRadiusAndPhi) {
    const Quadric q = make_disk_quadric(0.5, 1.0, 0.5, 180.0, Transform(), false);
    auto hit = intersect_quadric(q, {0.7, 0.1, 2}, {0, 0, -1}, 0.0, kInf);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.5, 1e-12);
    expect_near(quadric_normal(q, hit->p), {0, 0, 1}, 0.0);
    const double r = std::hypot(0.7, 0.1);
    const Vec2f uv = quadric_uv(q, hit->p, hit->phi);
    EXPECT_NEAR(uv.x, std::atan2(0.1, 0.7) / kPiD, 1e-6);
    EXPECT_NEAR(uv.y, (1.0 - r) / 0.5, 1e-6);
    EXPECT_FALSE(intersect_quadric(q, {0.25, 0.1, 2}, {0, 0, -1}, 0.0, kInf));  // in the hole
    EXPECT_FALSE(intersect_quadric(q, {0.7, -0.1, 2}, {0, 0, -1}, 0.0, kInf));  // phi 352 degrees
    EXPECT_FALSE(intersect_quadric(q, {0.7, 0.1, 2}, {1, 0, 0}, 0.0, kInf));    // parallel
    // From below, the same point; the normal stays +z (the front side is not the ray's side).
    auto below = intersect_quadric(q, {0.7, 0.1, -2}, {0, 0, 1}, 0.0, kInf);
    ASSERT_TRUE(below);
    EXPECT_NEAR(below->t, 2.5, 1e-12);
}

TEST(Quadric, ParametersAreClampedAsPbrtV4Does) {
    // zmin and zmax swapped and beyond the radius; phimax above 360.
    const Quadric s = make_sphere_quadric(1.0, 3.0, -0.5, 400.0, Transform(), false);
    EXPECT_EQ(s.z_min, -0.5);
    EXPECT_EQ(s.z_max, 1.0);
    EXPECT_NEAR(s.phi_max, 2 * kPiD, 1e-15);
    EXPECT_FALSE(s.clips_z_max());
    EXPECT_TRUE(s.clips_z_min());
    EXPECT_NEAR(s.object_area(), 2 * kPiD * 1.5, 1e-12);
    const Quadric c = make_cylinder_quadric(2.0, 1.0, -1.0, 90.0, Transform(), false);
    EXPECT_EQ(c.z_min, -1.0);
    EXPECT_EQ(c.z_max, 1.0);
    EXPECT_NEAR(c.object_area(), 0.5 * kPiD * 2.0 * 2.0, 1e-12);
    const Quadric d = make_disk_quadric(0.0, 2.0, 1.0, 180.0, Transform(), false);
    EXPECT_NEAR(d.object_area(), 0.5 * kPiD * 3.0, 1e-12);
}

TEST(QuadricIntersection, TransformedHitsLieOnTheTransformedSurface) {
    // A rotated, unevenly scaled, translated cylinder: hits in object space satisfy x^2 + y^2 = r^2
    // and the world normal is perpendicular to the world surface (both tangents).
    const Transform m = Transform::translate({1, -2, 3}) * Transform::rotate(normalize(Vec3d(1, 2, 3)), 0.7) *
                        Transform::scale({2, 0.5, 1.5});
    const Quadric q = make_cylinder_quadric(0.8, -1.0, 2.0, 300.0, m, false);
    Rng rng(3, 4);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3d target = m.apply_point(Vec3d(rng.next_float() * 2 - 1, rng.next_float() * 2 - 1, rng.next_float() * 3 - 1));
        const Vec3d o = target + Vec3d(sample_uniform_sphere(rng.next_vec2f())) * 10.0;
        auto hit = intersect_quadric(q, o, target - o, 0.0, kInf);
        if (!hit) continue;
        ++hits;
        EXPECT_NEAR(std::hypot(hit->p.x, hit->p.y), 0.8, 1e-12);
        expect_near(q.to_world.apply_point(hit->p), o + (target - o) * hit->t, 1e-9);
        const ShadingGeometry g = quadric_shading_geometry(q, hit->p, Vec3f(quadric_normal(q, hit->p)));
        const Vec3d n = quadric_normal(q, hit->p);
        EXPECT_NEAR(dot(n, normalize(Vec3d(g.dpdu))), 0.0, 1e-5);
        EXPECT_NEAR(dot(n, normalize(Vec3d(g.dpdv))), 0.0, 1e-5);
    }
    EXPECT_GT(hits, 500);
}

// The point of (u, v) on each quadric, from pbrt-v4's parameterisation (the inverse of quadric_uv).
TEST(QuadricShadingGeometry, DerivativesAreThoseOfTheParameterisation) {
    const Transform m = Transform::translate({0.5, 1, -1}) * Transform::rotate(normalize(Vec3d(-1, 2, 0.5)), 1.1) *
                        Transform::scale({1.5, 1.5, 1.5});
    const Quadric quadrics[] = {make_cylinder_quadric(0.8, -1.0, 2.0, 300.0, m, false),
                                make_sphere_quadric(1.2, -0.7, 0.9, 250.0, m, false),
                                make_disk_quadric(0.3, 1.0, 0.4, 290.0, m, false)};
    const double h = 1e-6;
    for (const Quadric& q : quadrics) {
        for (double u : {0.1, 0.45, 0.8})
            for (double v : {0.2, 0.5, 0.9}) {
                const Vec3d p = quadric_point_of_uv(q, u, v);
                const ShadingGeometry g = quadric_shading_geometry(q, p, Vec3f(quadric_normal(q, p)));
                EXPECT_NEAR(g.uv.x, u, 1e-6);
                EXPECT_NEAR(g.uv.y, v, 1e-6);
                const Vec3d dpdu = (m.apply_point(quadric_point_of_uv(q, u + h, v)) - m.apply_point(quadric_point_of_uv(q, u - h, v))) / (2 * h);
                const Vec3d dpdv = (m.apply_point(quadric_point_of_uv(q, u, v + h)) - m.apply_point(quadric_point_of_uv(q, u, v - h))) / (2 * h);
                expect_near(Vec3d(g.dpdu), dpdu, 1e-4 * length(dpdu));
                expect_near(Vec3d(g.dpdv), dpdv, 1e-4 * length(dpdv));
                // The normal's derivatives, likewise, against the world normal of the neighbours.
                const Vec3d dndu = (quadric_normal(q, quadric_point_of_uv(q, u + h, v)) - quadric_normal(q, quadric_point_of_uv(q, u - h, v))) / (2 * h);
                const Vec3d dndv = (quadric_normal(q, quadric_point_of_uv(q, u, v + h)) - quadric_normal(q, quadric_point_of_uv(q, u, v - h))) / (2 * h);
                expect_near(Vec3d(g.dndu), dndu, 1e-4 * (1 + length(dndu)));
                expect_near(Vec3d(g.dndv), dndv, 1e-4 * (1 + length(dndv)));
                // pbrt-v4's orientation: cross(dpdu, dpdv) along the outward normal.
                EXPECT_GT(dot(cross(Vec3d(g.dpdu), Vec3d(g.dpdv)), quadric_normal(q, p)), 0.0);
            }
    }
}

TEST(Quadric, MirrorKeepsTheFrontSideAndReverseOrientationFlipsIt) {
    const Quadric mirrored = make_cylinder_quadric(1.0, -1.0, 1.0, 360.0, Transform::scale({-1, 1, 1}), false);
    expect_near(quadric_normal(mirrored, {1, 0, 0}), {-1, 0, 0}, 1e-15);  // world point (-1, 0, 0): outward
    const Quadric reversed = make_cylinder_quadric(1.0, -1.0, 1.0, 360.0, Transform(), true);
    expect_near(quadric_normal(reversed, {1, 0, 0}), {-1, 0, 0}, 1e-15);
}

struct QuadricScene {
    std::vector<Quadric> quadrics;
    std::vector<Shape> shapes;
    std::unique_ptr<Accelerator> accel;

    explicit QuadricScene(std::vector<Quadric> q) : quadrics(std::move(q)) {
        for (uint32_t i = 0; i < quadrics.size(); ++i) shapes.push_back({ShapeKind::kQuadric, i, 0, {}, false});
        accel = std::make_unique<Accelerator>(std::span<const TriangleMesh>{}, std::span<const Sphere>{},
                                              std::span<const Disk>{}, shapes, AlphaCutouts{}, Instancing{},
                                              std::span<const CurveSet>{}, quadrics);
    }
};

TEST(AcceleratorQuadric, HitCarriesPointNormalUvAndShading) {
    QuadricScene scene({make_cylinder_quadric(1.0, -1.0, 1.0, 270.0, Transform::translate({0, 0, 5}), false),
                        make_disk_quadric(0.0, 1.0, 0.5, 360.0, Transform(), true)});
    auto hit = scene.accel->intersect(Ray{{3.0f, 0.0f, 5.5f}, {-1, 0, 0}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shape_id, 0u);
    EXPECT_FLOAT_EQ(hit->t, 2.0f);
    EXPECT_EQ(hit->p, Vec3f(1.0f, 0.0f, 5.5f));
    EXPECT_EQ(hit->ng, Vec3f(1, 0, 0));
    EXPECT_GT(hit->p_error.x, 0.0f);
    EXPECT_NEAR(scene.accel->uv(*hit).y, 0.75f, 1e-6f);
    const ShadingGeometry g = scene.accel->shading(*hit);
    EXPECT_NEAR(g.uv.y, 0.75f, 1e-6f);
    EXPECT_NEAR(g.dpdv.z, 2.0f, 1e-6f);
    // The reversed annulus faces -z; the hole lets rays through.
    auto disk = scene.accel->intersect(Ray{{0.75f, 0.0f, 1.0f}, {0, 0, -1}});
    ASSERT_TRUE(disk);
    EXPECT_EQ(disk->shape_id, 1u);
    EXPECT_EQ(disk->ng, Vec3f(0, 0, -1));
    EXPECT_NEAR(scene.accel->uv(*disk).y, 0.5f, 1e-6f);
    EXPECT_FALSE(scene.accel->intersect(Ray{{0.25f, 0.0f, 1.0f}, {0, 0, -1}}));
    EXPECT_TRUE(scene.accel->occluded(Ray{{0.75f, 0.0f, 1.0f}, {0, 0, -1}, 0.0f, 2.0f}));
    EXPECT_FALSE(scene.accel->occluded(Ray{{0.75f, 0.0f, 1.0f}, {0, 0, -1}, 0.0f, 0.9f}));
}

TEST(AcceleratorQuadric, BoundsContainTheSurface) {
    const Transform m = Transform::translate({-3, 2, 7}) * Transform::rotate(normalize(Vec3d(2, -1, 1)), 2.3) *
                        Transform::scale({0.5, 3, 1.25});
    const std::vector<Quadric> quadrics = {make_cylinder_quadric(0.8, -1.0, 2.0, 300.0, m, false),
                                           make_sphere_quadric(1.2, -0.7, 0.9, 250.0, m, false),
                                           make_disk_quadric(0.3, 1.0, 0.4, 290.0, m, false)};
    for (const Quadric& q : quadrics) {
        QuadricScene scene({q});
        const Bounds3f b = scene.accel->bounds();
        const QuadricEmitter points(scene.quadrics[0]);
        Rng rng(9, 2);
        for (int i = 0; i < 10000; ++i) {
            const Vec3f p(q.to_world.apply_point(points.object_point(rng.next_vec2f())));
            EXPECT_TRUE(p.x >= b.lo.x && p.y >= b.lo.y && p.z >= b.lo.z && p.x <= b.hi.x && p.y <= b.hi.y &&
                        p.z <= b.hi.z);
        }
    }
}

TEST(AcceleratorQuadric, SpawnedRaysNeverHitTheirOwnConvexSurface) {
    // From a hit on the outside of a convex piece (a cylinder's outside, seen from outside) rays
    // leaving to the front never meet the same surface again; rays leaving to the back may meet
    // it legitimately (across the inside), so only front-side rays are counted.
    enable_flush_denormals();
    const Transform m = Transform::translate({120, -40, 33}) * Transform::rotate(normalize(Vec3d(1, 1, 0)), 0.4);
    QuadricScene scene({make_cylinder_quadric(2.0, -3.0, 3.0, 360.0, m, false), make_sphere_quadric(1.5, -1.5, 1.5, 360.0, Transform::translate({-50, 7, 3}), false)});
    Rng rng(5, 6);
    int self = 0, tried = 0;
    for (int i = 0; i < 100000; ++i) {
        const bool cyl = i % 2 == 0;
        const Vec3d c = cyl ? m.apply_point(Vec3d(0, 0, 0)) : Vec3d(-50, 7, 3);
        const Vec3d o = c + Vec3d(sample_uniform_sphere(rng.next_vec2f())) * 20.0;
        auto hit = scene.accel->intersect(Ray{Vec3f(o), Vec3f(normalize(c - o + Vec3d(sample_uniform_sphere(rng.next_vec2f()))))});
        if (!hit) continue;
        Vec3f w = Frame::from_normal(hit->ng).to_world(sample_uniform_hemisphere(rng.next_vec2f()));
        ++tried;
        auto next = scene.accel->intersect(spawn_ray(*hit, w));
        if (next && next->shape_id == hit->shape_id) ++self;
    }
    EXPECT_GT(tried, 50000);
    EXPECT_EQ(self, 0);
}

}  // namespace
}  // namespace candela
