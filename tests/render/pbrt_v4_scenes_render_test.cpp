// The four pbrt-v4 scenes of ../shared/assets/pbrt-v4 (copied into scenes/pbrt-v4/, unchanged),
// opened as .pbrt files and rendered in spectral mode (the default for pbrt scenes) at the
// resolution of ../shared/refs/pbrt-v4/scenes.txt, against pbrt-v4's own renders. The bounds are
// that file's: what pbrt-v4's own noise at its spp explains (its README). candela renders half
// that spp (since 2026-11-29, for CI's time): its noise is then larger, so the same bounds ask
// more, and they still hold with room (block p95 at half the spp: cornell-box 1.28 % of 2 %,
// veach-mis 3.75 % of 5 %, killeroo-simple 1.61 % of 2 %, veach-bidir 11.5 % of 15 %). The
// references are kept as their 16x16-block means (tests/data/refs/, 3 KB each, written by
// `candela_compare_pbrt --write-block-means ../shared/refs/pbrt-v4/NAME.exr OUT.exr`).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bench/block_compare.h"
#include "candela/formats/scene_file.h"
#include "candela/image/image_io.h"
#include "candela/render/renderer.h"

namespace candela {
namespace CANDELA_UNITY_ID {

struct PbrtScene {
    const char* name;
    const char* file;
    int width, height, spp;
    double max_mean_bias, max_p95;  // scenes.txt
};

// veach-bidir was rendered by pbrt-v4 with bdpt: its lamps shine through glass, which a path
// tracer reaches only by chance, hence its wide bounds and more spp (scenes.txt: 1024, here 512).
constexpr PbrtScene kScenes[] = {
    {"cornell-box", "scene-v4.pbrt", 256, 256, 128, 0.01, 0.02},
    {"veach-mis", "scene-v4.pbrt", 320, 180, 128, 0.02, 0.05},
    {"killeroo-simple", "killeroo-simple.pbrt", 240, 240, 128, 0.01, 0.02},
    {"veach-bidir", "scene-v4.pbrt", 256, 256, 512, 0.03, 0.15},
};

class AgainstPbrtV4Scene : public testing::TestWithParam<PbrtScene> {};

TEST_P(AgainstPbrtV4Scene, IsWithinPbrtsOwnNoise) {
    const PbrtScene& p = GetParam();
    const std::filesystem::path root(CANDELA_SOURCE_DIR);
    Scene scene = load_scene_file(root / "scenes/pbrt-v4" / p.name / p.file);
    ASSERT_TRUE(scene.integrator.spectral);
    scene.camera.width = p.width;
    scene.camera.height = p.height;
    scene.sampler.spp = p.spp;
    const Image image = render(scene, {}).image;
    const Image ref = read_image(root / "tests/data/refs" / (std::string("pbrt-v4-") + p.name + "-blocks16.exr"));
    const bench::BlockComparison c = bench::compare_blocks(bench::block_means(image, 16), ref, 1);
    EXPECT_EQ(c.blocks_total, (p.width / 16) * (p.height / 16));
    EXPECT_TRUE(bench::within_bounds(c, p.max_mean_bias, p.max_p95)) << p.name << ": " << bench::describe(c);
}

INSTANTIATE_TEST_SUITE_P(Scenes, AgainstPbrtV4Scene, testing::ValuesIn(kScenes),
                         [](const testing::TestParamInfo<PbrtScene>& param_info) {
                             std::string n = param_info.param.name;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

}  // namespace
}  // namespace candela
