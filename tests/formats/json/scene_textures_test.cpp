// The scene file's `textures` and texture-valued material parameters (formats/json/scene_textures.cpp):
// every key changes the loaded scene, references resolve (forward too), cycles, unknown names and
// bad values are located errors, each image file is read once, and images are charged to the
// memory budget and covered by the content hash.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "candela/image/tonemap.h"
#include "candela/scene/content_hash.h"
#include "candela/scene/memory_budget.h"
#include "candela/formats/json/scene_loader.h"
#include "image/test_files.h"
#include "formats/json/scene_test_util.h"
#include "support/png_bytes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene with the given `textures` section's contents and a diffuse material "m" whose albedo
// is `albedo` (JSON).
Scene load_textures(const std::string& textures, const std::string& albedo = "0.5") {
    return load_json(R"({"textures": {)" + textures + R"(}, "materials": {"m": {"type": "diffuse", "albedo": )" +
                     albedo + "}}}");
}

SceneError textures_error(const std::string& textures, const std::string& albedo = "0.5") {
    return load_error(R"({"textures": {)" + textures + R"(}, "materials": {"m": {"type": "diffuse", "albedo": )" +
                      albedo + "}}}");
}

// The texture named `name`, as a T (the test fails if it is another kind).
template <class T>
T texture_named(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.texture_names.size(); ++i)
        if (s.texture_names[i] == name) {
            const T* t = std::get_if<T>(&s.textures.texture(uint32_t(i)));
            EXPECT_NE(t, nullptr) << name;
            return t ? *t : T{};
        }
    ADD_FAILURE() << "no texture " << name;
    return T{};
}

const ColorParam& albedo_param(const Scene& s) {
    return std::get<DiffuseParams>(s.materials.at(0).params[0]).albedo;
}

TextureContext at(float u, float v) { return TextureContext{Vec2f(u, v), Vec3f(0.0f)}; }

constexpr const char* kImage = R"("file": "textures/rgb_2x2.png")";

// ---- keys

TEST(SceneTextures, ConstantValueIsRead) {
    EXPECT_EQ(texture_named<ConstantTexture>(load_textures(R"("c": {"type": "constant", "value": [1, 2, 3]})"), "c")
                  .value,
              Rgb(1, 2, 3));
    EXPECT_EQ(texture_named<ConstantTexture>(load_textures(R"("c": {"type": "constant"})"), "c").value, Rgb(0.0f));
}

TEST(SceneTextures, CheckerboardKeysAreRead) {
    const CheckerboardTexture defaults =
        texture_named<CheckerboardTexture>(load_textures(R"("c": {"type": "checkerboard"})"), "c");
    EXPECT_EQ(defaults.color0.value, Rgb(1.0f));  // pbrt-v4's tex1 and tex2 defaults
    EXPECT_EQ(defaults.color1.value, Rgb(0.0f));
    EXPECT_EQ(defaults.uv.scale, Vec2f(1.0f, 1.0f));
    EXPECT_EQ(defaults.uv.offset, Vec2f(0.0f, 0.0f));
    const CheckerboardTexture c = texture_named<CheckerboardTexture>(
        load_textures(R"("c": {"type": "checkerboard", "color0": 0.2, "color1": [0.1, 0.2, 0.3],
                               "uv_scale": [8, 4], "uv_offset": [0.5, -0.25]})"),
        "c");
    EXPECT_EQ(c.color0.value, Rgb(0.2f));
    EXPECT_FALSE(c.color0.is_textured());
    EXPECT_EQ(c.color1.value, Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(c.uv.scale, Vec2f(8.0f, 4.0f));
    EXPECT_EQ(c.uv.offset, Vec2f(0.5f, -0.25f));
}

