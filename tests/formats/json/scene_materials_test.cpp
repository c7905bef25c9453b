// The scene file's microfacet materials (formats/json/scene_materials.cpp): `conductor` (eta and k, or
// reflectance), `roughness` (one alpha or [alpha_u, alpha_v], textures allowed) on conductors
// and dielectrics, `thin_dielectric`. Every key changes the loaded scene; bad values and
// conflicting keys are located errors; a dielectric without roughness stays the smooth lobe of
// version 1.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

using test::load_material;
using test::material_error;
using test::only_lobe;

TextureContext at(float u, float v) { return TextureContext{Vec2f(u, v), Vec3f(0.0f)}; }

// ---- diffuse_transmission

TEST(SceneMaterials, DiffuseTransmissionReadsReflectanceTransmittanceAndScale) {
    // pbrt-v4's defaults: 0.25 each.
    const auto d = only_lobe<DiffuseTransmissionLobe>(load_material(R"({"type": "diffuse_transmission"})"));
    EXPECT_EQ(d.reflectance, Color(0.25f));
    EXPECT_EQ(d.transmittance, Color(0.25f));
    const auto a = only_lobe<DiffuseTransmissionLobe>(load_material(
        R"({"type": "diffuse_transmission", "reflectance": [0.2, 0.4, 0.6], "transmittance": 0.3})"));
    EXPECT_EQ(a.reflectance, Color(0.2f, 0.4f, 0.6f));
    EXPECT_EQ(a.transmittance, Color(0.3f));
    // `scale` multiplies both, and each is clamped to 1 after (pbrt-v4's GetBxDF).
    const auto s = only_lobe<DiffuseTransmissionLobe>(load_material(
        R"({"type": "diffuse_transmission", "reflectance": [0.2, 0.4, 0.6], "transmittance": 0.3, "scale": 2})"));
    EXPECT_EQ(s.reflectance, Color(0.4f, 0.8f, 1.0f));
    EXPECT_EQ(s.transmittance, Color(0.6f));
    EXPECT_NE(material_error(R"({"type": "diffuse_transmission", "transmittance": 1.5})").message().find(
                  "expected"),
              std::string::npos);
    EXPECT_NE(material_error(R"({"type": "diffuse_transmission", "scale": -1})").message().find(">= 0"),
              std::string::npos);
}

// ---- conductor

TEST(SceneMaterials, ConductorEtaKAndRoughnessAreRead) {
    const auto a = only_lobe<ConductorLobe>(load_material(
        R"({"type": "conductor", "eta": [0.2, 0.4, 1.4], "k": [4, 2.4, 1.6], "roughness": 0.2})"));
    EXPECT_EQ(a.eta, Color(0.2f, 0.4f, 1.4f));
    EXPECT_EQ(a.k, Color(4.0f, 2.4f, 1.6f));
    EXPECT_EQ(a.distribution.alpha_x, 0.2f);
    EXPECT_EQ(a.distribution.alpha_y, 0.2f);
    // Without roughness: the smooth (delta) mirror with the complex Fresnel term.
    const auto b = only_lobe<ConductorLobe>(load_material(R"({"type": "conductor", "eta": 1.5, "k": 3})"));
    EXPECT_EQ(b.eta, Color(1.5f));
    EXPECT_EQ(b.k, Color(3.0f));
    EXPECT_TRUE(b.is_delta());
}

TEST(SceneMaterials, RoughnessPairIsAlphaAlongUThenV) {
    const auto c = only_lobe<ConductorLobe>(
        load_material(R"({"type": "conductor", "eta": 1, "k": 1, "roughness": [0.05, 0.4]})"));
    EXPECT_EQ(c.distribution.alpha_x, 0.05f);
    EXPECT_EQ(c.distribution.alpha_y, 0.4f);
    EXPECT_EQ(material_error(R"({"type": "conductor", "eta": 1, "k": 1, "roughness": [0.1]})").message(),
              "expected a roughness: a number or [alpha_u, alpha_v], got [0.1]");
    SceneError negative = material_error(R"({"type": "conductor", "eta": 1, "k": 1, "roughness": [0.1, -1]})");
    EXPECT_EQ(negative.where().json_pointer, "/materials/m/roughness/1");
    EXPECT_EQ(negative.message(), "expected a number >= 0, got -1");
}

