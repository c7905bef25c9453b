// Instances (geometry/instance.h): a shape reached through an instance gives the hit that the same
// shape placed directly by the instance's transform gives (point, normals, uv, shading geometry),
// to float precision; the hit names the object's shape and the instance; rays spawned from it do
// not hit it again.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/ray_offset.h"
#include "candela/math/constants.h"
#include "candela/math/frame.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "candela/textures/texture_kinds.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The object: a quad with tilted vertex normals (shape 0), a disk (shape 1) and, for similarity
// transforms, an inside-out sphere (shape 2), apart from each other in object space.
struct ObjectParts {
    TriangleMesh quad;
    Disk disk;
    Sphere sphere;
};

ObjectParts object_parts() {
    ObjectParts o;
    o.quad = make_quad({-4, -1, 0}, {2, 0, 0}, {0, 2, 0.5f});
    o.quad.normals = {normalize(Vec3f(0.1f, 0, 1)), normalize(Vec3f(0, 0.1f, 1)), normalize(Vec3f(-0.1f, 0, 1)),
                      normalize(Vec3f(0, -0.1f, 1))};
    o.disk = make_round_disk({2.5, 0, 0}, {0.2, 0.1, 1}, 1.0);
    o.sphere = Sphere{{0, 0, 0}, 1.0, true};
    return o;
}

// Point `k` of shape `shape` at random numbers u, in object space, away from edges and seams.
Vec3d object_point(const ObjectParts& o, int shape, Vec2f u) {
    u = u * 0.8f + Vec2f(0.1f, 0.1f);
    if (shape == 0) return Vec3d(Vec3f(-4, -1, 0) + Vec3f(2, 0, 0) * u.x + Vec3f(0, 2, 0.5f) * u.y);
    if (shape == 1) {
        const double r = std::sqrt(double(u.x)), phi = 2.0 * kPiD * double(u.y);
        return o.disk.point(r * std::cos(phi), r * std::sin(phi));
    }
    return Vec3d(sample_uniform_sphere(u));
}

// One world: the instanced object (twice: a decoy instance far away, then the one under test)
// or the same shapes placed directly by `to_world`.
struct World {
    std::vector<TriangleMesh> meshes;
    std::vector<Sphere> spheres;
    std::vector<Disk> disks;
    std::vector<Shape> shapes;
    std::vector<ObjectShapes> objects;
    std::vector<Instance> instances;
    std::unique_ptr<Accelerator> accel;

    World(const ObjectParts& o, const Transform& to_world, bool sphere, bool instanced) {
        meshes = {o.quad};
        disks = {o.disk};
        if (sphere) spheres = {o.sphere};
        if (instanced) {
            instances = {make_instance(0, Transform::translate({0, 1000, 0})), make_instance(0, to_world)};
        } else {
            transform_mesh(meshes[0], to_world, false);
            disks[0] = transform_disk(disks[0], to_world, false);
            if (sphere) {
                // A similarity: the radius scales by the cube root of |det|.
                spheres[0].center = to_world.apply_point(o.sphere.center);
                spheres[0].radius = o.sphere.radius * std::cbrt(std::abs(to_world.determinant()));
            }
        }
        shapes = {{ShapeKind::kMesh, 0, 0, {}, false}, {ShapeKind::kDisk, 0, 0, {}, false}};
        if (sphere) shapes.push_back({ShapeKind::kSphere, 0, 0, {}, false});
        if (instanced) objects = {{0, uint32_t(shapes.size())}};
        accel = std::make_unique<Accelerator>(meshes, spheres, disks, shapes, AlphaCutouts{},
                                              Instancing{objects, instances});
    }
};

// The angle between unit vectors, to first order (acos near 1 would lose the small ones to rounding).
float angle_between(const Vec3f& a, const Vec3f& b) { return length(a - b); }

// Relative agreement of two vectors.
float relative_difference(const Vec3f& a, const Vec3f& b) { return length(a - b) / std::max(length(b), 1e-30f); }

