// AOV layers (film/aov_layers.h, integrators/aov_tracer.h) on scenes whose albedo, normals and depth
// are known: a diffuse plane facing the camera, the same seen in a mirror, and nothing at all;
// filtered and averaged exactly like the beauty image; the same across stop and resume; and the
// beauty image the same bits with or without them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/film/pixel_filter.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/renderer.h"
#include "candela/render/job/shard_merge.h"
#include "candela/render/job/shard_part.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

AovLayers all_aovs() {
    AovLayers a;
    for (AovLayer l : {AovLayer::kAlbedo, AovLayer::kNormal, AovLayer::kDepth, AovLayer::kPosition}) a.add(l);
    return a;
}

const ImageLayer& layer(const RenderResult& r, const std::string& name) {
    for (const ImageLayer& l : r.aov_layers)
        if (l.name == name) return l;
    ADD_FAILURE() << "no layer " << name;
    return r.aov_layers.front();
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// A camera at the origin looking down +z (fov 40 degrees) at a square that fills its view at
// z = `distance`, facing it (normal -z), of material 0. No light: the beauty is black, the AOVs
// are not.
Scene facing_plane_scene(Material material, float distance, int spp) {
    Scene s;
    s.materials = {material};
    s.material_names = {"plane"};
    test::add_quad(s, {-50, -50, distance}, {0, 100, 0}, {100, 0, 0});  // cross(e1, e2) = -z
    test::set_camera(s, Vec3f{0, 0, 0}, Vec3f{0, 0, 1}, 40, 16, 12);
    s.sampler.spp = spp;
    s.sampler.seed = 7;
    s.film.aovs = all_aovs();
    return s;
}

// The cosine of the widest angle between the view axis and a ray of the 16x12, 40-degree camera
// (the vertical fov is 40 degrees, or the horizontal one when the image is taller): at a corner.
float widest_cosine() {
    const float t = std::tan(20.0f * 3.14159265f / 180.0f);  // half height at distance 1
    const float half_w = t * 16.0f / 12.0f;
    return 1.0f / std::sqrt(1.0f + t * t + half_w * half_w);
}

TEST(AovRender, FacingPlaneHasItsAlbedoNormalDepthAndPosition) {
    const RenderResult r = render(facing_plane_scene(make_diffuse(Rgb(0.5f)), 2.0f, 16), {.threads = 2});
    ASSERT_EQ(r.aov_layers.size(), 4u);
    EXPECT_EQ(r.aov_layers[0].name, "albedo");
    EXPECT_EQ(r.aov_layers[1].name, "normal");
    EXPECT_EQ(r.aov_layers[2].name, "depth");
    EXPECT_EQ(r.aov_layers[3].name, "position");
    EXPECT_EQ(r.aov_layers[2].channels, 1);
    EXPECT_EQ(r.aov_layers[2].channel_names[0], "Z");
    EXPECT_EQ(r.aov_layers[1].channel_names[2], "N.Z");
    const Image& albedo = layer(r, "albedo").image;
    const Image& normal = layer(r, "normal").image;
    const Image& depth = layer(r, "depth").image;
    const Image& position = layer(r, "position").image;
    const float max_depth = 2.0f / widest_cosine();
    for (size_t i = 0; i < albedo.pixels.size(); ++i) {
        // Every sample sees the same albedo and normal: their mean is exact.
        EXPECT_EQ(albedo.pixels[i], Rgb(0.5f)) << i;
        EXPECT_EQ(normal.pixels[i], Rgb(0.0f, 0.0f, -1.0f)) << i;  // facing the camera
        const Rgb p = position.pixels[i];
        EXPECT_NEAR(p.b, 2.0f, 1e-5f) << i;
        // The mean distance of a pixel's hits is at least the distance of their mean (Jensen)
        // and, over a pixel's 2.5-degree footprint, at most 0.1% more.
        const float mean_p = std::sqrt(p.r * p.r + p.g * p.g + p.b * p.b);
        const float z = depth.pixels[i].r;
        EXPECT_GE(z, mean_p * (1.0f - 1e-5f)) << i;
        EXPECT_LE(z, mean_p * 1.001f) << i;
        EXPECT_GE(z, 2.0f * (1.0f - 1e-6f)) << i;
        EXPECT_LE(z, max_depth) << i;
        EXPECT_EQ(depth.pixels[i].g, 0.0f);  // one channel
    }
    // The view is symmetric: the corners are farthest, the centre nearest.
    EXPECT_GT(depth.at(0, 0).r, depth.at(8, 6).r * 1.05f);
}

TEST(AovRender, MirrorIsLookedThroughToTheFirstDiffuseVertex) {
    // A mirror of albedo 0.9 at z = 2 facing the camera, and behind the camera a diffuse plane of
    // albedo 0.25 at z = -1 facing +z: every camera ray comes back to the plane.
    Scene s = facing_plane_scene(make_mirror(Rgb(0.9f)), 2.0f, 8);
    s.materials.push_back(make_diffuse(Rgb(0.25f)));
    s.material_names.push_back("behind");
    test::add_quad(s, {-50, -50, -1}, {100, 0, 0}, {0, 100, 0}, 1);  // cross(e1, e2) = +z
    const RenderResult r = render(s, {.threads = 2});
    const Image& albedo = layer(r, "albedo").image;
    const Image& normal = layer(r, "normal").image;
    const Image& depth = layer(r, "depth").image;
    const Image& position = layer(r, "position").image;
    for (size_t i = 0; i < albedo.pixels.size(); ++i) {
        // The diffuse plane's albedo times the mirror's tint (float rounding of the BSDF's f |cos| / pdf).
        EXPECT_NEAR(albedo.pixels[i].r, 0.9f * 0.25f, 1e-6f) << i;
        EXPECT_NEAR(albedo.pixels[i].b, 0.9f * 0.25f, 1e-6f) << i;
        // The plane's normal, facing the reflected rays that reach it.
        EXPECT_NEAR(normal.pixels[i].b, 1.0f, 1e-6f) << i;
        // Depth and position stay the mirror's: the first hit.
        EXPECT_NEAR(position.pixels[i].b, 2.0f, 1e-5f) << i;
        EXPECT_GE(depth.pixels[i].r, 2.0f * (1.0f - 1e-6f)) << i;
        EXPECT_LE(depth.pixels[i].r, 2.0f / widest_cosine()) << i;
    }
}

TEST(AovRender, ClearGlassPassesThroughWithItsFresnelShare) {
    // A clear glass sphere (index 1.5) well inside the view, in front of the diffuse plane of
    // albedo 0.5: at a pixel looking through its centre the camera ray refracts straight through
    // (with probability (1 - F)^2 about 0.92, F = 0.04 at normal incidence, on entering and
    // leaving; a reflection ends on nothing and gives albedo 0). The mean albedo is
    // 0.5 (1 - F)^2 plus the rare paths reflected inside and out again.
    Scene s = facing_plane_scene(make_diffuse(Rgb(0.5f)), 4.0f, 1024);
    s.materials.push_back(make_dielectric(1.5f));
    s.material_names.push_back("glass");
    test::add_sphere(s, {0, 0, 2}, 0.5, 1);
    s.camera.width = s.camera.height = 4;  // the centre pixels look through the sphere's middle
    s.camera.fov_degrees = 2.0f;
    s.sampler.type = SamplerType::kIndependent;
    const RenderResult r = render(s, {.threads = 2});
    const Image& albedo = layer(r, "albedo").image;
    double mean = 0.0;
    for (const Rgb& p : albedo.pixels) mean += double(p.r) / double(albedo.pixels.size());
    // (1 - F)^2 = 0.9216 near normal incidence; 16 pixels x 1024 samples of a Bernoulli albedo
    // (0 or 0.5): sigma = 0.5 sqrt(0.08 * 0.92 / 16384) = 0.0011; 5 sigma, and F's growth over
    // the 2-degree view is negligible.
    EXPECT_NEAR(mean, 0.5 * 0.9216, 0.006);
}

TEST(AovRender, MissesHaveDocumentedValues) {
    Scene s = facing_plane_scene(make_diffuse(Rgb(0.5f)), 2.0f, 4);
    s.camera.look_at = Vec3f{0, 0, -1};  // away from the plane
    const RenderResult r = render(s, {.threads = 1});
    for (size_t i = 0; i < r.image.pixels.size(); ++i) {
        EXPECT_EQ(layer(r, "albedo").image.pixels[i], Rgb(0.0f));
        EXPECT_EQ(layer(r, "normal").image.pixels[i], Rgb(0.0f));
        EXPECT_EQ(layer(r, "position").image.pixels[i], Rgb(0.0f));
        EXPECT_EQ(layer(r, "depth").image.pixels[i].r, kAovMissDepth);
        EXPECT_TRUE(std::isfinite(layer(r, "depth").image.pixels[i].r));
    }
}

// The albedo and depth debug integrators put, as their beauty, the value the AOV layer sums for
// each sample: so the layer must be the beauty image, bit for bit, for every kind of filter
// (weighted films included) and samples split over passes.
TEST(AovRender, LayersAreFilteredAndAveragedExactlyLikeTheBeauty) {
    for (FilterSettings filter : {FilterSettings(FilterType::kBox), FilterSettings(FilterType::kGaussian),
                                  test::filter_of(FilterType::kMitchell), test::filter_of(FilterType::kLanczos)}) {
        Scene box = test::small_box_scene(21, 13, 6);  // edges, a sphere, misses
        box.film.filter = filter;
        box.film.aovs.add(AovLayer::kAlbedo);
        box.integrator.type = IntegratorType::kAlbedo;
        const RenderResult a = render(box, {.threads = 2, .pass_spp = 4});
        EXPECT_TRUE(same_bits(a.image, layer(a, "albedo").image)) << int(filter.type);

        Scene plane = facing_plane_scene(make_diffuse(Rgb(0.5f)), 2.0f, 5);  // no misses
        plane.film.filter = filter;
        plane.film.aovs = {};
        plane.film.aovs.add(AovLayer::kDepth);
        plane.integrator.type = IntegratorType::kDepth;
        const RenderResult d = render(plane, {.threads = 2, .pass_spp = 2});
        Image depth = layer(d, "depth").image;
        for (Rgb& p : depth.pixels) p = Rgb(p.r);  // the integrator's grey
        EXPECT_TRUE(same_bits(d.image, depth)) << int(filter.type);
    }
}

TEST(AovRender, BeautyIsTheSameBitsWithOrWithoutAovs) {
    for (bool spectral : {false, true})
        for (SamplerType sampler : {SamplerType::kIndependent, SamplerType::kSobol}) {
            Scene s = test::lit_small_box_scene(19, 11, 8);
            s.integrator.spectral = spectral;
            s.sampler.type = sampler;
            const RenderResult without = render(s, {.threads = 2});
            s.film.aovs = all_aovs();
            const RenderResult with = render(s, {.threads = 3, .pass_spp = 3});
            EXPECT_TRUE(without.aov_layers.empty());
            EXPECT_EQ(with.aov_layers.size(), 4u);
            EXPECT_TRUE(same_bits(without.image, with.image)) << spectral << " " << int(sampler);
            EXPECT_EQ(without.state.film.values_per_pixel(), 3);
            EXPECT_EQ(with.state.film.values_per_pixel(), 3 + 10);
        }
}

TEST(AovRender, AovsAcrossCheckpointAndResumeEqualUninterrupted) {
    for (FilterSettings filter : {FilterSettings(FilterType::kBox), test::filter_of(FilterType::kMitchell)}) {
        Scene s = test::lit_small_box_scene(23, 17, 9);  // a light, a mirror ball: every AOV branch
        s.film.filter = filter;
        s.film.aovs = all_aovs();
        const RenderResult whole = render(s, {.threads = 2});

        int passes = 0;
        RenderOptions first{.threads = 3, .pass_spp = 4};
        first.on_pass = [&passes](const RenderState&) { ++passes; };
        first.stop = [&passes] { return passes >= 1; };
        const RenderResult stopped = render(s, first);
        ASSERT_EQ(stopped.state.samples_done, 4u);
        const fs::path file = fs::path(CANDELA_TEST_BINARY_DIR) / "aov_resume.ckpt";
        const RenderIdentity id = render_identity(s, 0x1234);
        write_checkpoint(file, id, stopped.state);
        Checkpoint c = read_checkpoint(file);
        check_checkpoint_matches(file, c.identity, id);
        const RenderResult resumed = render(s, {.threads = 1, .pass_spp = 2}, std::move(c.state));

        ASSERT_EQ(resumed.aov_layers.size(), whole.aov_layers.size());
        EXPECT_TRUE(same_bits(resumed.image, whole.image));
        for (size_t l = 0; l < whole.aov_layers.size(); ++l)
            EXPECT_TRUE(same_bits(resumed.aov_layers[l].image, whole.aov_layers[l].image)) << whole.aov_layers[l].name;

        // A checkpoint with other layers is refused, naming them.
        Scene fewer = s;
        fewer.film.aovs = {};
        fewer.film.aovs.add(AovLayer::kAlbedo);
        try {
            check_checkpoint_matches(file, read_checkpoint(file).identity, render_identity(fewer, 0x1234));
            ADD_FAILURE() << "a checkpoint with other AOV layers was accepted";
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("AOV layers albedo, normal, depth, position, this render albedo"),
                      std::string::npos)
                << e.what();
        }
        fs::remove(file);
    }
}