TEST(SceneMaterials, OnlyARoughnessPairThatDiffersMakesTheMaterialAnisotropic) {
    // An anisotropic lobe needs the frame's x axis along dpdu (integrators/shading_frame.h).
    const char* conductor = R"({"type": "conductor", "eta": 1, "k": 1, "roughness": )";
    EXPECT_TRUE(load_material(std::string(conductor) + "[0.05, 0.4]}").materials[0].anisotropic);
    EXPECT_FALSE(load_material(std::string(conductor) + "[0.2, 0.2]}").materials[0].anisotropic);
    EXPECT_FALSE(load_material(std::string(conductor) + "0.2}").materials[0].anisotropic);
    EXPECT_FALSE(load_material(std::string(conductor) +
                               R"({"type": "checkerboard", "color0": 0.1, "color1": 0.3}})")
                     .materials[0].anisotropic);
    EXPECT_TRUE(load_material(std::string(conductor) +
                              R"([{"type": "checkerboard", "color0": 0.1, "color1": 0.3}, 0.1]})")
                    .materials[0].anisotropic);
    EXPECT_TRUE(load_material(R"({"type": "dielectric", "roughness": [0.1, 0.3]})").materials[0].anisotropic);
    EXPECT_TRUE(load_material(R"({"type": "conductor", "reflectance": 1, "roughness": [0.1, 0.3]})")
                    .materials[0].anisotropic);
    EXPECT_TRUE(load_material(R"({"type": "conductor", "reflectance": 1, "roughness": [0.1, 0.3]})")
                    .materials[0].needs_shading_geometry);
}

TEST(SceneMaterials, ConductorReflectanceIsPbrtsArtistFriendlyForm) {
    // eta = 1 and k = 2 sqrt(r) / sqrt(1 - r): the lobe reflects r at normal incidence.
    const auto c = only_lobe<ConductorLobe>(
        load_material(R"({"type": "conductor", "reflectance": [0.9, 0.5, 0.0], "roughness": 0.3})"));
    EXPECT_EQ(c.eta, Color(1.0f));
    Color f0 = fresnel_complex(1.0f, c.eta, c.k);
    EXPECT_NEAR(f0[0], 0.9f, 1e-5f);
    EXPECT_NEAR(f0[1], 0.5f, 1e-5f);
    EXPECT_EQ(f0[2], 0.0f);
    // A reflectance of 1 is clamped to 0.9999 (pbrt-v4), so that k stays finite.
    const auto one = only_lobe<ConductorLobe>(load_material(R"({"type": "conductor", "reflectance": 1})"));
    EXPECT_TRUE(std::isfinite(one.k[0]));
    EXPECT_NEAR(fresnel_complex(1.0f, one.eta, one.k)[0], 0.9999f, 1e-5f);
    EXPECT_EQ(material_error(R"({"type": "conductor", "reflectance": 1.2})").message(),
              "expected a number in [0, 1], got 1.2");
}

TEST(SceneMaterials, ConductorNeedsEtaAndKOrReflectance) {
    SceneError both = material_error(R"({"type": "conductor", "eta": 1, "k": 1, "reflectance": 0.5})");
    EXPECT_EQ(both.where().json_pointer, "/materials/m/eta");
    EXPECT_EQ(both.message(), "give \"eta\" and \"k\" or \"reflectance\", not both");
    SceneError only_eta = material_error(R"({"type": "conductor", "eta": 1})");
    EXPECT_EQ(only_eta.where().json_pointer, "/materials/m");
    EXPECT_EQ(only_eta.message(), "a conductor needs \"eta\" and \"k\", \"reflectance\" or \"metal\"");
    EXPECT_EQ(material_error(R"({"type": "conductor", "eta": 1, "k": -1})").message(),
              "expected a number >= 0, got -1");
    EXPECT_EQ(material_error(R"({"type": "conductor", "eta": 1, "k": 1, "ior": 1.5})").message(),
              "unknown key \"ior\"; expected one of: alpha, bump_map, eta, k, metal, multiscatter, normal_map, normal_map_convention, reflectance, roughness, type");
}

