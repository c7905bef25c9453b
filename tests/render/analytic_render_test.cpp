// Direct light against a closed form (DESIGN.md, "Correctness"): the irradiance a uniform polygonal
// light puts on a plane, by Lambert's formula for polygons (Arvo 1995, "Applications of Irradiance
// Tensors to the Simulation of Non-Lambertian Phenomena", section 3; the classic differential
// area to polygon form factor): E(p) = (L / 2) sum_i theta_i (n . gamma_i), theta_i the angle the polygon's
// edge i subtends at p and gamma_i the unit normal of the plane through p and that edge. A diffuse
// plane of albedo rho then leaves radiance rho E / pi. With max_depth = 1 (direct light only) every
// estimator renders exactly that, so each pixel's expectation is the closed form averaged over the
// pixel's footprint on the plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "support/plane_irradiance.h"
#include "support/polygon_irradiance.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::Polygon;
using test::polygon_irradiance;

TEST(PolygonIrradiance, MatchesRectangleCornerFormFactor) {
    // The point under one corner of an a x b rectangle parallel to it at height c: the form factor
    // F = (1/2pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))],
    // A = a/c, B = b/c (Howell's catalogue of configuration factors: a differential element to a
    // parallel rectangle, its normal through a corner), and E = pi L F.
    const double a = 0.7, b = 1.9, c = 0.6, L = 3.0;
    const double A = a / c, B = b / c;
    const double F = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                      B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
                     (2.0 * kPiD);
    Polygon rect = {{0, c, 0}, {a, c, 0}, {a, c, b}, {0, c, b}};
    EXPECT_NEAR(polygon_irradiance({0, 0, 0}, {0, 1, 0}, rect, L), kPiD * L * F, 1e-12);
    // A huge square over the point fills the hemisphere: E -> pi L.
    Polygon huge = {{-1e6, 1, -1e6}, {1e6, 1, -1e6}, {1e6, 1, 1e6}, {-1e6, 1, 1e6}};
    EXPECT_NEAR(polygon_irradiance({0, 0, 0}, {0, 1, 0}, huge, L), kPiD * L, 1e-5);
}

constexpr int kSize = 32;
constexpr int kBlock = 4;
constexpr float kRadiance = 4.0f;
constexpr double kMaxDistance = 1.5;  // from the light's axis, of the plane points tested
const Rgb kAlbedo(0.8f, 0.6f, 0.4f);

// A unit square light at height light_y facing down (-y), centred on the y axis, lighting a large
// diffuse receiver plane y = receiver_y facing normal_y (+1 up, -1 down), seen from `eye`.
struct LitPlane {
    float receiver_y;
    float normal_y;
    float light_y;
    bool two_sided;
    Vec3f eye;
    Vec3f target;

    Polygon light() const {
        const double y = double(light_y);
        return {{-0.5, y, -0.5}, {0.5, y, -0.5}, {0.5, y, 0.5}, {-0.5, y, 0.5}};
    }
};

// The scene of `setup`; the light's material is black, so it reflects nothing.
Scene light_over_plane(const LitPlane& setup) {
    Scene s;
    s.materials = {make_diffuse(kAlbedo), make_diffuse(Rgb(0.0f))};
    s.material_names = {"receiver", "black"};
    const float y = setup.receiver_y;
    if (setup.normal_y > 0)
        test::add_quad(s, {-50, y, -50}, {0, 0, 100}, {100, 0, 0}, 0);
    else
        test::add_quad(s, {-50, y, -50}, {100, 0, 0}, {0, 0, 100}, 0);
    uint32_t light = test::add_quad(s, {-0.5f, setup.light_y, -0.5f}, {1, 0, 0}, {0, 0, 1}, 1);  // faces -y
    test::set_emission(s, light, Rgb(kRadiance), setup.two_sided);
    test::set_camera(s, setup.eye, setup.target, 60, kSize, kSize);
    s.sampler.seed = 5;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.integrator.max_depth = 1;
    return s;
}

// The expected image of the receiver within kMaxDistance of the light's axis (there every
// estimator finds the light often enough for its sample variance to be a fair estimate).
test::ExpectedImage expected_image(const Scene& scene, const LitPlane& setup) {
    const Vec3d n(0, double(setup.normal_y), 0);
    const Polygon light = setup.light();
    return test::expected_plane_image(scene, {setup.receiver_y, setup.normal_y, 0.0, 0.0, kMaxDistance},
                                      [&](const Vec3d& p) { return polygon_irradiance(p, n, light, double(kRadiance)); });
}

// z-tests of every block of valid pixels against `scale` times the closed form.
test::ZTestFamily test_against(const test::RenderMoments& m, const test::ExpectedImage& e, double scale) {
    return test::test_plane_image(m, e, kAlbedo, scale, kBlock);
}

