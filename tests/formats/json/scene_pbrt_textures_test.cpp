// Textures that pbrt-v4 scenes use, in the scene file (formats/json/scene_textures.cpp) and as
// values (textures/texture_kinds.h): `bilerp`, `directionmix`, `checkerboard` of `dimension` 3
// and the image colorspace `gamma` (pbrt-v4's encoding "gamma G"). Each key changes the loaded
// scene, the values at known points are pbrt-v4's, bad values are located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene whose material "m" is diffuse with the albedo texture `albedo` (JSON), unclamped
// through a `scale` of 1 so that values above 1 show.
Scene load_texture(const std::string& texture) {
    return load_json(R"({"textures": {"t": )" + texture + R"(}, "materials": {"m": {"type": "diffuse", "albedo": 0.5}}})");
}
SceneError texture_error(const std::string& texture) {
    return load_error(R"({"textures": {"t": )" + texture + R"(}, "materials": {"m": {"type": "diffuse", "albedo": 0.5}}})");
}

// Texture "t" (the last texture of the scene: its inputs come first) at uv, point p and normal n.
Rgb color_at(const Scene& s, Vec2f uv, Vec3f p = Vec3f(0.0f), Vec3f n = Vec3f(0.0f)) {
    TextureContext ctx{uv, p};
    ctx.n = n;
    return s.textures.color(uint32_t(s.textures.size() - 1), ctx);
}
float number_at(const Scene& s, Vec2f uv, Vec3f p = Vec3f(0.0f), Vec3f n = Vec3f(0.0f)) {
    TextureContext ctx{uv, p};
    ctx.n = n;
    return s.textures.number(uint32_t(s.textures.size() - 1), ctx);
}

void expect_rgb_near(const Rgb& got, const Rgb& expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(got.r, expected.r, tolerance);
    EXPECT_NEAR(got.g, expected.g, tolerance);
    EXPECT_NEAR(got.b, expected.b, tolerance);
}

// ---- bilerp

TEST(ScenePbrtTextures, BilerpInterpolatesItsCornersOverUv) {
    const Scene s = load_texture(R"({"type": "bilerp", "v00": [1, 0, 0], "v10": [0, 1, 0], "v01": [0, 0, 1],
                                     "v11": 4})");
    expect_rgb_near(color_at(s, Vec2f(0, 0)), Rgb(1, 0, 0));
    expect_rgb_near(color_at(s, Vec2f(1, 0)), Rgb(0, 1, 0));
    expect_rgb_near(color_at(s, Vec2f(0, 1)), Rgb(0, 0, 1));
    expect_rgb_near(color_at(s, Vec2f(1, 1)), Rgb(4, 4, 4));
    // (0.25, 0.5): weights 0.375 v00, 0.125 v10, 0.375 v01, 0.125 v11.
    expect_rgb_near(color_at(s, Vec2f(0.25f, 0.5f)), Rgb(0.375f + 0.5f, 0.125f + 0.5f, 0.375f + 0.5f));
    // As a number, the channels' average, as for a constant.
    EXPECT_NEAR(number_at(s, Vec2f(0.25f, 0.5f)), (0.875f + 0.625f + 0.875f) / 3.0f, 1e-6f);
}

TEST(ScenePbrtTextures, BilerpDefaultsArePbrtsAndUvTransformApplies) {
    // v00 0, v01 1, v10 0, v11 1: the value is t.
    const Scene plain = load_texture(R"({"type": "bilerp"})");
    EXPECT_NEAR(number_at(plain, Vec2f(0.9f, 0.3f)), 0.3f, 1e-6f);
    const Scene scaled = load_texture(R"({"type": "bilerp", "uv_scale": [1, 2], "uv_offset": [0, 0.1]})");
    EXPECT_NEAR(number_at(scaled, Vec2f(0.9f, 0.3f)), 0.7f, 1e-6f);
}

// ---- directionmix

TEST(ScenePbrtTextures, DirectionMixWeighsTex1ByTheNormalsCosineToDir) {
    const Scene s = load_texture(R"({"type": "directionmix", "tex1": [1, 0, 0], "tex2": [0, 0, 1], "dir": [0, 0, 2]})");
    expect_rgb_near(color_at(s, Vec2f(), Vec3f(), Vec3f(0, 0, 1)), Rgb(1, 0, 0));
    expect_rgb_near(color_at(s, Vec2f(), Vec3f(), Vec3f(0, 0, -1)), Rgb(1, 0, 0));  // |cos|
    expect_rgb_near(color_at(s, Vec2f(), Vec3f(), Vec3f(1, 0, 0)), Rgb(0, 0, 1));
    const float c = std::cos(1.0f);
    expect_rgb_near(color_at(s, Vec2f(), Vec3f(), Vec3f(std::sin(1.0f), 0, c)), Rgb(c, 0, 1.0f - c));
    EXPECT_NEAR(number_at(s, Vec2f(), Vec3f(), Vec3f(std::sin(1.0f), 0, c)), 1.0f / 3.0f, 1e-6f);
}

TEST(ScenePbrtTextures, DirectionMixDefaultsToPbrtsUpAndItsInputsMayBeTextures) {
    const Scene s = load_texture(
        R"({"type": "directionmix", "tex1": {"type": "checkerboard", "color0": 0.25, "color1": 0.75}})");
    // dir (0, 1, 0), tex2 1: w = 0.6 for n = (0.8, 0.6, 0).
    EXPECT_NEAR(number_at(s, Vec2f(0.5f, 0.5f), Vec3f(), Vec3f(0.8f, 0.6f, 0)), 0.6f * 0.25f + 0.4f, 1e-6f);
    EXPECT_NEAR(number_at(s, Vec2f(1.5f, 0.5f), Vec3f(), Vec3f(0.8f, 0.6f, 0)), 0.6f * 0.75f + 0.4f, 1e-6f);
}