// Shoots rays at points of every shape through both worlds and compares the hits. An instanced
// mesh interpolates its vertex normals in object space, a directly placed one in the world: under
// an uneven scale the shading normals differ by up to `ns_tolerance` (radians). A sphere's uv is
// the object's, which a directly placed sphere has only when the transform neither rotates nor
// mirrors (`sphere_uv`).
void expect_same_hits(const Transform& to_world, bool sphere, float ns_tolerance, bool sphere_uv) {
    const ObjectParts o = object_parts();
    const World instanced(o, to_world, sphere, true), direct(o, to_world, sphere, false);
    Rng rng(7, 3);
    const int shapes = sphere ? 3 : 2;
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const int shape = i % shapes;
        const Vec3f target(to_world.apply_point(object_point(o, shape, rng.next_vec2f())));
        const Vec3f from = target + sample_uniform_sphere(rng.next_vec2f()) * 30.0f;
        const Ray ray{from, normalize(target - from)};
        const auto a = instanced.accel->intersect(ray), b = direct.accel->intersect(ray);
        // A ray that only grazes a surface may hit it in one world and miss it in the other.
        if (bool(a) != bool(b)) {
            const SurfaceHit& only = a ? *a : *b;
            EXPECT_LT(std::abs(dot(ray.d, only.ng)), 0.01f) << i;
            continue;
        }
        if (!a) continue;
        ASSERT_EQ(a->shape_id, b->shape_id) << i;  // the object's shape ids are the scene's
        EXPECT_EQ(a->instance, 1u);
        ++hits;
        // Embree moves the ray into object space in float, which perturbs it by a few ulps of its
        // length; where it crosses the surface at a grazing angle, that moves the hit along the
        // ray by as much over the cosine. The bounds scale so (and the most grazing hits, whose
        // position no float ray pins down, are left out).
        const float cosine = std::abs(dot(ray.d, b->ng));
        if (cosine < 0.05f) continue;
        const float scale = std::max({1.0f, max_component(abs(from)), b->t}) / cosine;
        EXPECT_NEAR(a->t, b->t, 2e-6f * scale) << i;
        EXPECT_LT(length(a->p - b->p), 4e-6f * scale) << i;
        EXPECT_LT(angle_between(a->ng, b->ng), 1e-3f) << i << " shape " << a->shape_id;
        EXPECT_LT(angle_between(a->ns, b->ns), ns_tolerance) << i;
        EXPECT_GT(a->p_error.x, 0.0f);
        if (a->shape_id == 2 && !sphere_uv) continue;
        const Vec2f uva = instanced.accel->uv(*a), uvb = direct.accel->uv(*b);
        // uv moves with the point: by |dp| / |dpdu| at most, dpdu being at least about 1 here.
        EXPECT_NEAR(uva.x, uvb.x, 4e-6f * scale) << i;
        EXPECT_NEAR(uva.y, uvb.y, 4e-6f * scale) << i;
        const ShadingGeometry ga = instanced.accel->shading(*a), gb = direct.accel->shading(*b);
        EXPECT_LT(relative_difference(ga.dpdu, gb.dpdu), 1e-3f) << i << " shape " << a->shape_id;
        EXPECT_LT(relative_difference(ga.dpdv, gb.dpdv), 1e-3f) << i;
        EXPECT_LT(length(ga.dndu - gb.dndu), 2e-3f * std::max(1.0f, length(gb.dndu))) << i << " shape " << a->shape_id;
    }
    EXPECT_GT(hits, 2500);  // nearly every ray reaches its target (a few pass behind other shapes)
}

// Rotated, mirrored (det < 0) and uniformly scaled: spheres stay spheres, so all three kinds.
TEST(Instance, HitsMatchDirectPlacementUnderAMirroringSimilarity) {
    const Transform t = Transform::translate({10, -3, 7}) * Transform::rotate({1, 2, 3}, 0.7) *
                        Transform::scale({-1.5, 1.5, 1.5});
    ASSERT_TRUE(t.swaps_handedness());
    expect_same_hits(t, true, 1e-4f, false);
    expect_same_hits(Transform::translate({1, 2, -30}) * Transform::scale(Vec3d(0.5)), true, 1e-4f, true);
}

// A general affine map (uneven scale, shear by rotation after it): meshes and disks.
TEST(Instance, HitsMatchDirectPlacementUnderAnUnevenScale) {
    const Transform t = Transform::rotate({0, 1, 1}, -0.4) * Transform::scale({3, 0.5, 1.25}) *
                        Transform::rotate({1, 0, 0}, 0.3);
    expect_same_hits(Transform::translate({-20, 5, 0}) * t, false, 1e-2f, false);
    expect_same_hits(Transform::scale({1, -1, 1}) * t, false, 1e-2f, false);  // mirrored too
}