TEST(SceneTextures, ImageKeysAreRead) {
    const Scene plain = load_textures(std::string(R"("i": {"type": "image", )") + kImage + "}");
    const ImageTexture d = texture_named<ImageTexture>(plain, "i");
    EXPECT_EQ(d.wrap, TextureWrap::kRepeat);
    EXPECT_EQ(d.filter, TextureFilter::kBilinear);
    EXPECT_EQ(d.scale, 1.0f);
    EXPECT_FALSE(d.invert);
    ASSERT_EQ(plain.texture_files.size(), 1u);
    EXPECT_EQ(plain.texture_files[0].colorspace, TextureColorspace::kSrgb);
    EXPECT_EQ(plain.texture_files[0].name, "textures/rgb_2x2.png");
    EXPECT_EQ(plain.texture_files[0].pointer, "/textures/i/file");

    const Scene s = load_textures(std::string(R"("i": {"type": "image", )") + kImage +
                                  R"(, "colorspace": "linear", "wrap": "clamp", "filter": "point",
                                      "uv_scale": [2, 3], "uv_offset": [0.25, 0.5], "scale": 0.5,
                                      "invert": true})");
    const ImageTexture i = texture_named<ImageTexture>(s, "i");
    EXPECT_EQ(i.wrap, TextureWrap::kClamp);
    EXPECT_EQ(i.filter, TextureFilter::kPoint);
    EXPECT_EQ(i.uv.scale, Vec2f(2.0f, 3.0f));
    EXPECT_EQ(i.uv.offset, Vec2f(0.25f, 0.5f));
    EXPECT_EQ(i.scale, 0.5f);
    EXPECT_TRUE(i.invert);
    EXPECT_EQ(s.texture_files.at(0).colorspace, TextureColorspace::kLinear);
    EXPECT_EQ(texture_named<ImageTexture>(load_textures(std::string(R"("i": {"type": "image", )") + kImage +
                                                        R"(, "wrap": "black"})"),
                                          "i")
                  .wrap,
              TextureWrap::kBlack);
}

TEST(SceneTextures, ImageIsLoadedWithItsColorspace) {
    // rgb_2x2.png: top row red, green; bottom row blue, white.
    const Scene srgb = load_textures(std::string(R"("i": {"type": "image", "filter": "point", )") + kImage + "}");
    const uint32_t i = 0;
    EXPECT_EQ(srgb.textures.color(i, at(0.25f, 0.75f)), Rgb(1, 0, 0));
    EXPECT_EQ(srgb.textures.color(i, at(0.25f, 0.25f)), Rgb(0, 0, 1));
    EXPECT_EQ(srgb.textures.image(0).width, 2);
    EXPECT_EQ(srgb.textures.image(0).byte_values[128], decode_srgb(128.0f / 255.0f));
    const Scene linear = load_textures(std::string(R"("i": {"type": "image", "colorspace": "linear", )") + kImage + "}");
    EXPECT_EQ(linear.textures.image(0).byte_values[128], 128.0f / 255.0f);
}

TEST(SceneTextures, ScaleAndMixKeysAreRead) {
    const Scene s = load_textures(R"("a": {"type": "constant", "value": 0.25},
                                     "s": {"type": "scale", "tex": {"texture": "a"}, "scale": 3},
                                     "m": {"type": "mix", "tex1": 0.1, "tex2": {"texture": "a"},
                                           "amount": {"texture": "a"}},
                                     "d": {"type": "mix"}, "e": {"type": "scale"})");
    const ScaleTexture sc = texture_named<ScaleTexture>(s, "s");
    EXPECT_TRUE(sc.tex.is_textured());
    EXPECT_EQ(sc.scale.value, 3.0f);
    EXPECT_EQ(s.textures.color(sc.tex.texture, at(0, 0)), Rgb(0.25f));
    const MixTexture m = texture_named<MixTexture>(s, "m");
    EXPECT_EQ(m.tex1.value, Rgb(0.1f));
    EXPECT_TRUE(m.tex2.is_textured());
    EXPECT_TRUE(m.amount.is_textured());
    EXPECT_EQ(m.amount.lo, 0.0f);  // a textured amount is clamped to [0, 1]
    EXPECT_EQ(m.amount.hi, 1.0f);
    // pbrt-v4's defaults: mix of 0 and 1 by 0.5; scale of 1 by 1.
    const MixTexture d = texture_named<MixTexture>(s, "d");
    EXPECT_EQ(d.tex1.value, Rgb(0.0f));
    EXPECT_EQ(d.tex2.value, Rgb(1.0f));
    EXPECT_EQ(d.amount.value, 0.5f);
    EXPECT_EQ(s.textures.color(uint32_t(s.texture_names.size() - 1), at(0, 0)), Rgb(1.0f));
}

