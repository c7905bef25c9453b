// The scene content hash behind checkpoints: it changes with everything that changes the image
// (the scene file, the files it names, the command-line overrides) and with nothing else, not
// even the sample count, which a resumed render may raise.
#include "candela/scene/content_hash.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "candela/formats/json/scene_loader.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

// A scene with a mesh and an environment image, in a fresh folder of its own.
class ContentHash : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::path(CANDELA_TEST_BINARY_DIR) / "content_hash" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "meshes");
        fs::copy_file(fs::path(CANDELA_TEST_DATA_DIR) / "scenes/meshes/triangle.obj", dir_ / "meshes/tri.obj");
        fs::copy_file(fs::path(CANDELA_TEST_DATA_DIR) / "scenes/sky_2x1.hdr", dir_ / "sky.hdr");
        write("scene.json", scene_json(16, "0.5"));
    }

    static std::string scene_json(int spp, const std::string& albedo) {
        return R"({"sampler": {"spp": )" + std::to_string(spp) + R"(, "seed": 3},
  "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "resolution": [8, 6]},
  "materials": {"grey": {"type": "diffuse", "albedo": )" + albedo + R"(}},
  "shapes": [{"type": "mesh", "file": "meshes/tri.obj", "material": "grey"}],
  "lights": [{"type": "environment", "file": "sky.hdr"}]}
)";
    }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary) << text;
    }
    void append(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name, std::ios::binary | std::ios::app) << text;
    }
    // The hash of the scene as it is on disk now, loaded as the CLI loads it.
    uint64_t hash() { return scene_content_hash(load_scene(dir_ / "scene.json")); }

    fs::path dir_;
};

TEST_F(ContentHash, SameSceneSameHash) {
    EXPECT_EQ(hash(), hash());
    // Formatting and key order are not content.
    write("scene.json", R"({"lights": [{"file": "sky.hdr", "type": "environment"}],
        "shapes": [{"material": "grey", "type": "mesh", "file": "meshes/tri.obj"}],
        "materials": {"grey": {"albedo": 0.5, "type": "diffuse"}},
        "camera": {"resolution": [8, 6], "look_at": [0, 0, 0], "position": [0, 0, 3]},
        "sampler": {"seed": 3, "spp": 16}})");
    uint64_t reordered = hash();
    write("scene.json", scene_json(16, "0.5"));
    EXPECT_EQ(reordered, hash());
}

TEST_F(ContentHash, SampleCountDoesNotCount) {
    const uint64_t before = hash();
    write("scene.json", scene_json(4096, "0.5"));
    EXPECT_EQ(hash(), before);
    // Nor does --spp.
    Scene s = load_scene(dir_ / "scene.json");
    s.sampler.spp = 7;
    EXPECT_EQ(scene_content_hash(s), before);
}

TEST_F(ContentHash, ChangesWithTheSceneFile) {
    const uint64_t before = hash();
    write("scene.json", scene_json(16, "0.51"));
    EXPECT_NE(hash(), before);
}

TEST_F(ContentHash, ChangesWithAMeshFile) {
    const uint64_t before = hash();
    append("meshes/tri.obj", "# a comment is enough: the bytes changed\n");
    EXPECT_NE(hash(), before);
}

TEST_F(ContentHash, ChangesWithAnEnvironmentImage) {
    const uint64_t before = hash();
    fs::copy_file(fs::path(CANDELA_TEST_DATA_DIR) / "scenes/sky_3x2.hdr", dir_ / "sky.hdr",
                  fs::copy_options::overwrite_existing);
    EXPECT_NE(hash(), before);
}

TEST_F(ContentHash, ChangesWithEachCommandLineOverride) {
    const Scene loaded = load_scene(dir_ / "scene.json");
    const uint64_t before = scene_content_hash(loaded);
    Scene s = loaded;
    s.camera.width = 9;  // --resolution
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.camera.height = 7;
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.integrator.type = IntegratorType::kBsdf;  // --integrator
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.sampler.seed = 4;  // --seed
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.sampler.type = loaded.sampler.type == SamplerType::kSobol ? SamplerType::kIndependent : SamplerType::kSobol;
    EXPECT_NE(scene_content_hash(s), before);  // --sampler
    s = loaded;
    s.film.iso = 200;  // --iso
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.film.exposure_time = 0.5f;  // --exposure-time
    EXPECT_NE(scene_content_hash(s), before);
    s = loaded;
    s.film.white_balance = 5000;  // --white-balance
    EXPECT_NE(scene_content_hash(s), before);
    // --aov: each set of layers its own hash; none, the hash from before AOVs existed.
    s = loaded;
    s.film.aovs.add(AovLayer::kAlbedo);  // --aov albedo
    const uint64_t albedo = scene_content_hash(s);
    EXPECT_NE(albedo, before);
    s.film.aovs.add(AovLayer::kDepth);  // --aov albedo,depth
    EXPECT_NE(scene_content_hash(s), albedo);
    EXPECT_NE(scene_content_hash(s), before);
    s.film.aovs = {};  // --aov none
    EXPECT_EQ(scene_content_hash(s), before);
    s = loaded;
    s.sampler.adaptive = AdaptiveSettings{0.05f, 16};  // --noise-threshold
    const uint64_t adaptive = scene_content_hash(s);
    EXPECT_NE(adaptive, before);
    s.sampler.adaptive->min_spp = 32;  // --min-spp
    EXPECT_NE(scene_content_hash(s), adaptive);
    s.sampler.adaptive = AdaptiveSettings{0.06f, 16};
    EXPECT_NE(scene_content_hash(s), adaptive);
}

}  // namespace
}  // namespace candela
