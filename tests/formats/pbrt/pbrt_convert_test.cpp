// `candela convert`'s promise (pbrt_convert.h): the JSON scene and PLY meshes it writes load as
// the same Scene as the pbrt-v4 file, so they render the same bits. Each of the four pbrt-v4
// scenes of scenes/pbrt-v4/ is converted into a temporary folder, both are loaded and rendered
// tiny (24x24, 2 spp), and the images and meshes are compared byte for byte.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <string>
#include <vector>

#include "candela/formats/json/scene_loader.h"
#include "candela/formats/pbrt/pbrt_convert.h"
#include "candela/formats/scene_file.h"
#include "candela/render/renderer.h"
#include "candela/scene/scene.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

struct ConvertCase {
    const char* folder;
    const char* file;
};

constexpr ConvertCase kScenes[] = {
    {"cornell-box", "scene-v4.pbrt"},
    {"veach-mis", "scene-v4.pbrt"},
    {"killeroo-simple", "killeroo-simple.pbrt"},
    {"veach-bidir", "scene-v4.pbrt"},
};

void PrintTo(const ConvertCase& c, std::ostream* os) { *os << c.folder; }

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

Image render_tiny(Scene scene) {
    scene.camera.width = 24;
    scene.camera.height = 24;
    scene.sampler.spp = 2;
    return render(scene, {.threads = 2}).image;
}

class ConvertRoundTrip : public testing::TestWithParam<ConvertCase> {};

TEST_P(ConvertRoundTrip, ConvertedSceneRendersTheSameBits) {
    const ConvertCase& c = GetParam();
    const fs::path in = fs::path(CANDELA_SOURCE_DIR) / "scenes/pbrt-v4" / c.folder / c.file;
    const fs::path dir = fs::path(CANDELA_TEST_BINARY_DIR) / "pbrt_convert" / c.folder;
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path out = dir / "scene.json";
    const pbrt::ConvertResult converted = pbrt::convert_pbrt_scene(in, out);
    ASSERT_TRUE(fs::exists(out));

    const Scene from_pbrt = load_scene_file(in);
    const Scene from_json = load_scene(out);
    // The importer's warnings (pbrt-v4 features left out) come with the conversion; the written
    // scene has nothing left to warn about beyond what the JSON loader says of both.
    EXPECT_EQ(converted.warnings, from_pbrt.warnings);
    EXPECT_LE(from_json.warnings.size(), from_pbrt.warnings.size()) << testing::PrintToString(from_json.warnings);
    ASSERT_EQ(from_json.meshes.size(), from_pbrt.meshes.size());
    ASSERT_GT(from_pbrt.meshes.size() + from_pbrt.spheres.size() + from_pbrt.disks.size(), 0u);
    for (size_t i = 0; i < from_pbrt.meshes.size(); ++i) {
        SCOPED_TRACE("mesh " + std::to_string(i));
        EXPECT_TRUE(same_bytes(from_json.meshes[i].positions, from_pbrt.meshes[i].positions));
        EXPECT_TRUE(same_bytes(from_json.meshes[i].normals, from_pbrt.meshes[i].normals));
        EXPECT_TRUE(same_bytes(from_json.meshes[i].uvs, from_pbrt.meshes[i].uvs));
        EXPECT_TRUE(same_bytes(from_json.meshes[i].indices, from_pbrt.meshes[i].indices));
    }
    EXPECT_EQ(from_json.shapes.size(), from_pbrt.shapes.size());
    EXPECT_EQ(from_json.materials.size(), from_pbrt.materials.size());

    const Image a = render_tiny(from_pbrt);
    const Image b = render_tiny(from_json);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_TRUE(same_bytes(a.pixels, b.pixels)) << c.folder << ": the converted scene renders other pixels";
    float brightest = 0;
    for (const Rgb& p : a.pixels) brightest = std::max(brightest, p.max_component());
    EXPECT_GT(brightest, 0.0f);  // an all-black pair would prove nothing
}

INSTANTIATE_TEST_SUITE_P(PbrtV4Scenes, ConvertRoundTrip, testing::ValuesIn(kScenes),
                         [](const testing::TestParamInfo<ConvertCase>& p) {
                             std::string n = p.param.folder;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

// -o DIR/x.json makes a missing DIR (nested too) whether or not the scene has meshes to put there.
TEST(Convert, MakesTheMissingOutputFolderWithOrWithoutMeshes) {
    const fs::path dir = fs::path(CANDELA_TEST_BINARY_DIR) / "pbrt_convert_folders";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string head = "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
                             "LightSource \"point\" \"rgb I\" [1 1 1]\n";
    const std::pair<const char*, std::string> scenes[] = {
        {"spheres", head + "Shape \"sphere\"\n"},
        {"meshes", head + "Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n"},
    };
    for (const auto& [name, text] : scenes) {
        SCOPED_TRACE(name);
        const fs::path in = dir / (std::string(name) + ".pbrt");
        std::ofstream(in) << text;
        const fs::path out = dir / name / "new" / "scene.json";
        const pbrt::ConvertResult converted = pbrt::convert_pbrt_scene(in, out);
        EXPECT_TRUE(fs::is_regular_file(out));
        EXPECT_EQ(converted.mesh_files, std::string(name) == "meshes" ? 1u : 0u);
        EXPECT_NO_THROW(load_scene(out));
    }
}

}  // namespace
}  // namespace candela
