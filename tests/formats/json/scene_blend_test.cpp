// The scene file's `blend` material (formats/json/scene_materials.cpp): pbrt-v4's `mix`, one of
// two named materials at each point. Its keys change the loaded scene; unknown names, a blend of
// itself, a cycle of blends, a part with alpha and an amount outside [0, 1] are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene whose materials section is `materials` (the inside of the object).
Scene load_materials(const std::string& materials) { return load_json(R"({"materials": {)" + materials + "}}"); }
SceneError materials_error(const std::string& materials) {
    return load_error(R"({"materials": {)" + materials + "}}");
}

const char* kParts = R"("a": {"type": "diffuse", "albedo": 0.2}, "b": {"type": "diffuse", "albedo": 0.8}, )";

TEST(SceneBlend, PartsAndAmountAreRead) {
    const Scene s = load_materials(std::string(kParts) + R"("m": {"type": "blend", "materials": ["b", "a"], "amount": 0.3})");
    const Material& m = s.materials.at(2);
    ASSERT_TRUE(m.blend.has_value());
    EXPECT_EQ(m.blend->parts[0], 1u);
    EXPECT_EQ(m.blend->parts[1], 0u);
    EXPECT_EQ(m.blend->amount.value, 0.3f);
    EXPECT_FALSE(m.blend->amount.is_textured());
    // The path tracer resolves blends on its per-hit path; a blend has no lobes of its own.
    EXPECT_TRUE(m.per_hit);
    EXPECT_EQ(m.bsdf.lobe_count, 0u);
    EXPECT_FALSE(s.materials[0].blend.has_value());
}

TEST(SceneBlend, AmountDefaultsToPbrtsHalf) {
    const Scene s = load_materials(std::string(kParts) + R"("m": {"type": "blend", "materials": ["a", "b"]})");
    EXPECT_EQ(s.materials.at(2).blend->amount.value, 0.5f);
}

TEST(SceneBlend, PartsMayComeLaterAndBlendsNest) {
    const Scene s = load_materials(
        R"("outer": {"type": "blend", "materials": ["inner", "c"], "amount": 0.25},
           "inner": {"type": "blend", "materials": ["a", "b"]},
           "a": {"type": "diffuse"}, "b": {"type": "mirror"}, "c": {"type": "dielectric"})");
    EXPECT_EQ(s.materials.at(0).blend->parts[0], 1u);
    EXPECT_EQ(s.materials.at(0).blend->parts[1], 4u);
    EXPECT_EQ(s.materials.at(1).blend->parts[0], 2u);
    EXPECT_EQ(s.materials.at(1).blend->parts[1], 3u);
}

TEST(SceneBlend, AmountMayBeATextureClampedToTheUnitInterval) {
    const Scene s = load_json(
        R"({"textures": {"t": {"type": "checkerboard", "color0": -1, "color1": 3}},
            "materials": {"a": {"type": "diffuse"}, "b": {"type": "diffuse", "albedo": 0.5},
                          "m": {"type": "blend", "materials": ["a", "b"], "amount": {"texture": "t"}}}})");
    const FloatParam& amount = s.materials.at(2).blend->amount;
    ASSERT_TRUE(amount.is_textured());
    EXPECT_EQ(amount.lo, 0.0f);
    EXPECT_EQ(amount.hi, 1.0f);
    EXPECT_EQ(s.textures.eval(amount, TextureContext{Vec2f(0.5f, 0.5f), Vec3f(0.0f)}), 0.0f);
    EXPECT_EQ(s.textures.eval(amount, TextureContext{Vec2f(1.5f, 0.5f), Vec3f(0.0f)}), 1.0f);
}

TEST(SceneBlend, AlphaIsTheBlendsAndPartsCannotBeCutOut) {
    const Scene s = load_materials(std::string(kParts) +
                                   R"("m": {"type": "blend", "materials": ["a", "b"], "alpha": 0.4})");
    EXPECT_EQ(s.materials.at(2).surface.alpha.value, 0.4f);
    SceneError e = materials_error(
        R"("a": {"type": "diffuse", "alpha": 0.5}, "b": {"type": "diffuse"},
           "m": {"type": "blend", "materials": ["b", "a"]})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/materials/1");
    EXPECT_EQ(e.message(), R"(material "a" has alpha < 1: a blend's parts cannot be cut out (give the alpha to the blend))");
}

TEST(SceneBlend, MapsBelongToTheParts) {
    SceneError e = materials_error(std::string(kParts) +
                                   R"("m": {"type": "blend", "materials": ["a", "b"], "bump_map": 0.1})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/bump_map");
    EXPECT_EQ(e.message(), R"(a blend shades with the normal of the part it chooses; give "bump_map" to its parts)");
}

TEST(SceneBlend, BadPartsAreLocatedErrors) {
    struct Case {
        std::string blend, pointer, message;
    };
    const Case cases[] = {
        {R"({"type": "blend", "materials": ["a", "x"]})", "/materials/m/materials/1",
         R"(unknown material "x"; defined materials: a, b, m)"},
        {R"({"type": "blend", "materials": ["a"]})", "/materials/m/materials",
         R"(expected an array of 2 material names, got ["a"])"},
        {R"({"type": "blend", "materials": ["a", 3]})", "/materials/m/materials/1", "expected a material name, got 3"},
        {R"({"type": "blend", "materials": ["m", "a"]})", "/materials/m/materials/0",
         R"(a blend cannot contain itself ("m"))"},
        {R"({"type": "blend", "materials": ["a", "b"], "amount": 1.5})", "/materials/m/amount",
         "expected a number in [0, 1], got 1.5"},
        {R"({"type": "blend", "materials": ["a", "b"], "amount": -0.1})", "/materials/m/amount",
         "expected a number in [0, 1], got -0.1"},
        {R"({"type": "blend", "amount": 0.5})", "/materials/m", R"(missing required key "materials")"},
    };
    for (const Case& c : cases) {
        SceneError e = materials_error(std::string(kParts) + R"("m": )" + c.blend);
        EXPECT_EQ(e.where().json_pointer, c.pointer) << c.blend;
        EXPECT_EQ(e.message(), c.message) << c.blend;
    }
}

TEST(SceneBlend, ACycleOfBlendsIsAnError) {
    SceneError e = materials_error(
        R"("a": {"type": "diffuse"},
           "p": {"type": "blend", "materials": ["a", "q"]},
           "q": {"type": "blend", "materials": ["r", "a"]},
           "r": {"type": "blend", "materials": ["a", "p"]})");
    EXPECT_EQ(e.where().json_pointer, "/materials/r/materials/1");
    EXPECT_EQ(e.message(), R"(blends form a cycle: "p" -> "q" -> "r" -> "p")");
}

TEST(SceneBlend, AMixCannotHoldABlend) {
    SceneError e = materials_error(R"("m": {"type": "mix", "lobes": [{"type": "blend", "materials": ["a", "b"]}]})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/lobes/0/type");
}

}  // namespace
}  // namespace candela
