// The `hair` material's scene keys (docs/SCENE_FORMAT.md): defaults are pbrt-v4's, each key
// changes the loaded parameters, bad values are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_material;
using test::material_error;

HairParams hair(const std::string& keys) {
    Scene s = load_material(R"({"type": "hair")" + (keys.empty() ? "" : ", " + keys) + "}");
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.bsdf.lobe_count, 1u);
    EXPECT_TRUE(m.per_hit);
    EXPECT_TRUE(m.anisotropic);
    const HairParams* p = std::get_if<HairParams>(&m.params[0]);
    EXPECT_NE(p, nullptr) << keys;
    return p != nullptr ? *p : HairParams{};
}

TEST(SceneHair, DefaultsArePbrtV4s) {
    const HairParams p = hair("");
    // No absorption given: eumelanin 1.3.
    EXPECT_FALSE(p.from_reflectance);
    EXPECT_EQ(p.sigma_a.value, hair_sigma_a_from_concentration(1.3f, 0.0f));
    EXPECT_EQ(p.sigma_a.form, SpectrumForm::kUnbounded);
    EXPECT_EQ(p.eta.value, 1.55f);
    EXPECT_EQ(p.beta_m.value, 0.3f);
    EXPECT_EQ(p.beta_n.value, 0.3f);
    EXPECT_EQ(p.alpha.value, 2.0f);
}

TEST(SceneHair, KeysAreRead) {
    EXPECT_EQ(hair(R"("sigma_a": [0.1, 0.2, 3])").sigma_a.value, Rgb(0.1f, 0.2f, 3.0f));
    const HairParams r = hair(R"("reflectance": [0.6, 0.4, 0.2])");
    EXPECT_TRUE(r.from_reflectance);
    EXPECT_EQ(r.reflectance.value, Rgb(0.6f, 0.4f, 0.2f));
    EXPECT_EQ(r.reflectance.form, SpectrumForm::kAlbedo);
    EXPECT_EQ(hair(R"("eumelanin": 0.5)").sigma_a.value, hair_sigma_a_from_concentration(0.5f, 0.0f));
    // pbrt-v4: the concentration not given is 0 once the other is.
    EXPECT_EQ(hair(R"("pheomelanin": 2)").sigma_a.value, hair_sigma_a_from_concentration(0.0f, 2.0f));
    EXPECT_EQ(hair(R"("eumelanin": 0.3, "pheomelanin": 2)").sigma_a.value,
              hair_sigma_a_from_concentration(0.3f, 2.0f));
    EXPECT_EQ(hair(R"("eta": 1.4)").eta.value, 1.4f);
    EXPECT_EQ(hair(R"("beta_m": 0.7)").beta_m.value, 0.7f);
    EXPECT_EQ(hair(R"("beta_n": 0.1)").beta_n.value, 0.1f);
    EXPECT_EQ(hair(R"("scale_angle": 5)").alpha.value, 5.0f);
    // `alpha` stays the coverage every material takes.
    EXPECT_EQ(load_material(R"({"type": "hair", "alpha": 0.5})").materials.at(0).surface.alpha.value, 0.5f);
    // Textures where the other materials take them.
    EXPECT_TRUE(hair(R"("beta_m": {"type": "checkerboard", "color0": 0.1, "color1": 0.3})").beta_m.is_textured());
}

TEST(SceneHair, BadValuesAreLocatedErrors) {
    SceneError both = material_error(R"({"type": "hair", "sigma_a": 1, "reflectance": 0.5})");
    EXPECT_EQ(both.where().json_pointer, "/materials/m/reflectance");
    EXPECT_EQ(both.message(), "give one of \"sigma_a\", \"reflectance\", or \"eumelanin\"/\"pheomelanin\"");
    SceneError melanin = material_error(R"({"type": "hair", "reflectance": 0.5, "pheomelanin": 1})");
    EXPECT_EQ(melanin.where().json_pointer, "/materials/m/pheomelanin");
    EXPECT_EQ(material_error(R"({"type": "hair", "beta_m": -0.1})").message(), "expected a number in [0, 1], got -0.1");
    SceneError beta_n = material_error(R"({"type": "hair", "beta_n": 1.5})");
    EXPECT_EQ(beta_n.where().json_pointer, "/materials/m/beta_n");
    EXPECT_EQ(beta_n.message(), "expected a number in [0, 1], got 1.5");
    EXPECT_EQ(material_error(R"({"type": "hair", "eta": 0})").message(), "expected a number > 0, got 0");
    EXPECT_EQ(material_error(R"({"type": "hair", "sigma_a": -1})").message(), "expected a number >= 0, got -1");
    EXPECT_EQ(material_error(R"({"type": "hair", "reflectance": 1.2})").message(), "expected a number in [0, 1], got 1.2");
    EXPECT_EQ(material_error(R"({"type": "hair", "eumelanin": -2})").message(), "expected a number >= 0, got -2");
    EXPECT_EQ(material_error(R"({"type": "hair", "scale_angle": 100})").message(),
              "expected a number in [-90, 90], got 100");
    SceneError unknown = material_error(R"({"type": "hair", "beta": 0.3})");
    EXPECT_EQ(unknown.where().json_pointer, "/materials/m");
    EXPECT_NE(unknown.message().find("\"beta\""), std::string::npos) << unknown.message();
}

}  // namespace
}  // namespace candela
