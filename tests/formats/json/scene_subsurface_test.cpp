// The `subsurface` material: each way pbrt-v4 gives its interior, its keys, the random walk's
// medium on its shapes, and bad values as located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene whose one material "m" is `material`, on a sphere (and its warnings).
Scene with_material(const std::string& material, const std::string& shape_keys = "",
                    const std::string& integrator = "volpath") {
    return load_json(R"({"integrator": {"type": ")" + integrator + R"("}, "materials": {"m": )" + material +
                     R"(}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m")" +
                     shape_keys + "}], \"lights\": [{\"type\": \"environment\", \"color\": 1}]}");
}

const Subsurface& only_subsurface(const Scene& s) {
    EXPECT_EQ(s.subsurfaces.size(), 1u);
    EXPECT_EQ(s.materials[0].subsurface, 0u);
    return s.subsurfaces[0];
}

TEST(SceneLoaderSubsurface, DefaultsArePbrtV4s) {
    const Scene s = with_material(R"({"type": "subsurface"})");
    const Subsurface& ss = only_subsurface(s);
    EXPECT_EQ(ss.method, SubsurfaceMethod::kTabulated);
    EXPECT_FALSE(ss.from_reflectance);
    EXPECT_EQ(ss.sigma_a.value, Rgb(0.0011f, 0.0024f, 0.014f));
    EXPECT_EQ(ss.sigma_s.value, Rgb(2.55f, 3.21f, 3.77f));
    EXPECT_EQ(ss.eta, 1.33f);
    EXPECT_EQ(ss.g, 0.0f);
    EXPECT_EQ(ss.scale, 1.0f);
    // pbrt-v4's table: 100 albedos by 64 radii.
    EXPECT_EQ(ss.table.rho_samples.size(), 100u);
    EXPECT_EQ(ss.table.radius_samples.size(), 64u);
    // The boundary is smooth glass of the same index; no medium is made for the tabulated method.
    ASSERT_EQ(s.materials[0].bsdf.lobe_count, 1u);
    const auto* lobe = std::get_if<DielectricParams>(&s.materials[0].params[0]);
    ASSERT_NE(lobe, nullptr);
    EXPECT_EQ(lobe->ior, 1.33f);
    EXPECT_TRUE(s.media.empty());
    EXPECT_EQ(s.shapes[0].interior, kNoMedium);
}

TEST(SceneLoaderSubsurface, KeysChangeTheMaterial) {
    const Scene s = with_material(
        R"({"type": "subsurface", "sigma_a": [0.1, 0.2, 0.3], "sigma_s": 2, "scale": 10, "ior": 1.5, "g": 0.3,
            "roughness": [0.1, 0.2]})");
    const Subsurface& ss = only_subsurface(s);
    EXPECT_EQ(ss.sigma_a.value, Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(ss.sigma_s.value, Rgb(2.0f));
    EXPECT_EQ(ss.scale, 10.0f);
    EXPECT_EQ(ss.eta, 1.5f);
    EXPECT_EQ(ss.g, 0.3f);
    const auto* lobe = std::get_if<RoughDielectricParams>(&s.materials[0].params[0]);
    ASSERT_NE(lobe, nullptr);
    EXPECT_EQ(lobe->ior, 1.5f);
    EXPECT_EQ(lobe->roughness.alpha_u.value, 0.1f);
    EXPECT_EQ(lobe->roughness.alpha_v.value, 0.2f);
    // The coefficients at a point: scale applied.
    Color sa, ss_;
    ss.coefficients(s.textures, TextureContext{}, sa, ss_);
    EXPECT_NEAR(sa[2], 3.0f, 1e-6f);
    EXPECT_NEAR(ss_[0], 20.0f, 1e-6f);
}

TEST(SceneLoaderSubsurface, NamedMediumIsTheMediaPresetsTable) {
    const Scene s = with_material(R"({"type": "subsurface", "name": "Skin1", "scale": 2})");
    const Subsurface& ss = only_subsurface(s);
    // Jensen et al. 2001 via pbrt-v4: Skin1 sigma_s' (0.74, 0.88, 1.01), sigma_a (0.032, 0.17, 0.48), per mm.
    EXPECT_EQ(ss.sigma_s.value, Rgb(0.74f, 0.88f, 1.01f));
    EXPECT_EQ(ss.sigma_a.value, Rgb(0.032f, 0.17f, 0.48f));
    EXPECT_EQ(ss.scale, 2.0f);
}