TEST(Instance, MissesAndOcclusionAndBounds) {
    const ObjectParts o = object_parts();
    const World w(o, Transform::translate({0, 0, 50}), true, true);
    // The sphere of the instance at z = 50, and of the decoy at y = 1000.
    EXPECT_TRUE(w.accel->occluded(Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f}));
    EXPECT_FALSE(w.accel->occluded(Ray{{0, 0, 0}, {0, 0, 1}, 0.0f, 40.0f}));
    EXPECT_FALSE(w.accel->intersect(Ray{{0, 0, 0}, {0, 0, -1}}));
    const auto decoy = w.accel->intersect(Ray{{0, 1000, -10}, {0, 0, 1}});
    ASSERT_TRUE(decoy);
    EXPECT_EQ(decoy->instance, 0u);
    EXPECT_EQ(decoy->shape_id, 2u);
    EXPECT_NEAR(decoy->p.z, -1.0f, 1e-5f);
    EXPECT_NEAR(decoy->ng.z, 1.0f, 1e-6f);  // the sphere is inside-out: its front faces the centre
    const Bounds3f b = w.accel->bounds();
    EXPECT_LE(b.lo.y, -1.0f);
    EXPECT_GE(b.hi.y, 1001.0f);
    EXPECT_GE(b.hi.z, 51.0f);
}

// Rays leaving an instanced surface (offset by the hit's error bound, carried to the world) never
// hit the same planar or convex surface again on the way out, far from the origin too.
TEST(Instance, SpawnedRaysDoNotHitTheirOwnSurface) {
    const ObjectParts o = object_parts();
    const Transform t = Transform::translate({3000, -2000, 1000}) * Transform::rotate({1, 1, 0}, 1.1) *
                        Transform::scale({0.01, 0.02, 0.01});
    const World w(o, t, false, true);
    Rng rng(5, 1);
    int self_hits = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const int shape = i % 2;
        const Vec3f target(t.apply_point(object_point(o, shape, rng.next_vec2f())));
        const Vec3f from = target + sample_uniform_sphere(rng.next_vec2f()) * 0.5f;
        const auto hit = w.accel->intersect(Ray{from, normalize(target - from)});
        if (!hit) continue;
        ++hits;
        const Vec3f dir = Frame::from_normal(hit->ng).to_world(sample_uniform_sphere(rng.next_vec2f()));
        const auto next = w.accel->intersect(spawn_ray(*hit, dir));
        // The quad and the disk are planar: any hit on the same shape is a self-hit.
        if (next && next->shape_id == hit->shape_id && next->instance == hit->instance) ++self_hits;
    }
    EXPECT_GT(hits, 15000);
    EXPECT_EQ(self_hits, 0);
}

// Alpha cutouts through an instance: a quad of the object, cut by a checkerboard of its own uv,
// shows the checkerboard wherever the instance places it (the test runs in object space, on the
// object's uv), to intersect() and occluded() alike.
TEST(Instance, AlphaCutoutsCutInstancedShapes) {
    TextureSet textures;
    CheckerboardTexture checks;
    checks.color0 = ColorParam{Rgb(1.0f)};
    checks.color1 = ColorParam{Rgb(0.0f)};
    checks.uv.scale = Vec2f(4.0f, 4.0f);
    AlphaCutouts cutouts;
    cutouts.shape_alpha = {FloatParam{1.0f, textures.add(checks), 0.0f, 1.0f}};
    cutouts.textures = &textures;
    const std::vector<TriangleMesh> meshes = {make_quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0})};
    const std::vector<Shape> shapes = {{ShapeKind::kMesh, 0, 0, {}, false}};
    const std::vector<ObjectShapes> objects = {{0, 1}};
    // Stretched to 8 x 8, turned a quarter about z (u runs along +y), and moved to z = 5.
    const Transform t =
        Transform::translate({0, 0, 5}) * Transform::rotate({0, 0, 1}, kPiD / 2) * Transform::scale({8, 8, 1});
    const std::vector<Instance> instances = {make_instance(0, t)};
    const Accelerator accel(meshes, {}, {}, shapes, cutouts, Instancing{objects, instances});
    int opaque_cells = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            // The centre of uv cell (i, j) in the world: x = -(v * 8), y = u * 8.
            const Vec3f o(-(float(j) + 0.5f) * 2.0f, (float(i) + 0.5f) * 2.0f, 0.0f);
            const Ray r{o, Vec3f(0, 0, 1)};
            const bool opaque = (i + j) % 2 == 0;
            const auto hit = accel.intersect(r);
            EXPECT_EQ(bool(hit), opaque) << i << ", " << j;
            EXPECT_EQ(accel.occluded(Ray{o, r.d, 0.0f, 10.0f}), opaque) << i << ", " << j;
            if (hit) {
                EXPECT_NEAR(accel.uv(*hit).x, (float(i) + 0.5f) / 4.0f, 1e-5f);
                EXPECT_NEAR(accel.uv(*hit).y, (float(j) + 0.5f) / 4.0f, 1e-5f);
            }
            opaque_cells += opaque;
        }
    }
    EXPECT_EQ(opaque_cells, 8);
}

}  // namespace
}  // namespace candela
