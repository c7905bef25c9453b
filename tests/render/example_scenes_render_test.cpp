// Every example scene in scenes/ loads without errors or warnings and renders: a tiny image at
// a few samples per pixel, with no dropped (non-finite) samples and something visible. The
// README points users at these scenes, so a key that stops loading or a feature that crashes on
// them must fail here, not in a user's first command.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "candela/render/renderer.h"
#include "candela/formats/json/scene_loader.h"

namespace candela {
namespace CANDELA_UNITY_ID {

std::vector<std::filesystem::path> example_scenes() {
    std::vector<std::filesystem::path> out;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(CANDELA_SOURCE_DIR) + "/scenes"))
        if (std::filesystem::exists(entry.path() / "scene.json")) out.push_back(entry.path() / "scene.json");
    std::sort(out.begin(), out.end());
    return out;
}

TEST(ExampleScenes, EveryExampleSceneLoadsCleanlyAndRenders) {
    const std::vector<std::filesystem::path> scenes = example_scenes();
    ASSERT_GE(scenes.size(), 10u);  // the five of version 1, material-spheres, veach-mis, depth-of-field, cornell-box-pbrt, prism
    for (const std::filesystem::path& file : scenes) {
        SCOPED_TRACE(file.string());
        Scene scene = load_scene(file);
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
        scene.camera.width = 24;
        scene.camera.height = 16;
        scene.sampler.spp = 4;
        RenderResult r = render(scene, {.threads = 2});
        EXPECT_EQ(r.stats.dropped_samples, 0u);
        float brightest = 0.0f;
        for (const Rgb& p : r.image.pixels) brightest = std::max(brightest, p.max_component());
        EXPECT_GT(brightest, 0.0f);
    }
}

}  // namespace
}  // namespace candela