// ---- material parameters

TEST(SceneTextures, MaterialParameterTakesANameAnInlineTextureOrAConstant) {
    const Scene named = load_textures(R"("c": {"type": "checkerboard"})", R"({"texture": "c"})");
    EXPECT_TRUE(named.materials[0].textured);
    EXPECT_EQ(albedo_param(named).texture, 0u);
    // The albedo's range [0, 1] clamps the texture's values.
    EXPECT_EQ(albedo_param(named).lo, 0.0f);
    EXPECT_EQ(albedo_param(named).hi, 1.0f);

    const Scene inline_texture = load_json(R"({"materials": {"m": {"type": "diffuse",
        "albedo": {"type": "checkerboard", "color0": 0.25, "uv_scale": [2, 2]}}}})");
    ASSERT_TRUE(inline_texture.materials[0].textured);
    ASSERT_EQ(inline_texture.textures.size(), 1u);
    EXPECT_EQ(inline_texture.texture_names, std::vector<std::string>{""});
    const Bsdf bsdf = build_bsdf(inline_texture.materials[0], inline_texture.textures, at(0.1f, 0.1f));
    EXPECT_EQ(bsdf.albedo(), Color(0.25f));
    EXPECT_EQ(build_bsdf(inline_texture.materials[0], inline_texture.textures, at(0.6f, 0.1f)).albedo(), Color(0.0f));

    const Scene constant = load_textures(R"("c": {"type": "checkerboard"})", "[0.1, 0.2, 0.3]");
    EXPECT_FALSE(constant.materials[0].textured);
    EXPECT_EQ(albedo_param(constant).value, Rgb(0.1f, 0.2f, 0.3f));
}

TEST(SceneTextures, TexturesMayNameTexturesDefinedLater) {
    const Scene s = load_textures(R"("outer": {"type": "scale", "tex": {"texture": "inner"}, "scale": 2},
                                     "inner": {"type": "constant", "value": 0.25})",
                                  R"({"texture": "outer"})");
    // Inputs come first: inner is texture 0.
    EXPECT_EQ(s.texture_names, (std::vector<std::string>{"inner", "outer"}));
    EXPECT_EQ(s.textures.color(1, at(0, 0)), Rgb(0.5f));
    EXPECT_EQ(albedo_param(s).texture, 1u);
}

// ---- errors

TEST(SceneTextures, CyclesAreErrorsAtTheClosingReference) {
    SceneError e = textures_error(R"("a": {"type": "scale", "tex": {"texture": "b"}},
                                     "b": {"type": "mix", "tex2": {"texture": "a"}})");
    EXPECT_EQ(e.message(), R"(textures form a cycle: "a" -> "b" -> "a")");
    EXPECT_EQ(e.where().json_pointer, "/textures/b/tex2/texture");
    SceneError self = textures_error(R"("a": {"type": "checkerboard", "color1": {"texture": "a"}})");
    EXPECT_EQ(self.message(), R"(textures form a cycle: "a" -> "a")");
    EXPECT_EQ(self.where().json_pointer, "/textures/a/color1/texture");
}

TEST(SceneTextures, UnknownNamesAreErrorsListingTheDefinedOnes) {
    SceneError e = textures_error(R"("wood": {"type": "constant"}, "checks": {"type": "checkerboard"})",
                                  R"({"texture": "wod"})");
    EXPECT_EQ(e.message(), R"(unknown texture "wod"; defined textures: wood, checks)");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/albedo/texture");
    SceneError inside = textures_error(R"("a": {"type": "scale", "tex": {"texture": "nope"}})");
    EXPECT_EQ(inside.message(), R"(unknown texture "nope"; defined textures: a)");
    SceneError none = load_error(R"({"materials": {"m": {"type": "diffuse", "albedo": {"texture": "x"}}}})");
    EXPECT_EQ(none.message(), R"(unknown texture "x"; the scene defines no textures)");
}

