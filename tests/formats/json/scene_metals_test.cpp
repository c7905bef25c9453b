// The scene file's `metal` names on conductors and the `multiscatter` switch on conductors and
// dielectrics (formats/json/scene_materials.cpp): each changes the loaded lobes as documented in
// docs/SCENE_FORMAT.md, and bad values are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/materials/fresnel.h"
#include "candela/scene/enum_names.h"
#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

using test::load_material;
using test::material_error;
using test::only_lobe;

// ---- metal

TEST(SceneMetals, EveryMetalNameLoadsItsTableEntry) {
    for (std::string_view name : metal_names()) {
        const auto c = only_lobe<ConductorLobe>(
            load_material(R"({"type": "conductor", "roughness": 0.1, "metal": ")" + std::string(name) + "\"}"));
        const MetalIor& ior = metal_ior(*parse_metal(name));
        EXPECT_EQ(c.eta, from_rgb(ior.eta)) << name;
        EXPECT_EQ(c.k, from_rgb(ior.k)) << name;
        EXPECT_EQ(c.distribution.alpha_x, 0.1f) << name;
    }
}

TEST(SceneMetals, MetalsReflectTheDocumentedColours) {
    // docs/SCENE_FORMAT.md lists each metal's reflectance at normal incidence; two of them here
    // (tests/materials/metal_table_test.cpp checks all of them against the table).
    const auto gold = only_lobe<ConductorLobe>(load_material(R"({"type": "conductor", "metal": "Au"})"));
    EXPECT_TRUE(gold.is_delta());  // no roughness: the smooth metal
    const Color f_gold = fresnel_complex(1.0f, gold.eta, gold.k);
    EXPECT_NEAR(f_gold[0], 0.997f, 5e-4f);
    EXPECT_NEAR(f_gold[1], 0.783f, 5e-4f);
    EXPECT_NEAR(f_gold[2], 0.343f, 5e-4f);
    const auto iron = only_lobe<ConductorLobe>(load_material(R"({"type": "conductor", "metal": "Fe"})"));
    const Color f_iron = fresnel_complex(1.0f, iron.eta, iron.k);
    EXPECT_NEAR(f_iron[0], 0.530f, 5e-4f);
    EXPECT_NEAR(f_iron[1], 0.513f, 5e-4f);
    EXPECT_NEAR(f_iron[2], 0.494f, 5e-4f);
}

TEST(SceneMetals, UnknownMetalListsTheKnownOnes) {
    SceneError e = material_error(R"({"type": "conductor", "metal": "gold"})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/metal");
    EXPECT_EQ(e.message(), "unknown metal \"gold\"; expected one of: Ag, Al, Au, Cr, Cu, CuZn, Fe, Ti");
    EXPECT_EQ(material_error(R"({"type": "conductor", "metal": 79})").message(),
              "expected a metal (one of: Ag, Al, Au, Cr, Cu, CuZn, Fe, Ti), got 79");
}

TEST(SceneMetals, MetalExcludesEtaKAndReflectance) {
    for (const char* other : {R"("eta": 1, "k": 1)", R"("k": 1)", R"("reflectance": 0.5)"}) {
        SceneError e = material_error(std::string(R"({"type": "conductor", "metal": "Cu", )") + other + "}");
        EXPECT_EQ(e.message(), "give one of \"metal\", \"eta\" and \"k\", or \"reflectance\"") << other;
        EXPECT_NE(e.where().json_pointer, "/materials/m/metal") << other;  // at the other key
    }
}

// ---- multiscatter

TEST(SceneMultiscatter, OffByDefaultOnWhenAsked) {
    for (const char* conductor : {R"("metal": "Au")", R"("eta": 0.2, "k": 3)", R"("reflectance": 0.9)"}) {
        const std::string base = std::string(R"({"type": "conductor", "roughness": 0.4, )") + conductor;
        const auto off = only_lobe<ConductorLobe>(load_material(base + "}"));
        EXPECT_FALSE(off.multiscatter) << conductor;
        const auto off_too = only_lobe<ConductorLobe>(load_material(base + R"(, "multiscatter": false})"));
        EXPECT_FALSE(off_too.multiscatter) << conductor;
        const auto on = only_lobe<ConductorLobe>(load_material(base + R"(, "multiscatter": true})"));
        EXPECT_TRUE(on.multiscatter) << conductor;
        EXPECT_GT(on.fresnel_avg[1], 0.0f) << conductor;
    }
    const auto glass = only_lobe<DielectricLobe>(
        load_material(R"({"type": "dielectric", "roughness": 0.3, "multiscatter": true})"));
    EXPECT_TRUE(glass.multiscatter);
    EXPECT_FALSE(only_lobe<DielectricLobe>(load_material(R"({"type": "dielectric", "roughness": 0.3})")).multiscatter);
}

TEST(SceneMultiscatter, ChangesNothingOnSmoothSurfaces) {
    // Smooth glass keeps version 1's lobe; a smooth metal is a mirror, which loses nothing.
    only_lobe<FresnelSpecularLobe>(load_material(R"({"type": "dielectric", "multiscatter": true})"));
    const auto silver =
        only_lobe<ConductorLobe>(load_material(R"({"type": "conductor", "metal": "Ag", "multiscatter": true})"));
    EXPECT_FALSE(silver.multiscatter);
}

TEST(SceneMultiscatter, TexturedMaterialsBuildCompensatedLobesAtEachHit) {
    const Scene s = load_material(R"({"type": "conductor", "metal": "Cu", "multiscatter": true,
        "roughness": {"type": "checkerboard", "color0": 0.1, "color1": 0.7}})");
    ASSERT_TRUE(s.materials[0].textured);
    const Bsdf bsdf = build_bsdf(s.materials[0], s.textures, TextureContext{Vec2f(1.1f, 0.1f), Vec3f(0.0f)});
    const auto& c = std::get<ConductorLobe>(bsdf.lobes[0]);
    EXPECT_EQ(c.distribution.alpha_x, 0.7f);
    EXPECT_TRUE(c.multiscatter);
}

TEST(SceneMultiscatter, TakesOnlyABoolean) {
    SceneError e = material_error(R"({"type": "conductor", "metal": "Au", "multiscatter": 1})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/multiscatter");
    EXPECT_EQ(e.message(), "expected true or false, got 1");
    // Only conductors and dielectrics take it (the list of keys a diffuse takes is not ours to pin).
    const std::string diffuse = material_error(R"({"type": "diffuse", "multiscatter": true})").message();
    EXPECT_EQ(diffuse.rfind("unknown key \"multiscatter\"; expected one of: albedo, ", 0), 0u) << diffuse;
}

}  // namespace
}  // namespace candela
