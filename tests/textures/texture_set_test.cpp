// The texture kinds evaluated through a TextureSet (textures/texture_kinds.h, texture_set.h):
// constants, image textures with their uv transform, scale and invert, checkerboard edges, scale
// and mix, nesting, parameter clamping and depth.
#include "candela/textures/texture_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace candela {
namespace CANDELA_UNITY_ID {

TextureContext at(float u, float v) { return TextureContext{Vec2f(u, v), Vec3f(0.0f)}; }

ColorParam use(uint32_t texture) { return ColorParam{Rgb(0.0f), texture}; }
FloatParam use_number(uint32_t texture) { return FloatParam{0.0f, texture}; }

// A 2x2 RGB float image: top row (1, 0, 0), (0, 1, 0); bottom row (0, 0, 1), (1, 1, 1).
TextureImage two_by_two() {
    TextureImage image;
    image.width = 2;
    image.height = 2;
    image.channels = 3;
    image.floats = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    return image;
}

TEST(TextureSet, ConstantGivesItsColourAndChannelAverage) {
    TextureSet set;
    const uint32_t t = set.add(ConstantTexture{Rgb(0.2f, 0.4f, 0.9f)});
    EXPECT_EQ(set.color(t, at(0.3f, 0.7f)), Rgb(0.2f, 0.4f, 0.9f));
    EXPECT_FLOAT_EQ(set.number(t, at(0.3f, 0.7f)), 0.5f);
    // A grey constant is exactly its value as a number ((v + v + v) / 3 need not be).
    const uint32_t grey = set.add(ConstantTexture{Rgb(0.1f)});
    EXPECT_EQ(set.number(grey, at(0, 0)), 0.1f);
}

TEST(TextureSet, ParameterIsItsConstantOrItsTextureClamped) {
    TextureSet set;
    const uint32_t t = set.add(ConstantTexture{Rgb(-0.5f, 0.5f, 3.0f)});
    EXPECT_EQ(set.eval(ColorParam{Rgb(0.25f)}, at(0, 0)), Color(0.25f));
    EXPECT_EQ(set.eval(ColorParam{Rgb(0.25f), t}, at(0, 0)), Color(-0.5f, 0.5f, 3.0f));
    EXPECT_EQ(set.eval(ColorParam{Rgb(0.25f), t, 0.0f, 1.0f}, at(0, 0)), Color(0.0f, 0.5f, 1.0f));
    const uint32_t n = set.add(ConstantTexture{Rgb(7.0f)});
    EXPECT_EQ(set.eval(FloatParam{0.5f, n}, at(0, 0)), 7.0f);
    EXPECT_EQ(set.eval(FloatParam{0.5f, n, 0.0f, 2.0f}, at(0, 0)), 2.0f);
    // make_material evaluates textured parameters with an empty set: the constant.
    EXPECT_EQ(TextureSet().eval(ColorParam{Rgb(0.25f), 3}, at(0, 0)), Color(0.25f));
    EXPECT_EQ(TextureSet().eval(FloatParam{0.5f, 3}, at(0, 0)), 0.5f);
}

TEST(TextureSet, ImageTextureReadsItsImageAtTheTransformedUv) {
    TextureSet set;
    ImageTexture plain;
    plain.image = set.add_image(two_by_two());
    plain.filter = TextureFilter::kPoint;
    const uint32_t t = set.add(plain);
    EXPECT_EQ(set.color(t, at(0.25f, 0.75f)), Rgb(1, 0, 0));  // top left
    EXPECT_EQ(set.color(t, at(0.75f, 0.75f)), Rgb(0, 1, 0));
    EXPECT_EQ(set.color(t, at(0.25f, 0.25f)), Rgb(0, 0, 1));  // bottom left
    EXPECT_EQ(set.color(t, at(0.75f, 0.25f)), Rgb(1, 1, 1));

    // (s, t) = (2 u + 0.5, 0.5 v + 0.25): u = 0.1 -> s = 0.7 (right column), v = 0.2 -> t = 0.35
    // (bottom row); u = 0.3 -> s = 1.1, repeated to 0.1 (left column), v = 1.2 -> t = 0.85 (top).
    ImageTexture moved = plain;
    moved.uv = UvTransform{Vec2f(2.0f, 0.5f), Vec2f(0.5f, 0.25f)};
    const uint32_t m = set.add(moved);
    EXPECT_EQ(set.color(m, at(0.1f, 0.2f)), Rgb(1, 1, 1));
    EXPECT_EQ(set.color(m, at(0.3f, 1.2f)), Rgb(1, 0, 0));
    for (float u : {0.05f, 0.3f, 0.61f})
        for (float v : {0.1f, 0.45f, 0.9f})
            EXPECT_EQ(set.color(m, at(u, v)), set.color(t, at(2.0f * u + 0.5f, 0.5f * v + 0.25f))) << u << ", " << v;
}

TEST(TextureSet, ImageScaleAndInvertAsPbrt) {
    TextureSet set;
    ImageTexture tex;
    tex.image = set.add_image(two_by_two());
    tex.filter = TextureFilter::kPoint;
    tex.scale = 0.5f;
    const uint32_t scaled = set.add(tex);
    EXPECT_EQ(set.color(scaled, at(0.25f, 0.75f)), Rgb(0.5f, 0, 0));
    EXPECT_FLOAT_EQ(set.number(scaled, at(0.25f, 0.75f)), 0.5f / 3.0f);
    // Inverted: 1 - 0.5 value; as a colour clamped at 0, as a number max(0, 1 - v).
    tex.invert = true;
    const uint32_t inverted = set.add(tex);
    EXPECT_EQ(set.color(inverted, at(0.25f, 0.75f)), Rgb(0.5f, 1, 1));
    EXPECT_FLOAT_EQ(set.number(inverted, at(0.75f, 0.25f)), 0.5f);
    tex.scale = 3.0f;
    const uint32_t over = set.add(tex);
    EXPECT_EQ(set.color(over, at(0.75f, 0.25f)), Rgb(0.0f));
    EXPECT_EQ(set.number(over, at(0.75f, 0.25f)), 0.0f);
}

TEST(TextureSet, CheckerboardFlipsJustInsideEachIntegerLine) {
    TextureSet set;
    const uint32_t t = set.add(CheckerboardTexture{ColorParam{Rgb(0.2f)}, ColorParam{Rgb(0.8f)}, {}});
    const float below = std::nextafter(1.0f, 0.0f), above = std::nextafter(1.0f, 2.0f);
    // floor(s) + floor(t) even: color0; odd: color1.
    EXPECT_EQ(set.color(t, at(0.5f, 0.5f)), Rgb(0.2f));
    EXPECT_EQ(set.color(t, at(below, 0.5f)), Rgb(0.2f));
    EXPECT_EQ(set.color(t, at(above, 0.5f)), Rgb(0.8f));
    EXPECT_EQ(set.color(t, at(0.5f, below)), Rgb(0.2f));
    EXPECT_EQ(set.color(t, at(0.5f, above)), Rgb(0.8f));
    EXPECT_EQ(set.color(t, at(above, above)), Rgb(0.2f));  // 1 + 1: even
    // Across 0: floor(-tiny) = -1, odd.
    EXPECT_EQ(set.color(t, at(0.0f, 0.5f)), Rgb(0.2f));
    EXPECT_EQ(set.color(t, at(-1e-7f, 0.5f)), Rgb(0.8f));
    EXPECT_EQ(set.color(t, at(-1e-7f, -1e-7f)), Rgb(0.2f));
    EXPECT_EQ(set.color(t, at(-2.5f, 3.5f)), Rgb(0.2f));  // -3 + 3: even
    EXPECT_EQ(set.color(t, at(-2.5f, 4.5f)), Rgb(0.8f));  // -3 + 4: odd
    EXPECT_EQ(set.number(t, at(above, 0.5f)), 0.8f);
}

TEST(TextureSet, CheckerboardUvTransformScalesTheSquares) {
    TextureSet set;
    // uv_scale 8: squares of 1/8; uv_offset 0.5 shifts them by half a square.
    const uint32_t t = set.add(CheckerboardTexture{ColorParam{Rgb(0.0f)}, ColorParam{Rgb(1.0f)},
                                                   UvTransform{Vec2f(8.0f, 8.0f), Vec2f(0.5f, 0.0f)}});
    // s = 8 u + 0.5: u = 0.05 -> 0.9 (even), u = 0.07 -> 1.06 (odd).
    EXPECT_EQ(set.color(t, at(0.05f, 0.01f)), Rgb(0.0f));
    EXPECT_EQ(set.color(t, at(0.07f, 0.01f)), Rgb(1.0f));
    EXPECT_EQ(set.color(t, at(0.07f, 0.13f)), Rgb(0.0f));  // t = 1.04: odd + odd
}

TEST(TextureSet, ScaleAndMixCombineTheirInputs) {
    TextureSet set;
    const uint32_t a = set.add(ConstantTexture{Rgb(0.2f, 0.4f, 0.6f)});
    const uint32_t b = set.add(ConstantTexture{Rgb(1.0f, 0.0f, 0.5f)});
    const uint32_t half = set.add(ConstantTexture{Rgb(0.5f)});
    const uint32_t scaled = set.add(ScaleTexture{use(a), use_number(half)});
    EXPECT_EQ(set.color(scaled, at(0, 0)), Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(set.color(set.add(ScaleTexture{use(a), FloatParam{2.0f}}), at(0, 0)), Rgb(0.4f, 0.8f, 1.2f));
    // (1 - amount) tex1 + amount tex2.
    const uint32_t mix = set.add(MixTexture{use(a), use(b), FloatParam{0.25f}});
    const Rgb expected = Rgb(0.2f, 0.4f, 0.6f) * 0.75f + Rgb(1.0f, 0.0f, 0.5f) * 0.25f;
    EXPECT_EQ(set.color(mix, at(0, 0)), expected);
    EXPECT_FLOAT_EQ(set.number(mix, at(0, 0)), 0.75f * 0.4f + 0.25f * 0.5f);
    // The ends give one input exactly.
    EXPECT_EQ(set.color(set.add(MixTexture{use(a), use(b), FloatParam{0.0f}}), at(0, 0)), Rgb(0.2f, 0.4f, 0.6f));
    EXPECT_EQ(set.color(set.add(MixTexture{use(a), use(b), FloatParam{1.0f}}), at(0, 0)), Rgb(1.0f, 0.0f, 0.5f));
}

TEST(TextureSet, NestedTexturesEvaluateTheirInputsAtTheSamePoint) {
    TextureSet set;
    ImageTexture image;
    image.image = set.add_image(two_by_two());
    image.filter = TextureFilter::kPoint;
    const uint32_t img = set.add(image);
    const uint32_t dim = set.add(ScaleTexture{use(img), FloatParam{0.5f}});
    // Squares of 1/2: the bottom-left and top-right show the dimmed image, the others grey 0.3.
    const uint32_t checks = set.add(CheckerboardTexture{use(dim), ColorParam{Rgb(0.3f)},
                                                        UvTransform{Vec2f(2.0f, 2.0f), Vec2f(0.0f, 0.0f)}});
    // The amount is itself a checkerboard: 0 on even squares, 1 on odd ones.
    const uint32_t amount = set.add(CheckerboardTexture{ColorParam{Rgb(0.0f)}, ColorParam{Rgb(1.0f)},
                                                        UvTransform{Vec2f(2.0f, 2.0f), Vec2f(0.0f, 0.0f)}});
    const uint32_t mix = set.add(MixTexture{use(checks), ColorParam{Rgb(0.9f)}, use_number(amount)});
    EXPECT_EQ(set.color(checks, at(0.25f, 0.25f)), Rgb(0, 0, 0.5f));
    EXPECT_EQ(set.color(checks, at(0.75f, 0.75f)), Rgb(0, 0.5f, 0));
    EXPECT_EQ(set.color(checks, at(0.25f, 0.75f)), Rgb(0.3f));
    EXPECT_EQ(set.color(mix, at(0.75f, 0.25f)), Rgb(0.9f));
    EXPECT_EQ(set.color(mix, at(0.75f, 0.75f)), Rgb(0, 0.5f, 0));
    EXPECT_EQ(set.depth(img), 1);
    EXPECT_EQ(set.depth(dim), 2);
    EXPECT_EQ(set.depth(checks), 3);
    EXPECT_EQ(set.depth(mix), 4);
}

}  // namespace
}  // namespace candela