// Shard part files carry the AOV sums through the film's values: merged parts give the whole
// render's layers bit for bit, and a part of a render with other layers is not resumed.
TEST(AovRender, MergedShardPartsGiveTheWholeRendersLayers) {
    const fs::path dir = fs::path(CANDELA_TEST_BINARY_DIR) / "aov_shards";
    fs::create_directories(dir);
    for (bool weighted : {false, true}) {
        Scene s = test::lit_small_box_scene(37, 23, 4);
        if (weighted) s.film.filter = test::filter_of(FilterType::kMitchell);
        s.film.aovs = all_aovs();
        const RenderResult whole = render(s, {.threads = 2});
        std::vector<fs::path> files;
        for (int i = 1; i <= 3; ++i) {
            RenderOptions options{.threads = 1 + i % 2};
            options.shard = Shard{i, 3};
            const RenderResult part = render(s, options);
            files.push_back(dir / ("part-" + std::to_string(i) + ".ckpt"));
            write_shard_part(files.back(), render_identity(s, 0x5eed), part_info(s, options.shard), part.state);
        }
        const MergedRender merged = merge_shard_parts(files);
        ASSERT_TRUE(merged.state.film.aovs() == s.film.aovs);
        EXPECT_EQ(merged.identity.aov_layers, s.film.aovs.mask());
        EXPECT_TRUE(same_bits(merged.state.film.resolve(merged.state.samples_done), whole.image));
        const std::vector<ImageLayer> layers = merged.state.film.resolve_aovs(merged.state.samples_done);
        ASSERT_EQ(layers.size(), whole.aov_layers.size());
        for (size_t l = 0; l < layers.size(); ++l)
            EXPECT_TRUE(same_bits(layers[l].image, whole.aov_layers[l].image)) << layers[l].name << " " << weighted;

        // Resuming part 1 in a render without the normal layer is refused by name.
        const ShardPart part = read_shard_part(files[0]);
        Scene fewer = s;
        fewer.film.aovs = {};
        fewer.film.aovs.add(AovLayer::kAlbedo);
        try {
            check_part_matches(files[0], part, render_identity(fewer, 0x5eed), Shard{1, 3}, make_film(fewer));
            ADD_FAILURE() << "a part with other AOV layers was accepted";
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("AOV layers"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace candela