TEST(SceneTextures, NestingDeeperThanTheLimitIsAnError) {
    // t0 <- t1 <- ... : t_k has depth k + 1.
    auto chain = [](int n) {
        std::string json = R"("t0": {"type": "constant"})";
        for (int k = 1; k < n; ++k)
            json += ", \"t" + std::to_string(k) + R"(": {"type": "scale", "tex": {"texture": "t)" +
                    std::to_string(k - 1) + "\"}}";
        return json;
    };
    EXPECT_EQ(load_textures(chain(kMaxTextureDepth)).textures.depth(kMaxTextureDepth - 1), kMaxTextureDepth);
    SceneError e = textures_error(chain(kMaxTextureDepth + 1));
    EXPECT_NE(e.message().find("textures nest more than 16 deep"), std::string::npos) << e.message();
    // Named in reverse order, the reader recurses through the names; the limit holds there too.
    std::string reversed = R"("t0": {"type": "scale", "tex": {"texture": "t1"}})";
    for (int k = 1; k < 40; ++k)
        reversed += ", \"t" + std::to_string(k) + R"(": {"type": "scale", "tex": {"texture": "t)" +
                    std::to_string(k + 1) + "\"}}";
    reversed += R"(, "t40": {"type": "constant"})";
    EXPECT_NE(textures_error(reversed).message().find("textures nest more than 16 deep"), std::string::npos);
}

TEST(SceneTextures, BadValuesAreLocatedErrors) {
    struct Case {
        std::string texture;
        std::string pointer;
        std::string message;
    };
    const Case cases[] = {
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "wrap": "mirror"})", "/textures/t/wrap",
         R"(unknown wrap mode "mirror"; expected one of: black, clamp, repeat)"},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "filter": "trilinear"})", "/textures/t/filter",
         R"(unknown texture filter "trilinear"; expected one of: bilinear, point)"},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "rec2020"})", "/textures/t/colorspace",
         R"(unknown colorspace "rec2020"; expected one of: gamma, linear, srgb)"},
        {R"({"type": "image", "file": "sky_2x1.hdr", "colorspace": "srgb"})", "/textures/t/colorspace",
         R"("sky_2x1.hdr" holds linear values; "srgb" applies only to 8- and 16-bit images (.png, .jpg, .jpeg, .tga, .bmp))"},
        {R"({"type": "image", "file": "textures/nope.png"})", "/textures/t/file",
         "texture image file \"textures/nope.png\" not found"},
        {R"({"type": "image", "file": "meshes/triangle.obj"})", "/textures/t/file",
         R"(expected an image file (.png, .jpg, .jpeg, .tga, .bmp, .exr, .hdr, .pfm), got "meshes/triangle.obj")"},
        {R"({"type": "image", "file": "textures/rgb_2x2.png", "scale": -1})", "/textures/t/scale",
         "expected a number >= 0, got -1"},
        {R"({"type": "checkerboard", "uv_scale": [1]})", "/textures/t/uv_scale",
         "expected an array of 2 numbers [su, sv], got [1]"},
        {R"({"type": "mix", "amount": 2})", "/textures/t/amount", "expected a number in [0, 1], got 2"},
        {R"({"type": "mix", "tex1": {"texture": "u", "scale": 2}})", "/textures/t/tex1", R"(unknown key "scale")"},
        {R"({"type": "checkerboard", "color0": {"uv_scale": [2, 2]}})", "/textures/t/color0",
         R"(missing required key "type")"},
        {R"({"type": "noise"})", "/textures/t/type",
         R"(unknown texture type "noise"; expected one of: bilerp, checkerboard, constant, directionmix, image, mix, scale)"},
        {R"({"type": "image"})", "/textures/t", R"(missing required key "file")"},
        {R"({"type": "checkerboard", "colour0": 1})", "/textures/t", R"(unknown key "colour0" (did you mean "color0"?))"},
    };
    for (const Case& c : cases) {
        SceneError e = textures_error(R"("u": {"type": "constant"}, "t": )" + c.texture);
        EXPECT_EQ(e.where().json_pointer, c.pointer) << c.texture;
        EXPECT_NE(e.message().find(c.message), std::string::npos) << c.texture << "\n  " << e.message();
    }
}

