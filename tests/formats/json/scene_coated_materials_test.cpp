// The coated materials' scene keys (docs/SCENE_FORMAT.md): each, set to a value other than its
// default, changes the loaded lobe; defaults are pbrt-v4's; bad values are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// The one lobe of the one material of a scene whose `materials` section is {"m": <material>}.
template <class T>
T lobe_of(const std::string& material) {
    Scene s = load_json(R"({"materials": {"m": )" + material + "}}");
    const Bsdf& bsdf = s.materials.at(0).bsdf;
    EXPECT_EQ(bsdf.lobe_count, 1u);
    const T* lobe = std::get_if<T>(&bsdf.lobes[0]);
    EXPECT_NE(lobe, nullptr) << material;
    return lobe != nullptr ? *lobe : T{};
}

CoatedDiffuseLobe coated_diffuse(const std::string& keys) {
    return lobe_of<CoatedDiffuseLobe>(R"({"type": "coated_diffuse")" + (keys.empty() ? "" : ", " + keys) + "}");
}
CoatedConductorLobe coated_conductor(const std::string& keys) {
    return lobe_of<CoatedConductorLobe>(R"({"type": "coated_conductor")" + (keys.empty() ? "" : ", " + keys) + "}");
}

TEST(SceneCoatedMaterials, CoatedDiffuseDefaultsArePbrts) {
    CoatedDiffuseLobe d = coated_diffuse("");
    EXPECT_EQ(d.base.reflectance, Color(0.5f));
    EXPECT_EQ(d.coat.eta, 1.5f);
    EXPECT_TRUE(d.coat.distribution.effectively_smooth());
    EXPECT_EQ(d.thickness, 0.01f);
    EXPECT_EQ(d.medium_albedo, Color(0.0f));
    EXPECT_EQ(d.g, 0.0f);
    EXPECT_EQ(d.max_depth, 10);
    EXPECT_EQ(d.n_samples, 1);
}

TEST(SceneCoatedMaterials, CoatedDiffuseKeysAreRead) {
    EXPECT_EQ(coated_diffuse(R"("albedo": [0.7, 0.2, 0.1])").base.reflectance, Color(0.7f, 0.2f, 0.1f));
    CoatedDiffuseLobe iso = coated_diffuse(R"("roughness": 0.05)");
    EXPECT_EQ(iso.coat.distribution.alpha_x, 0.05f);
    EXPECT_EQ(iso.coat.distribution.alpha_y, 0.05f);
    CoatedDiffuseLobe aniso = coated_diffuse(R"("roughness": [0.1, 0.3])");
    EXPECT_EQ(aniso.coat.distribution.alpha_x, 0.1f);
    EXPECT_EQ(aniso.coat.distribution.alpha_y, 0.3f);
    EXPECT_EQ(coated_diffuse(R"("ior": 1.33)").coat.eta, 1.33f);
    EXPECT_EQ(coated_diffuse(R"("thickness": 0.2)").thickness, 0.2f);
    EXPECT_EQ(coated_diffuse(R"("medium_albedo": [0.9, 0.5, 0.1])").medium_albedo, Color(0.9f, 0.5f, 0.1f));
    EXPECT_EQ(coated_diffuse(R"("g": -0.3)").g, -0.3f);
    EXPECT_EQ(coated_diffuse(R"("maxdepth": 3)").max_depth, 3);
    EXPECT_EQ(coated_diffuse(R"("nsamples": 4)").n_samples, 4);
}

TEST(SceneCoatedMaterials, DesignDocExampleLoads) {
    // DESIGN.md's "plastic".
    CoatedDiffuseLobe d = coated_diffuse(R"("albedo": [0.7, 0.2, 0.2], "roughness": 0.05, "ior": 1.5, "thickness": 0.01)");
    EXPECT_EQ(d.base.reflectance, Color(0.7f, 0.2f, 0.2f));
    EXPECT_EQ(d.coat.distribution.alpha_x, 0.05f);
}

TEST(SceneCoatedMaterials, CoatedConductorDefaultsArePbrts) {
    CoatedConductorLobe c = coated_conductor("");
    EXPECT_EQ(c.coat.eta, 1.5f);
    EXPECT_TRUE(c.coat.distribution.effectively_smooth());
    EXPECT_TRUE(c.base.distribution.effectively_smooth());
    // Copper, relative to the coat.
    EXPECT_EQ(c.base.eta, Color(0.216561f, 0.958162f, 1.165808f) / 1.5f);
    EXPECT_EQ(c.base.k, Color(3.637741f, 2.577065f, 2.393857f) / 1.5f);
    EXPECT_EQ(c.thickness, 0.01f);
    EXPECT_EQ(c.medium_albedo, Color(0.0f));
    EXPECT_EQ(c.max_depth, 10);
    EXPECT_EQ(c.n_samples, 1);
}

