// DESIGN.md's determinism rule: the image is a function of the scene and seed only, bit for bit,
// whatever the thread count or tile size.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "support/test_scenes.h"

namespace candela {
namespace {

bool bit_identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

class Determinism : public ::testing::TestWithParam<std::pair<IntegratorType, FilterType>> {};

TEST_P(Determinism, SameImageForAnyThreadCountAndTileSize) {
    Scene scene = test::small_box_scene(37, 23, 8);  // sizes that do not divide into tiles
    scene.integrator.type = GetParam().first;
    scene.film.filter = GetParam().second;
    Image one = render(scene, {.threads = 1, .tile_size = 16}).image;
    Image two = render(scene, {.threads = 2, .tile_size = 16}).image;
    Image small_tiles = render(scene, {.threads = 2, .tile_size = 5}).image;
    EXPECT_TRUE(bit_identical(one, two));
    EXPECT_TRUE(bit_identical(one, small_tiles));
    // And the seed matters: a different seed gives a different image (for random integrators).
    scene.sampler.seed += 1;
    Image other = render(scene, {.threads = 2, .tile_size = 16}).image;
    EXPECT_FALSE(bit_identical(one, other));
}

INSTANTIATE_TEST_SUITE_P(AllDebugIntegrators, Determinism,
                         ::testing::Values(std::pair{IntegratorType::kAo, FilterType::kBox},
                                           std::pair{IntegratorType::kNormals, FilterType::kTent},
                                           std::pair{IntegratorType::kDepth, FilterType::kGaussian},
                                           std::pair{IntegratorType::kAlbedo, FilterType::kSmallpt}),
                         [](const auto& param_info) {
                             return std::string(integrator_type_name(param_info.param.first)) + "_" +
                                    std::string(filter_type_name(param_info.param.second));
                         });

}  // namespace
}  // namespace candela
