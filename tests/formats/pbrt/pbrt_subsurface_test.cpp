// pbrt-v4's `subsurface` material (SubsurfaceMaterial::Create in src/pbrt/materials.cpp) as
// candela's: each of its four ways to give the interior, its scale, eta, g and roughness, and
// pbrt-v4's errors as located ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

const std::filesystem::path kFile = std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "inline.pbrt";
const char* kLight = "AttributeBegin AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                     "Shape \"sphere\" \"float radius\" 0.1 AttributeEnd\n";

ImportedScene import(const std::string& material) {
    return import_pbrt_string("Integrator \"volpath\"\nWorldBegin\n" + material + "\nShape \"sphere\"\n" + kLight,
                              kFile);
}

// The document's subsurface material (the importer may place the spheres as instances).
nlohmann::ordered_json material_of(const ImportedScene& s) {
    for (const auto& [name, m] : s.document["materials"].items())
        if (m["type"] == "subsurface") return m;
    ADD_FAILURE() << "no subsurface material";
    return {};
}

std::string error_of(const std::string& material) {
    try {
        load_imported_scene(import(material), kFile);
    } catch (const SceneError& e) {
        return e.formatted();
    }
    return "no error";
}

TEST(PbrtSubsurface, DefaultsArePbrtV4s) {
    const ImportedScene s = import("Material \"subsurface\"");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const auto m = material_of(s);
    EXPECT_EQ(m["type"], "subsurface");
    EXPECT_EQ(m["ior"], 1.33);
    EXPECT_FALSE(m.contains("roughness"));
    const Scene scene = load_imported_scene(s, kFile);
    ASSERT_EQ(scene.subsurfaces.size(), 1u);
    EXPECT_EQ(scene.subsurfaces[0].sigma_s.value, Rgb(2.55f, 3.21f, 3.77f));
    EXPECT_EQ(scene.subsurfaces[0].method, SubsurfaceMethod::kTabulated);
}

TEST(PbrtSubsurface, EachWayToGiveTheInterior) {
    const auto named = material_of(import("Material \"subsurface\" \"string name\" \"Ketchup\" \"float scale\" 20"));
    EXPECT_EQ(named["name"], "Ketchup");
    EXPECT_EQ(named["scale"], 20.0);
    const auto coefficients =
        material_of(import("Material \"subsurface\" \"rgb sigma_a\" [0.1 0.2 0.3] \"rgb sigma_s\" [1 2 3] \"float g\" 0.4"));
    EXPECT_EQ(coefficients["sigma_a"], nlohmann::ordered_json::array({0.1, 0.2, 0.3}));
    EXPECT_EQ(coefficients["sigma_s"], nlohmann::ordered_json::array({1.0, 2.0, 3.0}));
    EXPECT_EQ(coefficients["g"], 0.4);
    const auto reflectance = material_of(import("Material \"subsurface\" \"rgb reflectance\" [0.8 0.6 0.4] "
                                                 "\"rgb mfp\" [0.5 0.25 0.125] \"float eta\" 1.5"));
    EXPECT_EQ(reflectance["reflectance"], nlohmann::ordered_json::array({0.8, 0.6, 0.4}));
    EXPECT_EQ(reflectance["mfp"], nlohmann::ordered_json::array({0.5, 0.25, 0.125}));
    EXPECT_EQ(reflectance["ior"], 1.5);
}

TEST(PbrtSubsurface, RoughnessIsRemappedAsPbrtV4Does) {
    EXPECT_EQ(material_of(import("Material \"subsurface\" \"float roughness\" 0.04"))["roughness"], 0.2);
    EXPECT_EQ(material_of(import("Material \"subsurface\" \"bool remaproughness\" false \"float uroughness\" 0.1 "
                                 "\"float vroughness\" 0.2"))["roughness"],
              nlohmann::ordered_json::array({0.1, 0.2}));
}

TEST(PbrtSubsurface, GWithANamedMediumWarnsAndIsZero) {
    const ImportedScene s = import("Material \"subsurface\" \"string name\" \"Skin1\" \"float g\" 0.5");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("non-zero \"g\" ignored with named scattering coefficients"), std::string::npos)
        << s.warnings[0];
    EXPECT_FALSE(material_of(s).contains("g"));
    EXPECT_EQ(load_imported_scene(s, kFile).subsurfaces[0].g, 0.0f);
}

TEST(PbrtSubsurface, ErrorsAreLocated) {
    EXPECT_NE(error_of("Material \"subsurface\" \"rgb sigma_a\" [1 1 1]")
                  .find("inline.pbrt:3:23: subsurface: provided \"sigma_a\" parameter without \"sigma_s\""),
              std::string::npos)
        << error_of("Material \"subsurface\" \"rgb sigma_a\" [1 1 1]");
    const std::string unknown = error_of("Material \"subsurface\" \"string name\" \"Milk\"");
    EXPECT_NE(unknown.find("inline.pbrt:3:"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("unknown measured medium \"Milk\""), std::string::npos) << unknown;
    const std::string zero_mfp = error_of("Material \"subsurface\" \"rgb reflectance\" [0.5 0.5 0.5] \"rgb mfp\" [1 0 1]");
    EXPECT_NE(zero_mfp.find("inline.pbrt:3:"), std::string::npos) << zero_mfp;
    EXPECT_NE(zero_mfp.find("expected a number > 0, got 0"), std::string::npos) << zero_mfp;
    const std::string negative = error_of("Material \"subsurface\" \"rgb sigma_a\" [1 -1 1] \"rgb sigma_s\" [1 1 1]");
    EXPECT_NE(negative.find("expected a number >= 0, got -1"), std::string::npos) << negative;
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela::pbrt