TEST(SceneCoatedMaterials, CoatedConductorKeysAreRead) {
    CoatedConductorLobe rough = coated_conductor(R"("interface_roughness": [0.1, 0.2], "conductor_roughness": 0.3)");
    EXPECT_EQ(rough.coat.distribution.alpha_x, 0.1f);
    EXPECT_EQ(rough.coat.distribution.alpha_y, 0.2f);
    EXPECT_EQ(rough.base.distribution.alpha_x, 0.3f);
    EXPECT_EQ(rough.base.distribution.alpha_y, 0.3f);
    CoatedConductorLobe gold = coated_conductor(R"("ior": 1.25, "conductor_eta": [0.2, 0.4, 1.5], "conductor_k": [4, 2.5, 2])");
    EXPECT_EQ(gold.coat.eta, 1.25f);
    EXPECT_EQ(gold.base.eta, Color(0.2f, 0.4f, 1.5f) / 1.25f);
    EXPECT_EQ(gold.base.k, Color(4.0f, 2.5f, 2.0f) / 1.25f);
    // Only eta given: k stays copper's (pbrt-v4 defaults each separately).
    EXPECT_EQ(coated_conductor(R"("conductor_eta": 1)").base.k, Color(3.637741f, 2.577065f, 2.393857f) / 1.5f);
    CoatedConductorLobe artist = coated_conductor(R"("reflectance": [0.64, 0.64, 0.64])");
    EXPECT_EQ(artist.base.eta, Color(1.0f / 1.5f));
    EXPECT_NEAR(artist.base.k[0], 2.0f * 0.8f / 0.6f / 1.5f, 1e-5f);
    CoatedConductorLobe medium = coated_conductor(R"("thickness": 0.5, "medium_albedo": 0.8, "g": 0.5, "maxdepth": 20, "nsamples": 2)");
    EXPECT_EQ(medium.thickness, 0.5f);
    EXPECT_EQ(medium.medium_albedo, Color(0.8f));
    EXPECT_EQ(medium.g, 0.5f);
    EXPECT_EQ(medium.max_depth, 20);
    EXPECT_EQ(medium.n_samples, 2);
}

TEST(SceneCoatedMaterials, BadValuesAreLocatedErrors) {
    auto error_of = [](const std::string& material) {
        return load_error(R"({"materials": {"m": )" + material + "}}");
    };
    SceneError both = error_of(R"({"type": "coated_conductor", "conductor_eta": 1, "reflectance": 0.5})");
    EXPECT_EQ(both.where().json_pointer, "/materials/m/conductor_eta");
    EXPECT_EQ(both.message(), "give \"conductor_eta\" and \"conductor_k\" or \"reflectance\", not both");
    EXPECT_EQ(error_of(R"({"type": "coated_diffuse", "g": 1.5})").message(), "expected a number in [-1, 1], got 1.5");
    EXPECT_EQ(error_of(R"({"type": "coated_diffuse", "nsamples": 0})").message(),
              "expected an integer in [1, 65535], got 0");
    EXPECT_EQ(error_of(R"({"type": "coated_diffuse", "maxdepth": -1})").message(),
              "expected an integer in [0, 65535], got -1");
    EXPECT_EQ(error_of(R"({"type": "coated_diffuse", "thickness": -0.1})").message(),
              "expected a number >= 0, got -0.1");
    EXPECT_EQ(error_of(R"({"type": "coated_diffuse", "medium_albedo": 2})").message(),
              "expected a number in [0, 1], got 2");
    SceneError pair = error_of(R"({"type": "coated_diffuse", "roughness": [0.1, 0.2, 0.3]})");
    EXPECT_EQ(pair.where().json_pointer, "/materials/m/roughness");
    EXPECT_EQ(pair.message(), "expected a roughness: a number or [alpha_u, alpha_v], got [0.1, 0.2, 0.3]");
    // The conductor's coat roughness is interface_roughness: `roughness` is a near miss there.
    SceneError near = error_of(R"({"type": "coated_conductor", "roughness": 0.1})");
    EXPECT_EQ(near.where().json_pointer, "/materials/m");
    EXPECT_NE(near.message().find("unknown key \"roughness\""), std::string::npos) << near.message();
}

TEST(SceneCoatedMaterials, ParametersMayBeTextures) {
    // A checkerboard of 0.25 and 1 over uv: the base's albedo, the coat's roughness and the
    // conductor's reflectance follow it (each clamped to its range).
    Scene s = load_json(R"({"textures": {"c": {"type": "checkerboard", "color0": 0.25, "color1": 1}},
        "materials": {"d": {"type": "coated_diffuse", "albedo": {"texture": "c"}, "roughness": {"texture": "c"}},
                      "k": {"type": "coated_conductor", "reflectance": {"texture": "c"}}}})");
    ASSERT_TRUE(s.materials.at(0).textured);
    ASSERT_TRUE(s.materials.at(1).textured);
    auto at = [](float u, float v) { return TextureContext{Vec2f(u, v), Vec3f(0.0f)}; };
    auto diffuse_at = [&](float u) { return std::get<CoatedDiffuseLobe>(build_bsdf(s.materials[0], s.textures, at(u, 0.5f)).lobes[0]); };
    EXPECT_EQ(diffuse_at(0.5f).base.reflectance, Color(0.25f));
    EXPECT_EQ(diffuse_at(0.5f).coat.distribution.alpha_x, 0.25f);
    EXPECT_EQ(diffuse_at(1.5f).base.reflectance, Color(1.0f));
    EXPECT_EQ(diffuse_at(1.5f).coat.distribution.alpha_y, 1.0f);
    auto conductor_at = [&](float u) { return std::get<CoatedConductorLobe>(build_bsdf(s.materials[1], s.textures, at(u, 0.5f)).lobes[0]); };
    EXPECT_LT(conductor_at(0.5f).base.k.max_component(), conductor_at(1.5f).base.k.max_component());
}

TEST(SceneCoatedMaterials, MixMayHoldACoat) {
    Scene s = load_json(R"({"materials": {"m": {"type": "mix", "lobes": [
        {"type": "coated_diffuse", "albedo": 0.3}, {"type": "coated_conductor", "reflectance": 0.9}]}}})");
    const Bsdf& bsdf = s.materials.at(0).bsdf;
    ASSERT_EQ(bsdf.lobe_count, 2u);
    EXPECT_TRUE(std::holds_alternative<CoatedDiffuseLobe>(bsdf.lobes[0]));
    EXPECT_TRUE(std::holds_alternative<CoatedConductorLobe>(bsdf.lobes[1]));
}

}  // namespace
}  // namespace candela
