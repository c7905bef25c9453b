// A scene of every pbrt-v4 feature the importer translates (tests/data/pbrt/features/
// all_features.pbrt): it loads with no warning but the one it must give (the halton sampler), each
// directive becomes the candela element docs/PBRT.md says, and it renders finite pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "candela/render/renderer.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

const std::filesystem::path kScene =
    std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "features" / "all_features.pbrt";

TEST(PbrtFeatures, EveryFeatureTranslates) {
    const ImportedScene s = import_pbrt_file(kScene);
    ASSERT_EQ(s.warnings.size(), 1u) << s.warnings.front();
    EXPECT_NE(s.warnings[0].find("Sampler \"halton\""), std::string::npos);
    const auto& d = s.document;
    EXPECT_EQ(d["sampler"]["seed"], 3);
    EXPECT_EQ(d["integrator"]["max_depth"], 8);
    EXPECT_EQ(d["film"]["filter"]["type"], "mitchell");
    EXPECT_EQ(d["film"]["filename"], "features.exr");
    EXPECT_EQ(d["camera"]["aperture_radius"], 0.01);
    const auto& m = d["materials"];
    EXPECT_EQ(m["gold"]["eta"]["spectrum"], "metal-Au-eta");
    EXPECT_EQ(m["gold"]["roughness"]["texture"], "rough");  // not remapped: remaproughness false
    EXPECT_EQ(m["glass"]["ior"]["spectrum"], "glass-BK7");
    EXPECT_DOUBLE_EQ(m["frost"]["roughness"].get<double>(), 0.2);  // sqrt(0.04)
    EXPECT_EQ(m["pane"]["type"], "thin_dielectric");
    EXPECT_EQ(m["plastic"]["type"], "coated_diffuse");
    EXPECT_EQ(m["plastic"]["pbrt_v4_weights"], true);
    EXPECT_EQ(m["lacquer"]["type"], "coated_conductor");
    EXPECT_EQ(m["blend"]["type"], "blend");
    EXPECT_EQ(m["blend"]["materials"], nlohmann::ordered_json::array({"gold", "plastic"}));
    EXPECT_EQ(m["air"], nlohmann::ordered_json({{"type", "interface"}}));
    const auto& t = d["textures"];
    EXPECT_EQ(t["checks"]["filter"], "point");
    EXPECT_EQ(t["checks"]["uv_scale"], nlohmann::ordered_json::array({4.0, 4.0}));
    EXPECT_EQ(t["solid"]["dimension"], 3);
    EXPECT_EQ(t["bl"]["type"], "bilerp");
    EXPECT_EQ(t["dm"]["type"], "directionmix");
    const auto& lights = d["lights"];
    ASSERT_EQ(lights.size(), 4u);
    EXPECT_EQ(lights[0]["type"], "environment");
    EXPECT_EQ(lights[1]["type"], "directional");
    EXPECT_EQ(lights[1]["irradiance"]["blackbody"], 5500.0);
    EXPECT_EQ(lights[1]["scale"], 2.0);  // illuminance
    EXPECT_EQ(lights[2]["type"], "spot");
    EXPECT_EQ(lights[2]["position"], nlohmann::ordered_json::array({2.0, 3.0, 0.0}));
    EXPECT_EQ(lights[3]["power"], 20.0);
    EXPECT_EQ(d["objects"]["post"]["shapes"].size(), 2u);
}

TEST(PbrtFeatures, TheSceneLoadsAndRendersFinitePixels) {
    Scene scene = load_pbrt_scene(kScene);
    EXPECT_EQ(scene.instances.size(), 4u);  // three posts and the sphere of the blend (a textured amount)
    EXPECT_EQ(scene.output_file, "features.exr");
    scene.camera.width = 16;
    scene.camera.height = 12;
    scene.sampler.spp = 2;
    const RenderResult result = render(scene, {});
    double sum = 0;
    for (const Rgb& p : result.image.pixels) {
        ASSERT_TRUE(p.is_finite());
        sum += double(p.r) + double(p.g) + double(p.b);
    }
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace candela::pbrt