TEST(SceneLoaderSubsurface, ReflectanceAndMfpInvertTheEffectiveAlbedo) {
    const Scene s = with_material(R"({"type": "subsurface", "reflectance": [0.8, 0.5, 0.2], "mfp": 0.5, "scale": 2})");
    const Subsurface& ss = only_subsurface(s);
    EXPECT_TRUE(ss.from_reflectance);
    Color sa, sigma_s;
    ss.coefficients(s.textures, TextureContext{}, sa, sigma_s);
    // sigma_t = 1 / (mfp scale) = 1 in every channel; the albedo falls with the reflectance.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sa[c] + sigma_s[c], 1.0f, 1e-5f) << c;
    EXPECT_GT(sigma_s[0], sigma_s[1]);
    EXPECT_GT(sigma_s[1], sigma_s[2]);
    // mfp defaults to 1 (pbrt-v4).
    const Scene d = with_material(R"({"type": "subsurface", "reflectance": 0.5})");
    ss.coefficients(d.textures, TextureContext{}, sa, sigma_s);
    only_subsurface(d).coefficients(d.textures, TextureContext{}, sa, sigma_s);
    EXPECT_NEAR(sa[0] + sigma_s[0], 1.0f, 1e-5f);
}

TEST(SceneLoaderSubsurface, RandomWalkGivesItsShapesTheInteriorMedium) {
    const Scene s = with_material(R"({"type": "subsurface", "method": "random_walk", "sigma_a": [0.1, 0.2, 0.3],
                                      "sigma_s": 2, "scale": 10, "g": 0.5})");
    const Subsurface& ss = only_subsurface(s);
    EXPECT_EQ(ss.method, SubsurfaceMethod::kRandomWalk);
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_EQ(ss.medium, 0u);
    EXPECT_EQ(s.shapes[0].interior, 0u);
    EXPECT_EQ(s.shapes[0].exterior, kNoMedium);
    const auto* m = std::get_if<HomogeneousMedium>(&s.media[0]);
    ASSERT_NE(m, nullptr);
    EXPECT_TRUE(m->subsurface);
    EXPECT_FALSE(medium_counts_bounces(s.media[0]));
    EXPECT_EQ(m->g, 0.5f);
    EXPECT_NEAR(m->sigma_a.rgb.b, 3.0f, 1e-6f);
    EXPECT_NEAR(m->sigma_s.rgb.g, 20.0f, 1e-5f);
    EXPECT_NEAR(m->sigma_s.spectrum(550.0f), 20.0f, 1e-4f);
}

TEST(SceneLoaderSubsurface, RandomWalkFromReflectanceHasTheTabulatedCoefficients) {
    const Scene s = with_material(R"({"type": "subsurface", "method": "random_walk", "reflectance": 0.6, "mfp": 2})");
    const auto* m = std::get_if<HomogeneousMedium>(&s.media[0]);
    ASSERT_NE(m, nullptr);
    Color sa, ss;
    only_subsurface(s).coefficients(s.textures, TextureContext{}, sa, ss);
    EXPECT_NEAR(m->sigma_s.rgb.r, ss[0], 1e-6f);
    EXPECT_NEAR(m->sigma_a.rgb.g, sa[1], 1e-6f);
    // A grey reflectance's spectrum is flat: the same coefficients at every wavelength.
    EXPECT_NEAR(m->sigma_s.spectrum(450.0f), ss[0], 1e-3f);
    EXPECT_NEAR(m->sigma_s.spectrum(650.0f), ss[0], 1e-3f);
}

TEST(SceneLoaderSubsurface, IntegratorsThatIgnoreItAreWarnedAbout) {
    const Scene path = with_material(R"({"type": "subsurface"})", "", "path");
    ASSERT_EQ(path.warnings.size(), 1u);
    EXPECT_NE(path.warnings[0].find("the scene has subsurface materials but the path integrator renders only their "
                                    "dielectric boundary"),
              std::string::npos)
        << path.warnings[0];
    EXPECT_TRUE(with_material(R"({"type": "subsurface"})").warnings.empty());
}

