// DESIGN.md's determinism rule: the image is a function of the scene and seed only, bit for bit,
// whatever the thread count or tile size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

bool bit_identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

class Determinism : public ::testing::TestWithParam<std::pair<IntegratorType, FilterType>> {};

std::string param_name(const ::testing::TestParamInfo<std::pair<IntegratorType, FilterType>>& info) {
    return std::string(integrator_type_name(info.param.first)) + "_" + std::string(filter_type_name(info.param.second));
}

TEST_P(Determinism, SameImageForAnyThreadCountAndTileSize) {
    // Sizes that do not divide into tiles. The light transport integrators get a light, a mirror
    // and indirect light, so that every branch of their loops runs.
    const IntegratorType type = GetParam().first;
    const bool transport = type == IntegratorType::kPath || type == IntegratorType::kBsdf ||
                           type == IntegratorType::kWhitted;
    Scene scene = transport ? test::lit_small_box_scene(37, 23, 8) : test::small_box_scene(37, 23, 8);
    scene.integrator.type = type;
    scene.film.filter = GetParam().second;
    Image one = render(scene, {.threads = 1, .tile_size = 16}).image;
    Image two = render(scene, {.threads = 2, .tile_size = 16}).image;
    Image small_tiles = render(scene, {.threads = 2, .tile_size = 5}).image;
    // A black image would be trivially identical: the scene must show something.
    float brightest = 0.0f;
    for (const Rgb& p : one.pixels) brightest = std::max(brightest, p.max_component());
    EXPECT_GT(brightest, 0.0f);
    EXPECT_TRUE(bit_identical(one, two));
    EXPECT_TRUE(bit_identical(one, small_tiles));
    // And the seed matters: a different seed gives a different image (for random integrators).
    scene.sampler.seed += 1;
    Image other = render(scene, {.threads = 2, .tile_size = 16}).image;
    EXPECT_FALSE(bit_identical(one, other));
}

// Renders `scene` with one thread, two threads, and small tiles; expects the same bits from all
// three and an image that is not black (a black image is trivially identical). Returns it.
Image expect_same_image_for_any_threads_and_tiles(const Scene& scene) {
    Image one = render(scene, {.threads = 1, .tile_size = 16}).image;
    const Image two = render(scene, {.threads = 2, .tile_size = 16}).image;
    const Image small_tiles = render(scene, {.threads = 2, .tile_size = 5}).image;
    float brightest = 0.0f;
    for (const Rgb& p : one.pixels) brightest = std::max(brightest, p.max_component());
    EXPECT_GT(brightest, 0.0f);
    EXPECT_TRUE(bit_identical(one, two));
    EXPECT_TRUE(bit_identical(one, small_tiles));
    return one;
}

// Spectral mode: the wavelengths come from the sampler's own numbers, so the image is still a
// function of the scene, sampler, spp and seed; and it is not the RGB mode's image.
TEST(DeterminismSpectral, SameImageForAnyThreadCountAndTileSize) {
    for (IntegratorType type : {IntegratorType::kPath, IntegratorType::kBsdf, IntegratorType::kWhitted}) {
        SCOPED_TRACE(std::string(integrator_type_name(type)));
        Scene scene = test::lit_small_box_scene(37, 23, 8);
        scene.integrator.type = type;
        scene.integrator.spectral = true;
        const Image one = expect_same_image_for_any_threads_and_tiles(scene);
        scene.integrator.spectral = false;
        EXPECT_FALSE(bit_identical(one, render(scene, {.threads = 2, .tile_size = 16}).image));
    }
}

// Volpath in a scene with media, in both modes: its medium walks draw from generators seeded by
// the sampler's numbers, so the image is still a function of the scene, spp and seed.
TEST(DeterminismMedia, SameImageForAnyThreadCountAndTileSize) {
    for (bool spectral : {false, true}) {
        SCOPED_TRACE(spectral ? "spectral" : "rgb");
        Scene scene = test::media_small_box_scene(37, 23, 8);
        scene.integrator.spectral = spectral;
        const Image one = expect_same_image_for_any_threads_and_tiles(scene);
        scene.sampler.seed += 1;
        EXPECT_FALSE(bit_identical(one, render(scene, {.threads = 2, .tile_size = 16}).image));
    }
}

INSTANTIATE_TEST_SUITE_P(AllDebugIntegrators, Determinism,
                         ::testing::Values(std::pair{IntegratorType::kAo, FilterType::kBox},
                                           std::pair{IntegratorType::kNormals, FilterType::kTent},
                                           std::pair{IntegratorType::kDepth, FilterType::kGaussian},
                                           std::pair{IntegratorType::kAlbedo, FilterType::kSmallpt}),
                         param_name);

INSTANTIATE_TEST_SUITE_P(AllTransportIntegrators, Determinism,
                         ::testing::Values(std::pair{IntegratorType::kPath, FilterType::kBox},
                                           std::pair{IntegratorType::kBsdf, FilterType::kTent},
                                           std::pair{IntegratorType::kWhitted, FilterType::kSmallpt},
                                           std::pair{IntegratorType::kPath, FilterType::kGaussian}),
                         param_name);

}  // namespace
}  // namespace candela