struct EstimatorCase {
    std::string name;
    IntegratorType type;
    bool mis;
    int spp;  // BSDF sampling, the noisiest here, gets more
};

class QuadLightIrradiance : public ::testing::TestWithParam<EstimatorCase> {
  protected:
    Scene scene_for(const LitPlane& setup) const {
        Scene scene = light_over_plane(setup);
        scene.integrator.type = GetParam().type;
        scene.integrator.mis = GetParam().mis;
        scene.sampler.spp = GetParam().spp;
        return scene;
    }

    void check(const LitPlane& setup, const std::string& name) const {
        Scene scene = scene_for(setup);
        test::RenderMoments m = test::render_moments(scene);
        EXPECT_EQ(m.dropped, 0u);
        test::ExpectedImage e = expected_image(scene, setup);
        ASSERT_GT(std::count(e.valid.begin(), e.valid.end(), true), kSize * kSize / 4);
        test::ZTestFamily family = test_against(m, e, 1.0);
        EXPECT_TRUE(family.passed()) << family.summary();
        // Power: the same test rejects an answer 5% too bright, in at least a quarter of the blocks.
        test::ZTestFamily wrong = test_against(m, e, 1.05);
        EXPECT_GE(wrong.rejected(), wrong.tests() / 4) << wrong.summary();
        if (!family.passed()) test::write_diagnostic(m, "analytic_" + name + "_" + GetParam().name);
    }
};

// A floor under the light, seen obliquely from below the light's height.
TEST_P(QuadLightIrradiance, FloorUnderOneSidedLightMatchesClosedForm) {
    check({-0.5f, 1.0f, 0.5f, false, {0, 0.3f, -1.4f}, {0, -0.5f, 0}}, "floor");
}

// The same on the plane y = 0: points there have exact zero coordinates, the case where spawned
// rays must still leave the surface (ray_offset.h) with denormals flushed to zero, as the renderer
// runs.
TEST_P(QuadLightIrradiance, FloorThroughOriginUnderOneSidedLightMatchesClosedForm) {
    check({0.0f, 1.0f, 1.0f, false, {0, 0.8f, -1.4f}, {0, 0, 0}}, "origin_floor");
}

// A two-sided light lights both sides by the same formula: the floor below it, and the ceiling
// above it facing down.
TEST_P(QuadLightIrradiance, FloorUnderTwoSidedLightMatchesClosedForm) {
    check({-0.5f, 1.0f, 0.5f, true, {0, 0.3f, -1.4f}, {0, -0.5f, 0}}, "two_sided_floor");
}

TEST_P(QuadLightIrradiance, CeilingOverTwoSidedLightMatchesClosedForm) {
    check({2.0f, -1.0f, 1.0f, true, {0, 1.2f, -1.4f}, {0, 2, 0}}, "ceiling");
}

// A one-sided light sends nothing backwards: the ceiling over it and the light's own back, seen
// from between them, are exactly black, at any path depth.
TEST_P(QuadLightIrradiance, OneSidedLightIsBlackFromBehind) {
    Scene scene = scene_for({2.0f, -1.0f, 1.0f, false, {0, 1.5f, -1.2f}, {0, 1.4f, 0.5f}});
    scene.integrator.max_depth = 64;
    scene.sampler.spp = 16;
    test::RenderMoments m = test::render_moments(scene);
    EXPECT_EQ(m.dropped, 0u);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) ASSERT_EQ(m.mean(x, y, c), 0.0) << "pixel " << x << ", " << y;
    // The view does show the light's back and the ceiling, not only the void.
    PerspectiveCamera camera(scene.camera);
    int light_pixels = 0, ceiling_pixels = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            Ray r = camera.generate_ray({float(x) + 0.5f, float(y) + 0.5f});
            Vec3f on_light = r.o + r.d * ((1.0f - r.o.y) / r.d.y);
            light_pixels += r.d.y < 0.0f && std::abs(on_light.x) < 0.5f && std::abs(on_light.z) < 0.5f;
            ceiling_pixels += r.d.y > 0.0f;
        }
    }
    EXPECT_GT(light_pixels, kSize * kSize / 20);
    EXPECT_GT(ceiling_pixels, kSize * kSize / 4);
}

void PrintTo(const EstimatorCase& c, std::ostream* os) { *os << c.name; }

INSTANTIATE_TEST_SUITE_P(AllEstimators, QuadLightIrradiance,
                         ::testing::Values(EstimatorCase{"path", IntegratorType::kPath, true, 1024},
                                           EstimatorCase{"nee", IntegratorType::kPath, false, 1024},
                                           EstimatorCase{"bsdf", IntegratorType::kBsdf, true, 4096},
                                           EstimatorCase{"whitted", IntegratorType::kWhitted, true, 1024}),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace candela
