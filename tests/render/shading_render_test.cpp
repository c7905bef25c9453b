// Renders with normal maps and alpha cutouts: a flat map and a transparent surface change nothing,
// a tilted map follows the cosine law, half-transparent surfaces pass half the light, and images
// stay the same for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "candela/render/renderer.h"
#include "support/polygon_irradiance.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

bool bit_identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

float brightest(const Image& image) {
    float m = 0.0f;
    for (const Rgb& p : image.pixels) m = std::max(m, p.max_component());
    return m;
}

// The colour of tangent-space normal n.
Rgb encode(Vec3f n) { return Rgb(0.5f * n.x + 0.5f, 0.5f * n.y + 0.5f, 0.5f * n.z + 0.5f); }

// Gives every material of the scene a constant normal map of tangent-space normal n.
void map_every_normal(Scene& scene, Vec3f n) {
    SurfaceParams s;
    s.normal_map = ColorParam{encode(n)};
    for (Material& m : scene.materials) set_surface(m, s);
}

TEST(NormalMapRender, FlatMapRendersBitIdenticalToNone) {
    // Diffuse walls, a mirror and a glass sphere: every lobe kind in the mapped frame.
    const Scene plain = test::cornell_glass_scene(24, 24, 8);
    Scene flat = plain;
    map_every_normal(flat, Vec3f(0, 0, 1));
    ASSERT_TRUE(flat.materials[0].needs_shading_geometry);
    const Image a = render(plain, {.threads = 2}).image;
    EXPECT_GT(brightest(a), 0.0f);
    EXPECT_TRUE(bit_identical(a, render(flat, {.threads = 2}).image));
    // Control: a tilted map goes through the same code and does change the image.
    Scene tilted = plain;
    map_every_normal(tilted, normalize(Vec3f(0.3f, 0, 1)));
    EXPECT_FALSE(bit_identical(a, render(tilted, {.threads = 2}).image));
}

// A diffuse floor (y = 0, front +y; its quad's dpdu runs along +z) seen at one point, the origin,
// through a one-pixel camera of tiny field of view, lit by a small square light at (0, 2, 2)
// facing down. A normal map tilting the normal by `tilt` towards +u (+z, the light's side) sets
// the irradiance to Lambert's polygon formula for the tilted normal (the light lies wholly above
// the tilted tangent plane for the tilts used). Direct light only (max_depth 1).
constexpr float kFloorAlbedo = 0.8f;
constexpr float kLightRadiance = 50.0f;

test::Polygon small_light() { return {{-0.1, 2, 1.9}, {0.1, 2, 1.9}, {0.1, 2, 2.1}, {-0.1, 2, 2.1}}; }

Scene tilted_floor(float tilt, uint64_t seed) {
    Scene s;
    s.materials = {make_diffuse(Rgb(kFloorAlbedo)), make_diffuse(Rgb(0.0f))};
    s.material_names = {"floor", "black"};
    SurfaceParams surface;
    surface.normal_map = ColorParam{encode(Vec3f(std::sin(tilt), 0.0f, std::cos(tilt)))};
    set_surface(s.materials[0], surface);
    test::add_quad(s, {-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, 0);  // +y; edge1 (u) along +z
    const uint32_t light = test::add_quad(s, {-0.1f, 2, 1.9f}, {0.2f, 0, 0}, {0, 0, 0.2f}, 1);  // faces -y
    test::set_emission(s, light, Rgb(kLightRadiance));
    test::set_camera(s, Vec3f{0, 1, -1}, Vec3f{0, 0, 0}, 0.01f, 1, 1);
    s.sampler.spp = 4096;
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.seed = seed;
    s.integrator.max_depth = 1;
    return s;
}

// rho E / pi at the origin for the normal tilted by `tilt` towards +z.
double expected_radiance(float tilt) {
    const Vec3d n(0.0, std::cos(double(tilt)), std::sin(double(tilt)));
    return double(kFloorAlbedo) * test::polygon_irradiance(Vec3d(0.0), n, small_light(), kLightRadiance) / kPiD;
}

TEST(NormalMapRender, TiltedMapFollowsTheCosineLaw) {
    const float tilts[] = {-0.3f, 0.0f, 0.3f};
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, 3));
    test::ZTestFamily untilted(family.z_critical());  // power: the untilted answer must be rejected
    double previous = 0.0;
    for (int k = 0; k < 3; ++k) {
        const test::RenderMoments m = test::render_moments(tilted_floor(tilts[k], 11 + uint64_t(k)));
        const test::BlockEstimate b = test::block_estimate(m, 0, 0, 1, 0);
        family.add(b.mean - expected_radiance(tilts[k]), b.variance, k, 0, 0);
        if (tilts[k] != 0.0f) untilted.add(b.mean - expected_radiance(0.0f), b.variance, k, 0, 0);
        EXPECT_GT(b.mean, previous);  // tilting towards the light brightens the floor
        previous = b.mean;
    }
    EXPECT_TRUE(family.passed()) << family.summary();
    EXPECT_EQ(untilted.rejected(), 2) << untilted.summary();
}