TEST(SceneTextures, AnErrorInsideAnImageNamesTheImageAndTheKey) {
    testing::TempDir dir;
    testing::write_test_file(dir / "broken.png", "not a png at all");
    try {
        load_scene_from_string(R"({"textures": {"t": {"type": "image", "file": "broken.png"}}})", dir / "scene.json");
        ADD_FAILURE() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, (dir / "broken.png").string());
        EXPECT_NE(e.message().find("(referenced by /textures/t/file at "), std::string::npos) << e.message();
    }
}

// ---- each file once

TEST(SceneTextures, AFileUsedTwiceIsReadOnce) {
    const Scene s = load_json(R"({"textures": {
        "a": {"type": "image", "file": "textures/rgb_2x2.png"},
        "b": {"type": "image", "file": "./textures/../textures/rgb_2x2.png", "wrap": "clamp"},
        "c": {"type": "image", "file": "textures/rgb_2x2.png", "colorspace": "linear"}},
      "materials": {"m": {"type": "diffuse", "albedo": {"type": "image", "file": "textures/rgb_2x2.png"}},
                    "n": {"type": "diffuse", "albedo": {"type": "image", "file": "sky_2x1.hdr"}},
                    "o": {"type": "mirror", "albedo": {"type": "image", "file": "sky_2x1.hdr", "colorspace": "linear"}}}})");
    // One file in sRGB (a, b and m's), the same in linear (c), the HDR once (n, o).
    ASSERT_EQ(s.texture_files.size(), 3u);
    ASSERT_EQ(s.textures.image_count(), 3u);
    EXPECT_EQ(texture_named<ImageTexture>(s, "a").image, 0u);
    EXPECT_EQ(texture_named<ImageTexture>(s, "b").image, 0u);
    EXPECT_EQ(texture_named<ImageTexture>(s, "c").image, 1u);
    EXPECT_EQ(std::get<ImageTexture>(s.textures.texture(3)).image, 0u);
    EXPECT_EQ(std::get<ImageTexture>(s.textures.texture(4)).image, 2u);
    EXPECT_EQ(std::get<ImageTexture>(s.textures.texture(5)).image, 2u);
    EXPECT_EQ(s.texture_files[2].colorspace, TextureColorspace::kLinear);
    EXPECT_EQ(s.textures.image(2).width, 2);
}

// ---- memory and content hash

TEST(SceneTextures, ImagesAreChargedToTheMemoryBudget) {
    const std::string json = R"({"camera": {"resolution": [1, 1]},
        "textures": {"t": {"type": "image", "file": "textures/rgb_2x2.png"}}})";
    const Scene s = load_json(json);
    EXPECT_EQ(s.textures.image_memory_bytes(), texture_memory_bytes(2, 2, 3, 1));
    EXPECT_EQ(scene_memory_bytes(s), film_memory_bytes(1, 1) + texture_memory_bytes(2, 2, 3, 1));
    LoadOptions tight;
    tight.memory_limit = MemoryLimit{film_memory_bytes(1, 1) + 500, "the test's limit is"};
    try {
        load_scene_from_string(json, test::scenes_dir() / "inline.json", tight);
        ADD_FAILURE() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().json_pointer, "/textures/t/file");
        EXPECT_NE(e.message().find("texture image \"textures/rgb_2x2.png\" (2x2) needs about"),
                  std::string::npos)
            << e.message();
    }
}

TEST(SceneTextures, ContentHashCoversTextureFiles) {
    testing::TempDir dir;
    const std::string json = R"({"materials": {"m": {"type": "diffuse",
        "albedo": {"type": "checkerboard", "color1": {"type": "image", "file": "t.png"}}}}})";
    testing::write_test_file(dir / "scene.json", json);
    testing::write_test_file(dir / "t.png", test::make_png(1, 1, 8, 0, 1, {10}));
    const uint64_t before = scene_content_hash(load_scene(dir / "scene.json"));
    testing::write_test_file(dir / "t.png", test::make_png(1, 1, 8, 0, 1, {11}));
    EXPECT_NE(scene_content_hash(load_scene(dir / "scene.json")), before);
}

}  // namespace
}  // namespace candela
