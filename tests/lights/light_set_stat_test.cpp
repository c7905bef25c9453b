// Chi-square goodness of fit, in solid angle at a reference point, of LightSet::sample against
// LightSet::pdf (tests/support/chi2.h): the directions normalize(p - ref) of the sampled points
// are histogrammed over (phi, cos theta) and compared with the density LightTestScene::
// direction_pdf computes by tracing each direction through the lights. The pdf must integrate to 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "lights/light_test_scene.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 14;  // in this file, for the Sidak correction
const Rgb kWhite{1.0f};

// The harness integrates each cell's pdf from a grid of nodes 1/16 of a cell apart, so the corner
// of a triangle that pokes into a cell by less than that may integrate to 0, and a sample there
// fails the test. This checks that every triangle corner's direction keeps `margin` cells from
// the cell edges (polygon edges are found: they cross the nodes on the cell edges).
void expect_corners_clear_of_cell_edges(const LightTestScene& scene, const Vec3f& ref, const SphericalDomain& domain,
                                        const Chi2Options& opt, double margin = 0.2) {
    Vec2d lo = domain.param_min(), hi = domain.param_max();
    for (const TriangleMesh& m : scene.meshes) {
        for (size_t t = 0; t < m.triangle_count(); ++t) {
            const Vec3f* p[3] = {&m.positions[m.indices[3 * t]], &m.positions[m.indices[3 * t + 1]],
                                 &m.positions[m.indices[3 * t + 2]]};
            if (length(cross(*p[1] - *p[0], *p[2] - *p[0])) == 0.0f) continue;  // never sampled
            for (const Vec3f* v : p) {
                Vec2d q = domain.to_param(normalize(*v - ref));
                double fx = (q.x - lo.x) / (hi.x - lo.x) * opt.res_x;
                double fy = (q.y - lo.y) / (hi.y - lo.y) * opt.res_y;
                double to_edge = std::min(std::min(fx - std::floor(fx), std::ceil(fx) - fx),
                                          std::min(fy - std::floor(fy), std::ceil(fy) - fy));
                EXPECT_GE(to_edge, margin) << "move the test's vertex " << v->x << ", " << v->y << ", " << v->z;
            }
        }
    }
}

