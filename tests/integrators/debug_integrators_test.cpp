// The debug integrators against values known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/geometry/accelerator.h"
#include "candela/integrators/debug_integrators.h"
#include "candela/render/renderer.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A camera ray straight down onto a floor at y = 0.
Ray down_ray() { return Ray{{0, 1, 0}, {0, -1, 0}}; }

TEST(AoIntegrator, MatchesClosedFormBetweenParallelPlanes) {
    // Floor y = 0 and a ceiling at height h (both effectively infinite). A cosine-distributed ray
    // from the floor reaches the ceiling within distance D iff cos(theta) > h / D, which has
    // probability 1 - (h/D)^2; so the unoccluded fraction is (h/D)^2.
    const float h = 1.0f, D = 2.0f;
    Scene s;
    s.materials = {make_diffuse(Rgb(0.5f))};
    test::add_quad(s, {-1e3f, 0, -1e3f}, {0, 0, 2e3f}, {2e3f, 0, 0});  // floor, facing +y
    test::add_quad(s, {-1e3f, h, -1e3f}, {2e3f, 0, 0}, {0, 0, 2e3f});  // ceiling, facing -y
    Accelerator accel(s.meshes, s.spheres, s.shapes);
    AoIntegrator ao(accel, D);
    const int n = 200000;
    double sum = 0;
    RayCounters counters;
    for (int i = 0; i < n; ++i) {
        Sampler rng(SamplerType::kIndependent, 0, uint32_t(i), 1);
        // The camera sits between the planes, looking down at the floor.
        sum += double(ao.radiance(Ray{{0, 0.5f, 0}, {0, -1, 0}}, rng, counters).r);
    }
    double expected = double(h * h / (D * D));
    // Bernoulli estimator: standard error sqrt(p (1 - p) / n); allow 5 sigma.
    double sigma = std::sqrt(expected * (1 - expected) / n);
    EXPECT_NEAR(sum / n, expected, 5 * sigma);
    EXPECT_EQ(counters.camera, uint64_t(n));
    EXPECT_EQ(counters.shadow, uint64_t(n));
}

TEST(AoIntegrator, OpenPlaneIsUnoccludedAndEnclosedPointIsOccluded) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.5f))};
    test::add_quad(s, {-10, 0, -10}, {0, 0, 20}, {20, 0, 0});
    Accelerator open(s.meshes, s.spheres, s.shapes);
    AoIntegrator ao_open(open, kInfinity);
    RayCounters c;
    for (int i = 0; i < 100; ++i) {
        Sampler rng(SamplerType::kIndependent, 1, uint32_t(i), 0);
        EXPECT_EQ(ao_open.radiance(down_ray(), rng, c), Rgb(1.0f));
    }
    // Inside a closed sphere every direction is blocked.
    Scene inside;
    inside.materials = {make_diffuse(Rgb(0.5f))};
    test::add_sphere(inside, {0, 0, 0}, 5.0);
    Accelerator closed(inside.meshes, inside.spheres, inside.shapes);
    AoIntegrator ao_closed(closed, kInfinity);
    for (int i = 0; i < 100; ++i) {
        Sampler rng(SamplerType::kIndependent, 1, uint32_t(i), 0);
        EXPECT_EQ(ao_closed.radiance(Ray{{0, 0, 0}, {0, 0, 1}}, rng, c), Rgb(0.0f));
    }
}

TEST(DebugIntegrators, NormalsDepthAlbedoOfAKnownHit) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.1f, 0.2f, 0.3f)), make_mirror(Rgb(0.9f))};
    test::add_quad(s, {-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, 0);  // floor facing +y
    Accelerator accel(s.meshes, s.spheres, s.shapes);
    RayCounters c;
    Sampler rng(SamplerType::kIndependent, 0, 0, 0);
    EXPECT_EQ(NormalsIntegrator(accel).radiance(down_ray(), rng, c), Rgb(0.5f, 1.0f, 0.5f));
    // Depth counts from the camera position: near (2.5) plus the ray's own distance (1).
    EXPECT_EQ(DepthIntegrator(accel, 2.5f).radiance(down_ray(), rng, c), Rgb(3.5f));
    EXPECT_EQ(AlbedoIntegrator(s, accel).radiance(down_ray(), rng, c), Rgb(0.1f, 0.2f, 0.3f));
    // Escaping rays are black in all of them.
    Ray up{{0, 1, 0}, {0, 1, 0}};
    EXPECT_EQ(NormalsIntegrator(accel).radiance(up, rng, c), Rgb(0.0f));
    EXPECT_EQ(DepthIntegrator(accel, 0.0f).radiance(up, rng, c), Rgb(0.0f));
    EXPECT_EQ(AlbedoIntegrator(s, accel).radiance(up, rng, c), Rgb(0.0f));
}

TEST(Renderer, CountsSamplesAndRaysAndFillsEveryPixel) {
    Scene scene = test::small_box_scene(20, 10, 4);
    scene.integrator.type = IntegratorType::kAlbedo;
    RenderResult r = render(scene, {.threads = 2});
    EXPECT_EQ(r.image.width, 20);
    EXPECT_EQ(r.image.height, 10);
    EXPECT_EQ(r.stats.samples, 20u * 10u * 4u);
    EXPECT_EQ(r.stats.rays.camera, 20u * 10u * 4u);
    EXPECT_EQ(r.stats.dropped_samples, 0u);
    // Pixel (10, 3) sees only the back wall (at z = 1 its rays span y in [0.41, 0.83], above the
    // ball), so every sample returns the wall's albedo exactly.
    EXPECT_EQ(r.image.at(10, 3), Rgb(0.8f, 0.7f, 0.6f));
}

}  // namespace
}  // namespace candela