void expect_error(const std::string& material, const std::string& pointer, const std::string& message,
                  const std::string& shape_keys = "") {
    const std::string json = R"({"materials": {"m": )" + material +
                             R"(}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m")" +
                             shape_keys + "}]}";
    SceneError e = load_error(json);
    EXPECT_EQ(e.where().json_pointer, pointer) << json;
    EXPECT_EQ(e.message(), message) << json;
}

TEST(SceneLoaderSubsurface, BadValuesAreLocated) {
    expect_error(R"({"type": "subsurface", "name": "Milk"})", "/materials/m/name",
                 "unknown measured medium \"Milk\"; the media are Apple, Apple Juice, Budweiser Beer, Cappuccino "
                 "Powder, Chardonnay, Chicken1, Chicken2, Clorox, Coke, Coors Light Beer, Cranberry Juice, Cream, "
                 "Espresso, Gatorade, Grape Juice, Head & Shoulders Shampoo, Ketchup, Lemon Tea Powder, Lowfat "
                 "Chocolate Milk, Lowfat Milk, Lowfat Soy Milk, Marble, Merlot, Mint Mocha Coffee, Orange Powder, "
                 "Pepsi, Pink Lemonade Powder, Potato, Reduced Milk, Regular Chocolate Milk, Regular Milk, Regular "
                 "Soy Milk, Ruby Grapefruit Juice, Salt Powder, Shampoo, Skimmilk, Skin1, Skin2, Spectralon, "
                 "Sprite, Strawberry Shampoo, Sugar Powder, Suisse Mocha Powder, White Grapefruit Juice, White "
                 "Zinfandel, Wholemilk");
    expect_error(R"({"type": "subsurface", "sigma_a": -1, "sigma_s": 1})", "/materials/m/sigma_a",
                 "expected a number >= 0, got -1");
    expect_error(R"({"type": "subsurface", "sigma_a": 1, "sigma_s": [1, -2, 3]})", "/materials/m/sigma_s/1",
                 "expected a number >= 0, got -2");
    expect_error(R"({"type": "subsurface", "reflectance": 0.5, "mfp": 0})", "/materials/m/mfp",
                 "expected a number > 0, got 0");
    expect_error(R"({"type": "subsurface", "reflectance": 1.5})", "/materials/m/reflectance",
                 "expected a number in [0, 1], got 1.5");
    expect_error(R"({"type": "subsurface", "sigma_a": 1})", "/materials/m/sigma_a",
                 "\"sigma_a\" needs \"sigma_s\" too");
    expect_error(R"({"type": "subsurface", "mfp": 1})", "/materials/m/mfp",
                 "\"mfp\" needs \"reflectance\" (the albedo it goes with)");
    expect_error(R"({"type": "subsurface", "name": "Skin1", "sigma_a": 1})", "/materials/m/sigma_a",
                 "give a medium \"name\" or its coefficients, not both");
    expect_error(R"({"type": "subsurface", "name": "Skin1", "g": 0.5})", "/materials/m/g",
                 "a named medium's sigma_s is a reduced coefficient: its g is 0");
    expect_error(R"({"type": "subsurface", "g": 1})", "/materials/m/g", "expected a number in (-1, 1), got 1");
    expect_error(R"({"type": "subsurface", "scale": 0})", "/materials/m/scale", "expected a number > 0, got 0");
    expect_error(R"({"type": "subsurface", "method": "dipole"})", "/materials/m/method",
                 "unknown method \"dipole\"; expected one of: random_walk, tabulated");
    expect_error(R"({"type": "subsurface", "method": "random_walk", "reflectance": {"type": "checkerboard"}})",
                 "/materials/m/method",
                 "the random walk needs constant coefficients (a texture varies on the surface, a medium in space); "
                 "use \"method\": \"tabulated\"");
}

TEST(SceneLoaderSubsurface, RandomWalkShapesTakeNoInterior) {
    SceneError e = load_error(R"({"media": {"fog": {"type": "homogeneous"}},
        "materials": {"m": {"type": "subsurface", "method": "random_walk"}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m", "interior": "fog"}]})");
    EXPECT_EQ(e.where().json_pointer, "/shapes/0/interior");
    EXPECT_EQ(e.message(), "the material \"m\" is a subsurface random walk: its medium is the shape's interior "
                           "(leave \"interior\" out)");
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela
