// LightSet: which shapes are lights, selection probabilities, one- and two-sided radiance, mesh
// samples on their triangles with the normals hits report, the solid angle density against
// closed forms, and pdf() equal to the pdf sample() returns, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/sphere_intersection.h"
#include "candela/sampling/warps.h"
#include "candela/sampling/rng.h"
#include "lights/light_test_scene.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

const Vec3f kOrigin{0.0f, 0.0f, 0.0f};

// Three lights of different kinds and one plain shape:
//   0: one-sided quad 2 x 0.5 at z = 2 facing -z, emission (1, 2, 3)
//   1: plain sphere (not a light)
//   2: sphere r = 0.5, emission (4, 4, 4)
//   3: two-sided triangle of area 1, emission (0.5, 0, 0)
LightTestScene three_lights() {
    LightTestScene scene;
    scene.add_mesh(make_quad({-1.0f, -0.25f, 2.0f}, {0.0f, 0.5f, 0.0f}, {2.0f, 0.0f, 0.0f}), Rgb(1.0f, 2.0f, 3.0f));
    scene.add_sphere({Vec3d(0.0, 5.0, 0.0), 1.0, false}, Rgb());
    scene.add_sphere({Vec3d(3.0, 0.0, 0.0), 0.5, false}, Rgb(4.0f));
    scene.add_mesh(make_triangle({0.0f, -3.0f, 0.0f}, {2.0f, -3.0f, 0.0f}, {0.0f, -3.0f, 1.0f}), Rgb(0.5f, 0.0f, 0.0f),
                   true);
    return scene;
}

TEST(LightSet, EveryEmittingShapeIsALight) {
    LightTestScene scene = three_lights();
    LightSet lights = scene.light_set();
    EXPECT_FALSE(lights.empty());
    EXPECT_EQ(lights.size(), 3u);
}

TEST(LightSet, ReadsTheChoiceNumberOnlyWithSeveralLights) {
    // One light: uc picks nothing, and any uc gives the same sample (so the integrators skip it).
    LightTestScene one;
    one.add_mesh(make_quad({-1.0f, -1.0f, 2.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}), Rgb(1.0f));
    LightSet lights = one.light_set();
    EXPECT_FALSE(lights.uses_choice());
    std::optional<LightSample> a = lights.sample(kOrigin, 0.1f, {0.3f, 0.6f});
    std::optional<LightSample> b = lights.sample(kOrigin, 0.9f, {0.3f, 0.6f});
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->p, b->p);
    EXPECT_TRUE(three_lights().light_set().uses_choice());
    EXPECT_FALSE(LightTestScene().light_set().uses_choice());  // no light at all
}

TEST(LightSet, PowerSelectionIsProportionalToPower) {
    LightTestScene scene = three_lights();
    LightSet lights = scene.light_set(LightSelection::kPower);
    // pi * area * luminance * sides.
    double quad = kPiD * 1.0 * static_cast<double>(Rgb(1.0f, 2.0f, 3.0f).luminance());
    double sphere = kPiD * (4.0 * kPiD * 0.25) * 4.0;
    double triangle = kPiD * 1.0 * static_cast<double>(Rgb(0.5f, 0.0f, 0.0f).luminance()) * 2.0;
    double total = quad + sphere + triangle;
    // Powers are summed in float: a few roundings each.
    auto expect_relative = [](float actual, double expected) {
        EXPECT_NEAR(static_cast<double>(actual) / expected, 1.0, 1e-6);
    };
    expect_relative(lights.selection_probability(0), quad / total);
    EXPECT_EQ(lights.selection_probability(1), 0.0f);
    expect_relative(lights.selection_probability(2), sphere / total);
    expect_relative(lights.selection_probability(3), triangle / total);
    // pdf() includes the selection: the sphere's cone density times its probability.
    double one_minus_cos = 1.0 - std::sqrt(1.0 - 0.25 / 9.0);
    expect_relative(lights.pdf(kOrigin, 2, {2.5f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}),
                    sphere / total / (2.0 * kPiD * one_minus_cos));
}

TEST(LightSet, UniformSelectionIsOneOverTheLightCount) {
    LightTestScene scene = three_lights();
    LightSet lights = scene.light_set(LightSelection::kUniform);
    EXPECT_FLOAT_EQ(lights.selection_probability(0), 1.0f / 3.0f);
    EXPECT_EQ(lights.selection_probability(1), 0.0f);
    EXPECT_FLOAT_EQ(lights.selection_probability(2), 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(lights.selection_probability(3), 1.0f / 3.0f);
}

TEST(LightSet, PdfIsZeroForShapesThatAreNotLights) {
    LightTestScene scene = three_lights();
    LightSet lights = scene.light_set();
    EXPECT_EQ(lights.pdf(kOrigin, 1, {0.0f, 4.0f, 0.0f}, {0.0f, -1.0f, 0.0f}), 0.0f);
    EXPECT_EQ(lights.pdf(kOrigin, 99, {0.0f, 4.0f, 0.0f}, {0.0f, -1.0f, 0.0f}), 0.0f);  // no such shape
    EXPECT_TRUE(lights.emitted(1, {0.0f, -1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}).is_black());
    EXPECT_TRUE(lights.emitted(99, {0.0f, -1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}).is_black());
}

TEST(LightSet, NoEmittersMeansNothingToSample) {
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.0, 0.0, 3.0), 1.0, false}, Rgb());
    LightSet lights = scene.light_set();
    EXPECT_TRUE(lights.empty());
    EXPECT_EQ(lights.size(), 0u);
    EXPECT_FALSE(lights.sample(kOrigin, 0.5f, {0.5f, 0.5f}));
    EXPECT_FALSE(LightSet().sample(kOrigin, 0.5f, {0.5f, 0.5f}));
    EXPECT_EQ(LightSet().pdf(kOrigin, 0, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}), 0.0f);
}

TEST(LightSet, EmittingMeshOfZeroAreaIsNotALight) {
    LightTestScene scene;
    scene.add_mesh(make_triangle({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {2.0f, 0.0f, 1.0f}), Rgb(1.0f));
    scene.add_mesh(TriangleMesh{}, Rgb(1.0f));
    uint32_t quad = scene.add_mesh(make_quad({0.0f, 0.0f, 2.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}), Rgb(1.0f));
    LightSet lights = scene.light_set();
    EXPECT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights.selection_probability(0), 0.0f);
    EXPECT_EQ(lights.selection_probability(quad), 1.0f);
}

TEST(LightSet, OneSidedLightIsBlackFromBehindTwoSidedIsNot) {
    LightTestScene scene = three_lights();
    LightSet lights = scene.light_set();
    const Vec3f n_quad(0.0f, 0.0f, -1.0f);
    EXPECT_EQ(lights.emitted(0, n_quad, {0.0f, 0.6f, -0.8f}), Color(1.0f, 2.0f, 3.0f));
    EXPECT_TRUE(lights.emitted(0, n_quad, {0.0f, 0.6f, 0.8f}).is_black());
    const Vec3f n_tri(0.0f, -1.0f, 0.0f);  // cross((2,0,0), (0,0,1))
    EXPECT_EQ(lights.emitted(3, n_tri, {0.0f, -1.0f, 0.0f}), Color(0.5f, 0.0f, 0.0f));
    EXPECT_EQ(lights.emitted(3, n_tri, {0.0f, 1.0f, 0.0f}), Color(0.5f, 0.0f, 0.0f));

    // Samples of the quad alone: radiance in front, black (with the true density) behind.
    LightTestScene quad_only;
    quad_only.add_mesh(make_quad({-1.0f, -0.25f, 2.0f}, {0.0f, 0.5f, 0.0f}, {2.0f, 0.0f, 0.0f}), Rgb(1.0f, 2.0f, 3.0f));
    LightSet quad = quad_only.light_set();
    std::optional<LightSample> front = quad.sample(kOrigin, 0.3f, {0.4f, 0.6f});
    ASSERT_TRUE(front);
    EXPECT_EQ(front->Le, Color(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(front->n, n_quad);
    std::optional<LightSample> back = quad.sample({0.0f, 0.0f, 4.0f}, 0.3f, {0.4f, 0.6f});
    ASSERT_TRUE(back);
    EXPECT_TRUE(back->Le.is_black());
    EXPECT_GT(back->pdf, 0.0f);
}

TEST(LightSet, ReversedSphereEmitsInwardOnly) {
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.0, 0.0, 0.0), 2.0, true}, Rgb(1.5f));
    LightSet lights = scene.light_set();
    std::optional<LightSample> inside = lights.sample({0.5f, 0.0f, 0.0f}, 0.5f, {0.2f, 0.9f});
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->Le, Color(1.5f));
    EXPECT_LT(dot(inside->n, inside->p), 0.0f);  // the front normal points to the centre
    std::optional<LightSample> outside = lights.sample({0.0f, 0.0f, 5.0f}, 0.5f, {0.2f, 0.9f});
    ASSERT_TRUE(outside);
    EXPECT_TRUE(outside->Le.is_black());
}

TEST(LightSet, PointsOnAnInwardEmittingSphereSeeItsWholeRadiance) {
    // A path vertex on the inside of a furnace sphere, rounded to float on either side of the
    // surface. Area sampling from a point on a sphere has cos_ref = cos_light = d / 2r, so every
    // sample estimates the irradiance L cos_ref / pdf = pi L exactly (no variance): a sample that
    // takes the cone from outside (black radiance) or a wrong density shows at once.
    const Sphere spheres[] = {{Vec3d(0.0, 0.0, 0.0), 1.0, true},
                              {Vec3d(50.0, 681.33, 81.6), 600.0, true},
                              {Vec3d(1000.0, -20.0, 3.0), 1.0, true}};
    for (const Sphere& sphere : spheres) {
        LightTestScene scene;
        scene.add_sphere(sphere, Rgb(2.0f));
        LightSet lights = scene.light_set();
        Rng rng(21, 3);
        for (int i = 0; i < 1000; ++i) {
            Vec3d on = project_to_sphere(sphere, sphere.center + Vec3d(sample_uniform_sphere(rng.next_vec2f())));
            Vec3f ref(on);
            Vec3f n_in = normalize(Vec3f(sphere.center - on));
            float uc = rng.next_float();
            Vec2f u = rng.next_vec2f();
            std::optional<LightSample> s = lights.sample(ref, uc, u);
            ASSERT_TRUE(s) << "radius " << sphere.radius << ", sample " << i;
            ASSERT_EQ(s->Le, Color(2.0f)) << "radius " << sphere.radius << ", sample " << i;
            double d = length(Vec3d(s->p) - Vec3d(ref));
            if (d < 1e-3 * sphere.radius) continue;  // the rounding of ref dominates cos there
            double cos_ref = static_cast<double>(dot(n_in, s->p - ref)) / d;
            EXPECT_NEAR(2.0 * cos_ref / static_cast<double>(s->pdf) / (2.0 * kPiD), 1.0, 1e-3)
                << "radius " << sphere.radius << ", sample " << i;
        }
    }
}

TEST(LightSet, MeshSamplesLieInTheirTriangles) {
    TriangleMesh m;
    m.positions = {{0.0f, 0.0f, 1.0f}, {2.0f, 0.0f, 1.5f}, {0.0f, 1.0f, 1.2f},
                   {-1.0f, 0.0f, 3.0f}, {-1.0f, 0.3f, 3.0f}, {-1.3f, 0.0f, 2.7f},
                   {3.0f, 3.0f, 0.5f}, {4.0f, 3.0f, 0.5f}, {3.0f, 5.0f, 2.0f}};
    m.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    LightTestScene scene;
    scene.add_mesh(m, Rgb(1.0f));
    LightSet lights = scene.light_set();
    Rng rng(11, 2);
    int per_triangle[3] = {0, 0, 0};
    for (int i = 0; i < 3000; ++i) {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        std::optional<LightSample> s = lights.sample({0.5f, 0.5f, -1.0f}, uc, u);
        ASSERT_TRUE(s);
        int found = -1;
        for (int t = 0; t < 3; ++t) {
            Vec3d p0(m.positions[3 * t]), p1(m.positions[3 * t + 1]), p2(m.positions[3 * t + 2]);
            Vec3d ng = cross(p1 - p0, p2 - p0);
            double area2 = length(ng);
            Vec3d p(s->p);
            // Signed sub-areas over the total: barycentrics, all in [0, 1] inside.
            double b0 = dot(cross(p1 - p, p2 - p), ng) / (area2 * area2);
            double b1 = dot(cross(p2 - p, p0 - p), ng) / (area2 * area2);
            double b2 = dot(cross(p0 - p, p1 - p), ng) / (area2 * area2);
            double plane_distance = std::abs(dot(p - p0, ng)) / area2;
            if (b0 >= -1e-6 && b1 >= -1e-6 && b2 >= -1e-6 && plane_distance < 1e-5) {
                found = t;
                EXPECT_GT(dot(Vec3d(s->n), ng / area2), 1.0 - 1e-6);
            }
        }
        ASSERT_GE(found, 0) << "sample " << i << " at " << s->p.x << ", " << s->p.y << ", " << s->p.z;
        ++per_triangle[found];
    }
    for (int count : per_triangle) EXPECT_GT(count, 0);
}

// Quads are sampled as parallelograms (a + u.x e1 + u.y e2); other meshes triangle by triangle.
TEST(MeshEmitter, QuadsAndOnlyQuadsUseTheParallelogramForm) {
    EXPECT_TRUE(MeshEmitter(make_quad({-1.0f, 3.0f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f})).is_parallelogram());
    // Far from the origin and rotated, with every corner rounded on its own (as a transform does).
    TriangleMesh turned = make_quad({343.0f, 548.7f, 227.0f}, {0.0f, 0.0f, 105.0f}, {-130.0f, 0.0f, 0.0f});
    const float c = std::cos(0.7f), s = std::sin(0.7f);
    for (Vec3f& p : turned.positions) p = Vec3f(c * p.x - s * p.y, s * p.x + c * p.y, p.z + 1000.0f);
    EXPECT_TRUE(MeshEmitter(turned).is_parallelogram());
    // A kite: two triangles sharing a diagonal, but not a parallelogram.
    TriangleMesh kite = make_quad({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    kite.positions[2] = Vec3f(1.5f, 1.5f, 1.0f);
    EXPECT_FALSE(MeshEmitter(kite).is_parallelogram());
    // Vertex normals decide the front per point: the triangle route handles them.
    TriangleMesh smooth = make_quad({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    smooth.normals.assign(4, Vec3f(0.0f, 0.0f, 1.0f));
    EXPECT_FALSE(MeshEmitter(smooth).is_parallelogram());
    // Two separate triangles that happen to share no diagonal.
    TriangleMesh apart = make_quad({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    apart.indices = {0, 1, 2, 2, 3, 1};
    EXPECT_FALSE(MeshEmitter(apart).is_parallelogram());
}

TEST(MeshEmitter, ParallelogramSamplesKeepTheirStratumAndTheHitNormal) {
    const Vec3f a(-1.0f, -0.5f, 2.0f), e1(2.0f, 0.0f, 0.4f), e2(0.3f, 1.0f, 0.0f);
    TriangleMesh quad = make_quad(a, e1, e2);
    MeshEmitter emitter(quad);
    ASSERT_TRUE(emitter.is_parallelogram());
    // The point is a + u.x e1 + u.y e2: every stratum of u lands in the matching part of the quad.
    Rng rng(3, 7);
    for (int i = 0; i < 1000; ++i) {
        Vec2f u = rng.next_vec2f();
        std::optional<EmitterSample> s = emitter.sample(kOrigin, u);
        ASSERT_TRUE(s);
        Vec3f expected = a + e1 * u.x + e2 * u.y;
        EXPECT_LT(length(s->p - expected), 1e-6f) << "u = " << u.x << ", " << u.y;
        // The normal of the triangle the point lies in: (a, b, c) below the diagonal, (a, c, d) above.
        const uint32_t* v = &quad.indices[u.y > u.x ? 3 : 0];
        EXPECT_EQ(s->n, winding_normal(quad.positions[v[0]], quad.positions[v[1]], quad.positions[v[2]]));
        EXPECT_EQ(emitter.pdf(kOrigin, s->p, s->n), s->pdf);
    }
}

TEST(LightSet, PdfOfSmallFarQuadIsDistanceSquaredOverProjectedArea) {
    // A 0.01 x 0.01 quad 10 away, tilted 60 degrees: pdf = d^2 / (A cos theta) to O(size / d).
    const float c = 0.5f, s = std::sqrt(3.0f) / 2.0f;
    const Vec3f centre(0.0f, 0.0f, 10.0f);
    const Vec3f e1(0.01f, 0.0f, 0.0f), e2(0.0f, 0.01f * c, -0.01f * s);
    LightTestScene scene;
    // Normal cross(e2, e1) = (0, -s, -c): towards the origin, 60 degrees off the line of sight.
    scene.add_mesh(make_quad(centre - e1 * 0.5f - e2 * 0.5f, e2, e1), Rgb(1.0f));
    LightSet lights = scene.light_set();
    const double expected = 100.0 / (1e-4 * 0.5);
    Rng rng(5, 5);
    for (int i = 0; i < 100; ++i) {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        std::optional<LightSample> ls = lights.sample(kOrigin, uc, u);
        ASSERT_TRUE(ls);
        EXPECT_EQ(ls->Le, Color(1.0f));
        EXPECT_NEAR(static_cast<double>(ls->pdf) / expected, 1.0, 3e-3);
    }
    // At the centre, exact but for the area of the quad's float vertices (0.01 edges at z = 10:
    // rounding of 5e-7 moves the area by up to 1e-4 relative).
    EXPECT_NEAR(static_cast<double>(lights.pdf(kOrigin, 0, centre, {0.0f, -s, -c})) / expected, 1.0, 1e-4);
}

TEST(LightSet, PdfEqualsTheSampledPdfExactly) {
    // One light per set, so each sample's shape is known; references inside and outside spheres.
    std::vector<LightTestScene> scenes(5);
    scenes[0].add_mesh(make_quad({-1.0f, -1.0f, 2.0f}, {2.0f, 0.0f, 0.3f}, {0.0f, 2.0f, 0.0f}), Rgb(1.0f));
    scenes[1].add_mesh(make_triangle({-1.0f, 0.0f, 1.0f}, {1.0f, 0.2f, 1.0f}, {0.0f, 2.0f, 3.0f}), Rgb(1.0f), true);
    scenes[2].add_sphere({Vec3d(0.0, 0.5, 2.5), 1.0, false}, Rgb(1.0f));
    scenes[3].add_sphere({Vec3d(0.1, 0.0, 0.2), 3.0, true}, Rgb(1.0f));
    scenes[4].add_sphere({Vec3d(1e5 + 1.0, 40.8, 81.6), 1e5, false}, Rgb(1.0f));
    Rng rng(9, 9);
    for (size_t k = 0; k < scenes.size(); ++k) {
        LightSet lights = scenes[k].light_set();
        for (int i = 0; i < 500; ++i) {
            // In the unit cube around the origin; for the wall, in smallpt's box.
            Vec3f ref;
            for (int axis = 0; axis < 3; ++axis) ref[axis] = rng.next_float() - 0.5f;
            if (k == 4) ref = Vec3f(50.0f, 40.0f, 80.0f) + ref * 80.0f;
            float uc = rng.next_float();
            Vec2f u = rng.next_vec2f();
            std::optional<LightSample> s = lights.sample(ref, uc, u);
            if (!s) continue;
            EXPECT_EQ(lights.pdf(ref, 0, s->p, s->n), s->pdf) << "scene " << k << ", sample " << i;
            EXPECT_TRUE(std::isfinite(s->pdf));
            // The direction comes from the same difference as the pdf.
            Vec3d to_p = Vec3d(s->p) - Vec3d(ref);
            EXPECT_NEAR(dot(Vec3d(s->wi), to_p / length(to_p)), 1.0, 1e-6) << "scene " << k << ", sample " << i;
        }
    }
}

TEST(LightSet, SampledNormalsAndRadianceAgreeWithHits) {
    // What next-event estimation sees must be what a ray hitting the light sees: the same front
    // normal (also where vertex normals overrule the winding) and so the same radiance.
    TriangleMesh flipped = make_triangle({-1.0f, -1.0f, 2.0f}, {1.0f, -1.0f, 2.0f}, {0.0f, 1.0f, 2.0f});
    flipped.normals = {{0.0f, 0.0f, -1.0f}, {0.1f, 0.0f, -0.99f}, {0.0f, 0.1f, -0.99f}};  // against the winding
    LightTestScene scene;
    scene.add_mesh(flipped, Rgb(1.0f));
    scene.add_mesh(make_quad({-1.0f, 3.0f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 2.0f}), Rgb(2.0f));
    scene.add_sphere({Vec3d(-3.0, 0.0, 0.0), 1.0, false}, Rgb(3.0f));
    scene.add_sphere({Vec3d(0.0, 0.0, 0.0), 10.0, true}, Rgb(4.0f));
    LightSet lights = scene.light_set(LightSelection::kUniform);  // by power, the big sphere would take all
    Accelerator accel(scene.meshes, scene.spheres, scene.shapes);
    Rng rng(1, 1);
    int agreed[4] = {0, 0, 0, 0};
    for (int i = 0; i < 2000; ++i) {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        std::optional<LightSample> s = lights.sample(kOrigin, uc, u);
        ASSERT_TRUE(s);
        std::optional<SurfaceHit> hit = accel.intersect(Ray{kOrigin, normalize(s->p - kOrigin), 0.0f, kInfinity});
        ASSERT_TRUE(hit);
        if (length(hit->p - s->p) > 1e-4f * std::max(1.0f, length(s->p))) continue;  // hidden
        ++agreed[hit->shape_id];
        EXPECT_GT(dot(hit->ng, s->n), 0.9999f) << "shape " << hit->shape_id;
        EXPECT_EQ(lights.emitted(hit->shape_id, hit->ng, -normalize(s->p)), s->Le) << "shape " << hit->shape_id;
        // The hit point is the sampled one up to rounding: the densities agree to that precision.
        EXPECT_NEAR(lights.pdf(kOrigin, hit->shape_id, hit->p, hit->ng) / s->pdf, 1.0f, 1e-4f)
            << "shape " << hit->shape_id;
    }
    for (int count : agreed) EXPECT_GT(count, 200);
}

}  // namespace
}  // namespace candela::test