// `expected_integral`: the probability that sample() picks a light with a density over
// directions (not a delta light, whose samples the sampler below counts as failures).
void expect_fits(const LightTestScene& scene, LightSelection selection, const Vec3f& ref,
                 SphericalDomain domain = {}, double expected_integral = 1.0) {
    LightSet lights = scene.light_set(selection);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.expected_integral = expected_integral;
    expect_corners_clear_of_cell_edges(scene, ref, domain, opt);
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        std::optional<LightSample> s = lights.sample(ref, uc, u);
        if (!s || s->is_delta) return std::nullopt;
        return normalize(s->p - ref);
    };
    auto pdf = [&](Vec3f w) { return scene.direction_pdf(lights, ref, w); };
    Chi2Result r = chi2_test(domain, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(LightSetChi2, OneTriangle) {
    LightTestScene scene;
    scene.add_mesh(make_triangle({-1.0f, -0.5f, 1.0f}, {1.2f, -0.8f, 1.54f}, {0.1f, 1.0f, 0.7f}), kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, QuadAtAnAngle) {
    LightTestScene scene;
    scene.add_mesh(make_quad({-0.8f, -0.6f, 1.2f}, {1.48f, 0.0f, 0.6f}, {0.3f, 1.34f, -0.4f}), kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, MeshOfUnequalTriangles) {
    // Areas from 0.02 to 1.5, one degenerate triangle (never sampled), and one triangle partly
    // behind another, where the density of a direction is the sum over both points.
    TriangleMesh m;
    m.positions = {{-1.0f, -1.0f, 1.0f},   {0.5f, -1.2f, 1.12f}, {-0.6f, 0.4f, 0.9f},    // large
                   {0.6f, 0.22f, 0.8f},    {0.8f, 0.22f, 0.8f},  {0.7f, 0.35f, 0.88f},   // small
                   {0.0f, 0.0f, -1.0f},    {1.0f, 0.0f, -1.0f},  {2.0f, 0.0f, -1.0f},    // degenerate
                   {-1.2f, -0.2f, -0.58f}, {-0.3f, 1.0f, -1.5f}, {-1.4f, 0.92f, 0.22f},  // behind ref
                   {-1.5f, -1.64f, 2.0f},  {0.3f, -1.8f, 2.2f},  {-1.1f, -0.5f, 1.94f}}; // behind the large one
    m.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
    LightTestScene scene;
    scene.add_mesh(std::move(m), kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, SphereFromOutsideNearlyHemispherical) {
    // sin theta_max = 1 / 1.02: the cone's half-angle is 78.6 degrees.
    LightTestScene scene;
    scene.add_sphere({Vec3d(normalize(Vec3f(0.3f, 0.2f, 1.0f))) * 1.02, 1.0, false}, kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, SphereFromOutsideOffAxis) {
    LightTestScene scene;
    scene.add_sphere({Vec3d(normalize(Vec3f(-0.5f, 0.4f, 1.0f))) * 3.0, 1.0, false}, kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, SphereFromOutsideNarrowCone) {
    // 1 - cos theta_max = 5.6e-4: the cap covers 28 of the 50 rows of cos theta in [0.999, 1].
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.0, 0.0, 30.0), 1.0, false}, kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f}, SphericalDomain{0.999, 1.0});
}

TEST(LightSetChi2, SmallptLightFromInsideTheBox) {
    // smallpt's light, a sphere of radius 600 poking through the ceiling, from the box's floor.
    LightTestScene scene;
    scene.add_sphere({Vec3d(50.0, 681.6 - 0.27, 81.6), 600.0, false}, Rgb(12.0f));
    expect_fits(scene, LightSelection::kPower, {50.0f, 40.0f, 81.6f});
}

TEST(LightSetChi2, SphereFromInsideReverseOrientation) {
    LightTestScene scene;
    scene.add_sphere({Vec3d(0.3, -0.2, 0.5), 2.0, true}, kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

// A quad, a non-emitting sphere (so light and shape indices differ) and an emitting sphere.
LightTestScene two_lights() {
    LightTestScene scene;
    scene.add_mesh(make_quad({-1.5f, -1.0f, 1.05f}, {1.0f, 0.0f, 0.3f}, {0.0f, 1.15f, 0.0f}), Rgb(1.0f, 1.0f, 1.0f));
    scene.add_sphere({Vec3d(0.0, 0.0, -5.0), 1.0, false}, Rgb(0.0f));
    scene.add_sphere({Vec3d(1.5, 0.5, -0.5), 0.6, false}, Rgb(4.0f, 2.0f, 1.0f));
    return scene;
}

TEST(LightSetChi2, TwoLightsSelectedByPower) {
    expect_fits(two_lights(), LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, TwoLightsSelectedUniformly) {
    expect_fits(two_lights(), LightSelection::kUniform, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, TwoSidedQuadSeenFromBehindAndASphere) {
    LightTestScene scene;
    // The quad's front faces +z, away from ref: its samples carry radiance only because it is
    // two-sided, and the density is the same either way.
    scene.add_mesh(make_quad({-0.5f, 0.5f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.96f, 0.0f}), Rgb(0.5f), true);
    scene.add_sphere({Vec3d(0.0, -2.0, 0.5), 0.8, false}, Rgb(3.0f));
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, DiskFacingThePoint) {
    LightTestScene scene;
    scene.add_disk(make_round_disk({0.2, -0.1, 1.5}, {-0.1, 0.2, -1.0}, 0.8), kWhite);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, TiltedEllipseSeenObliquely) {
    // Scaled unevenly, rotated and seen from the side: area sampling stays uniform on the
    // ellipse (the concentric map carried by an affine map), and the solid-angle density varies
    // strongly over it.
    LightTestScene scene;
    scene.add_disk(transform_disk(make_round_disk({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0),
                                  Transform::translate({1.0, 0.3, 1.2}) * Transform::rotate({0.0, 1.0, 0.0}, 1.1) *
                                      Transform::scale({1.3, 0.4, 1.0}),
                                  false),
                   kWhite, true);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f});
}

TEST(LightSetChi2, DiskAndSphereBesideDeltaLights) {
    // Point and directional lights take their share of the selection: the area lights' samples
    // keep their densities, scaled by their own (smaller) selection probabilities.
    LightTestScene scene;
    scene.add_disk(make_round_disk({-1.0, 0.5, 1.0}, {1.0, -0.5, -1.0}, 0.6), Rgb(2.0f));
    scene.add_sphere({Vec3d(1.2, -0.4, 0.8), 0.5, false}, Rgb(1.0f));
    scene.add_delta_light(PointLight{{0.0f, 2.0f, 0.0f}, Color(0.3f)});
    scene.add_delta_light(DirectionalLight{{0.0f, -1.0f, 0.0f}, Color(0.1f)});
    LightSet lights = scene.light_set();
    double area_lights = static_cast<double>(lights.selection_probability(0)) +
                         static_cast<double>(lights.selection_probability(1));
    ASSERT_LT(area_lights, 0.9);
    expect_fits(scene, LightSelection::kPower, {0.0f, 0.0f, 0.0f}, {}, area_lights);
}

}  // namespace
}  // namespace candela::test