// A material of alpha `alpha` (diffuse, of albedo `albedo`) added to the scene; returns its index.
uint32_t add_cutout_material(Scene& scene, float alpha, float albedo) {
    Material m = make_diffuse(Rgb(albedo));
    SurfaceParams s;
    s.alpha = FloatParam{alpha};
    set_surface(m, s);
    scene.materials.push_back(m);
    scene.material_names.push_back("cutout");
    return uint32_t(scene.materials.size() - 1);
}

// Cut-out shapes between the camera and the box, under the light, and a sphere in the box.
void add_cutouts(Scene& scene, uint32_t material) {
    test::add_quad(scene, {-1, -1, -0.9f}, {0, 2, 0}, {2, 0, 0}, material);         // across the view, -z
    test::add_quad(scene, {-1, 0.9f, -1}, {2, 0, 0}, {0, 0, 2}, material);          // under the light, -y
    test::add_sphere(scene, {0.0, -0.2, 0.0}, 0.3, material);
}

TEST(AlphaRender, TransparentSurfacesAreInvisibleAndCastNoShadows) {
    const Scene plain = test::cornell_box_scene(24, 24, 8);
    Scene cut = plain;
    add_cutouts(cut, add_cutout_material(cut, 0.0f, 0.8f));
    const Image a = render(plain, {.threads = 2}).image;
    EXPECT_GT(brightest(a), 0.0f);
    // Every ray passes them, so every path, and every random number it draws, is the same.
    EXPECT_TRUE(bit_identical(a, render(cut, {.threads = 2}).image));
    // Control: opaque, the same shapes show.
    Scene opaque = plain;
    add_cutouts(opaque, add_cutout_material(opaque, 1.0f, 0.8f));
    EXPECT_FALSE(bit_identical(a, render(opaque, {.threads = 2}).image));
}

TEST(AlphaRender, SameImageForAnyThreadCountAndTileSize) {
    Scene scene = test::lit_small_box_scene(37, 23, 8);
    add_cutouts(scene, add_cutout_material(scene, 0.5f, 0.8f));
    const Image one = render(scene, {.threads = 1, .tile_size = 16}).image;
    EXPECT_GT(brightest(one), 0.0f);
    EXPECT_TRUE(bit_identical(one, render(scene, {.threads = 2, .tile_size = 16}).image));
    EXPECT_TRUE(bit_identical(one, render(scene, {.threads = 2, .tile_size = 5}).image));
}

// A square light of radiance 1 facing -y at y = 2 over a diffuse floor at y = 0, optionally with
// a black plane of alpha 1/2 at y = 1 between them; the camera, below the plane, sees the floor
// and, at the top of the image, the light's front through the plane. With direct light only,
// every path from the light to the camera crosses the plane once, so the plane halves every
// pixel's expectation.
Scene light_through_plane(bool with_plane, uint64_t seed) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.8f)), make_diffuse(Rgb(0.0f))};
    s.material_names = {"floor", "black"};
    test::add_quad(s, {-20, 0, -20}, {0, 0, 40}, {40, 0, 0}, 0);  // +y
    const uint32_t light = test::add_quad(s, {-1, 2, -1}, {2, 0, 0}, {0, 0, 2}, 1);  // faces -y
    test::set_emission(s, light, Rgb(1.0f));
    if (with_plane) test::add_quad(s, {-20, 1, -20}, {40, 0, 0}, {0, 0, 40}, add_cutout_material(s, 0.5f, 0.0f));
    test::set_camera(s, Vec3f{0, 0.5f, -2.5f}, Vec3f{0, 0.6f, 0}, 70, 16, 16);
    s.sampler.spp = 256;
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.seed = seed;
    s.integrator.max_depth = 1;
    return s;
}

TEST(AlphaRender, HalfTransparentSurfaceLetsHalfTheLightThrough) {
    const test::RenderMoments with = test::render_moments(light_through_plane(true, 3));
    const test::RenderMoments without = test::render_moments(light_through_plane(false, 4));
    constexpr int kBlock = 4;
    const long lit = test::lit_blocks(without, kBlock);
    ASSERT_GT(lit, 3 * 16 / 2);
    test::ZTestFamily family(test::sidak_critical_z(test::kRenderTestAlpha, 3 * 16));
    test::compare_renders(with, without, kBlock, family, 0.5);
    EXPECT_TRUE(family.passed()) << family.summary();
    // Power: the same test rejects a plane that passed 60% in some of the lit blocks.
    test::ZTestFamily wrong(family.z_critical());
    test::compare_renders(with, without, kBlock, wrong, 0.6);
    EXPECT_GE(wrong.rejected(), lit / 4) << wrong.summary();
    if (!family.passed()) test::write_diagnostic(with, "alpha_half_plane");
}

}  // namespace
}  // namespace candela