// ---- checkerboard, dimension 3

TEST(ScenePbrtTextures, SolidCheckerboardAlternatesOverTheHitPoint) {
    const Scene s = load_texture(R"({"type": "checkerboard", "dimension": 3, "color0": 0.25, "color1": 0.75})");
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(0.5f, 0.5f, 0.5f)), 0.25f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(1.5f, 0.5f, 0.5f)), 0.75f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(1.5f, 1.5f, 0.5f)), 0.25f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(1.5f, 1.5f, 1.5f)), 0.75f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(-0.5f, 0.5f, 0.5f)), 0.75f);
    // uv plays no part.
    EXPECT_EQ(number_at(s, Vec2f(1.5f, 0.0f), Vec3f(0.5f, 0.5f, 0.5f)), 0.25f);
}

TEST(ScenePbrtTextures, SolidCheckerboardTransformTakesTextureSpaceIntoTheWorld) {
    // Texture space scaled by 2 then moved by 1 in x: world x in [1, 3) is texture x in [0, 1).
    const Scene s = load_texture(R"({"type": "checkerboard", "dimension": 3, "color0": 0.25, "color1": 0.75,
                                     "transform": [{"scale": 2}, {"translate": [1, 0, 0]}]})");
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(2.9f, 1.9f, 1.9f)), 0.25f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(0.9f, 1.9f, 1.9f)), 0.75f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(3.1f, 1.9f, 1.9f)), 0.75f);
    EXPECT_EQ(number_at(s, Vec2f(), Vec3f(2.9f, 2.1f, 1.9f)), 0.75f);
}

TEST(ScenePbrtTextures, DimensionTwoIsTheCheckerboardOfBefore) {
    const Scene s = load_texture(R"({"type": "checkerboard", "dimension": 2, "color0": 0.25, "color1": 0.75})");
    EXPECT_EQ(number_at(s, Vec2f(1.5f, 0.5f), Vec3f(0.5f)), 0.75f);
    EXPECT_EQ(number_at(s, Vec2f(0.5f, 0.5f), Vec3f(1.5f, 0.5f, 0.5f)), 0.25f);
}

// ---- colorspace gamma

TEST(ScenePbrtTextures, GammaColorspaceIsKeptWithItsExponent) {
    const Scene s = load_texture(R"({"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma", "gamma": 2.2})");
    ASSERT_EQ(s.texture_files.size(), 1u);
    EXPECT_EQ(s.texture_files[0].colorspace, TextureColorspace::kGamma);
    EXPECT_EQ(s.texture_files[0].gamma, 2.2f);
    // The file's texels are 0 or 255: 0 and 1 in any encoding.
    EXPECT_EQ(s.textures.image(0).byte_values[255], 1.0f);
    EXPECT_NEAR(s.textures.image(0).byte_values[128], std::pow(128.0f / 255.0f, 2.2f), 1e-6f);
    // Two gammas of one file are two images.
    const Scene two = load_json(R"({"textures": {
        "a": {"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma", "gamma": 2.2},
        "b": {"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma", "gamma": 1.8},
        "c": {"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma", "gamma": 2.2}}})");
    EXPECT_EQ(two.texture_files.size(), 2u);
}

// ---- errors

TEST(ScenePbrtTextures, BadValuesAreLocatedErrors) {
    struct Case {
        std::string texture, pointer, message;
    };
    const Case cases[] = {
        {R"({"type": "checkerboard", "dimension": 4})", "/textures/t/dimension", "expected an integer in [2, 3], got 4"},
        {R"({"type": "checkerboard", "dimension": 3, "uv_scale": [2, 2]})", "/textures/t/uv_scale",
         R"("uv_scale" is for a checkerboard of dimension 2 (over uv); dimension 3 takes "transform")"},
        {R"({"type": "checkerboard", "transform": [{"scale": 2}]})", "/textures/t/transform",
         "a transform is for a checkerboard of dimension 3"},
        {R"({"type": "checkerboard", "dimension": 3, "transform": [{"scale": [1, 0, 1]}]})",
         "/textures/t/transform/0/scale", ""},
        {R"({"type": "directionmix", "dir": [0, 0, 0]})", "/textures/t/dir", "expected a direction, got the zero vector"},
        {R"({"type": "bilerp", "v00": "red"})", "/textures/t/v00", ""},
        {R"({"type": "bilerp", "amount": 1})", "/textures/t", ""},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma"})", "/textures/t/colorspace",
         R"(colorspace "gamma" needs a "gamma" exponent, e.g. "gamma": 2.2)"},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "gamma": 2.2})", "/textures/t/gamma",
         R"("gamma" is the exponent of "colorspace": "gamma")"},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "gamma", "gamma": 0})", "/textures/t/gamma",
         "expected a number > 0, got 0"},
        {R"({"type": "image", "file": "sky_2x1.hdr", "colorspace": "gamma", "gamma": 2})", "/textures/t/colorspace",
         R"("sky_2x1.hdr" holds linear values; "gamma" applies only to 8- and 16-bit images (.png, .jpg, .jpeg, .tga, .bmp))"},
    };
    for (const Case& c : cases) {
        SceneError e = texture_error(c.texture);
        EXPECT_EQ(e.where().json_pointer.substr(0, c.pointer.size()), c.pointer) << c.texture;
        if (!c.message.empty()) {
            EXPECT_EQ(e.message(), c.message) << c.texture;
        }
    }
}

}  // namespace
}  // namespace candela