TEST(SceneMaterials, ConductorParametersMayBeTextures) {
    const Scene s = load_material(R"({"type": "conductor",
        "eta": {"type": "checkerboard", "color0": 0.5, "color1": 2},
        "k": 3, "roughness": [{"type": "checkerboard", "color0": 0.1, "color1": 0.7}, 0.2]})");
    ASSERT_TRUE(s.materials[0].textured);
    const Bsdf even = build_bsdf(s.materials[0], s.textures, at(0.1f, 0.1f));
    const Bsdf odd = build_bsdf(s.materials[0], s.textures, at(1.1f, 0.1f));
    const auto& e = std::get<ConductorLobe>(even.lobes[0]);
    const auto& o = std::get<ConductorLobe>(odd.lobes[0]);
    EXPECT_EQ(e.eta, Color(0.5f));
    EXPECT_EQ(o.eta, Color(2.0f));
    EXPECT_EQ(e.distribution.alpha_x, 0.1f);
    EXPECT_EQ(o.distribution.alpha_x, 0.7f);
    EXPECT_EQ(o.distribution.alpha_y, 0.2f);
}

// ---- dielectric roughness

TEST(SceneMaterials, DielectricRoughnessMakesItMicrofacetGlass) {
    const auto g = only_lobe<DielectricLobe>(
        load_material(R"({"type": "dielectric", "ior": 1.33, "tint": 0.5, "roughness": 0.15})"));
    EXPECT_EQ(g.eta, 1.33f);
    EXPECT_EQ(g.tint, Color(0.5f));
    EXPECT_EQ(g.distribution.alpha_x, 0.15f);
    EXPECT_EQ(g.distribution.alpha_y, 0.15f);
    const auto a = only_lobe<DielectricLobe>(
        load_material(R"({"type": "dielectric", "roughness": [0.05, 0.4], "fresnel": "exact"})"));
    EXPECT_EQ(a.eta, 1.5f);
    EXPECT_EQ(a.distribution.alpha_y, 0.4f);
}

TEST(SceneMaterials, DielectricOfRoughnessZeroIsTheSmoothLobeOfVersionOne) {
    // Absent, 0 or [0, 0]: FresnelSpecularLobe, so that version 1 scenes render bit for bit.
    for (const char* roughness : {"", R"(, "roughness": 0)", R"(, "roughness": [0, 0])"}) {
        const auto g = only_lobe<FresnelSpecularLobe>(
            load_material(std::string(R"({"type": "dielectric", "ior": 1.4)") + roughness + "}"));
        EXPECT_EQ(g.eta, 1.4f) << roughness;
    }
    EXPECT_EQ(material_error(R"({"type": "dielectric", "roughness": 0.1, "fresnel": "schlick"})").message(),
              "fresnel \"schlick\" is for a smooth dielectric (roughness 0)");
    EXPECT_EQ(material_error(R"({"type": "dielectric", "roughness": "rough"})").message(),
              "expected a number >= 0, got \"rough\"");
}

// ---- thin dielectric

TEST(SceneMaterials, ThinDielectricIorIsRead) {
    EXPECT_EQ(only_lobe<ThinDielectricLobe>(load_material(R"({"type": "thin_dielectric", "ior": 1.33})")).eta,
              1.33f);
    EXPECT_EQ(only_lobe<ThinDielectricLobe>(load_material(R"({"type": "thin_dielectric"})")).eta, 1.5f);
    EXPECT_EQ(material_error(R"({"type": "thin_dielectric", "ior": 0})").message(),
              "expected a number > 0, got 0");
    EXPECT_EQ(material_error(R"({"type": "thin_dielectric", "tint": 0.5})").message(),
              "unknown key \"tint\"; expected one of: alpha, bump_map, ior, normal_map, normal_map_convention, type");
}

TEST(SceneMaterials, NewTypesMixWithTheOthers) {
    const Scene s = load_material(R"({"type": "mix", "lobes": [
        {"type": "conductor", "reflectance": 0.5, "roughness": 0.2},
        {"type": "thin_dielectric"}, {"type": "dielectric", "roughness": 0.3}]})");
    const Bsdf& bsdf = s.materials[0].bsdf;
    ASSERT_EQ(bsdf.lobe_count, 3u);
    EXPECT_TRUE(std::holds_alternative<ConductorLobe>(bsdf.lobes[0]));
    EXPECT_TRUE(std::holds_alternative<ThinDielectricLobe>(bsdf.lobes[1]));
    EXPECT_TRUE(std::holds_alternative<DielectricLobe>(bsdf.lobes[2]));
}

}  // namespace
}  // namespace candela
