// Against pbrt-v4 (issue 14): scenes/cornell-box-pbrt, Bitterli's Cornell box with the numbers
// of its pbrt-v4 file, rendered in spectral mode matches pbrt-v4's own render within the bounds
// of ../shared/refs/pbrt-v4/scenes.txt (1% on each channel's mean, 2% on the 16x16-block p95
// of the relative luminance difference: what pbrt-v4's own noise explains, README there). The
// reference is kept as its 16x16-block means (tests/data/refs/, 3 KB, written by
// `candela_compare_pbrt --write-block-means ../shared/refs/pbrt-v4/cornell-box.exr OUT.exr`), all
// the comparison reads. The control: RGB mode is outside the bounds (+4% in blue over the image,
// 10% at the block p95), the difference the spectral mode exists to remove. The control renders 64
// spp, not the scene's 256: its +4% in blue is a mean over the whole image, whose noise at 64 spp
// is far below 1% (a quarter of the time; the block p95 is then noise too, so it is not asserted).
#include <gtest/gtest.h>

#include <filesystem>

#include "bench/block_compare.h"
#include "candela/image/image_io.h"
#include "candela/render/renderer.h"
#include "candela/formats/json/scene_loader.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// `spp`: 0 keeps the scene's.
bench::BlockComparison compare_with_pbrt(bool spectral, int spp = 0) {
    const std::filesystem::path root(CANDELA_SOURCE_DIR);
    Scene scene = load_scene(root / "scenes/cornell-box-pbrt/scene.json");
    scene.integrator.spectral = spectral;
    if (spp > 0) scene.sampler.spp = spp;
    const Image image = render(scene, {}).image;
    const Image ref = read_image(root / "tests/data/refs/pbrt-v4-cornell-box-blocks16.exr");
    return bench::compare_blocks(bench::block_means(image, 16), ref, 1);
}

TEST(AgainstPbrtV4, SpectralCornellBoxIsWithinPbrtsOwnNoise) {
    const bench::BlockComparison c = compare_with_pbrt(true);
    EXPECT_EQ(c.blocks_total, 256);
    EXPECT_TRUE(bench::within_bounds(c, 0.01, 0.02))
        << "mean ratio " << c.mean_ratio[0] << " " << c.mean_ratio[1] << " " << c.mean_ratio[2] << ", block p95 "
        << c.p95;
}

TEST(AgainstPbrtV4, RgbCornellBoxIsNot) {
    const bench::BlockComparison c = compare_with_pbrt(false, 64);
    EXPECT_GT(c.mean_ratio[2], 1.02) << "mean ratio " << c.mean_ratio[0] << " " << c.mean_ratio[1] << " "
                                     << c.mean_ratio[2];  // blue: +4% over the image
}

}  // namespace
}  // namespace candela
