// Image lookups (textures/texture_image.h): exact values at texel centres, bilinear weights
// between them, each wrap mode at and beyond the edges, point filtering, the orientation of
// (s, t), and how a texel is read as a number.
#include "candela/textures/texture_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace candela {
namespace CANDELA_UNITY_ID {

// A float image of `channels` values per texel, row-major from the top row.
TextureImage float_image(int width, int height, int channels, std::vector<float> values) {
    TextureImage image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.floats = std::move(values);
    EXPECT_EQ(image.floats.size(), size_t(width * height * channels));
    return image;
}

// A 4x2 RGB image whose texel (x, y) is (x, y, 10 + x + 4 y): every texel distinct.
TextureImage numbered_image() {
    std::vector<float> v;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) v.insert(v.end(), {float(x), float(y), float(10 + x + 4 * y)});
    return float_image(4, 2, 3, v);
}

// The texture coordinates of texel (x, y)'s centre ((0, 0) the bottom-left corner).
Vec2f centre(const TextureImage& image, int x, int y) {
    return Vec2f((float(x) + 0.5f) / float(image.width), 1.0f - (float(y) + 0.5f) / float(image.height));
}

Rgb numbered(int x, int y) { return Rgb(float(x), float(y), float(10 + x + 4 * y)); }

constexpr TextureWrap kWraps[] = {TextureWrap::kRepeat, TextureWrap::kClamp, TextureWrap::kBlack};

TEST(TextureImage, ExactAtTexelCentresWithEitherFilterAndAnyWrap) {
    const TextureImage image = numbered_image();
    for (TextureWrap wrap : kWraps)
        for (TextureFilter filter : {TextureFilter::kBilinear, TextureFilter::kPoint})
            for (int y = 0; y < 2; ++y)
                for (int x = 0; x < 4; ++x) {
                    const RgbAlpha v = image.lookup(centre(image, x, y), wrap, filter);
                    EXPECT_EQ(v.rgb, numbered(x, y)) << x << ", " << y;
                    EXPECT_EQ(v.alpha, 1.0f);
                }
}

TEST(TextureImage, TopRowIsAtTopOfUvSquare) {
    // uv (0, 0) is the bottom-left corner: the file's last row; v = 1 the first.
    const TextureImage image = numbered_image();
    EXPECT_EQ(image.lookup({0.01f, 0.01f}, TextureWrap::kClamp, TextureFilter::kPoint).rgb, numbered(0, 1));
    EXPECT_EQ(image.lookup({0.99f, 0.99f}, TextureWrap::kClamp, TextureFilter::kPoint).rgb, numbered(3, 0));
}

TEST(TextureImage, BilinearWeightsBetweenCentres) {
    const TextureImage image = numbered_image();
    const Vec2f a = centre(image, 1, 0), b = centre(image, 2, 0), c = centre(image, 1, 1);
    // A quarter of the way from texel 1 to texel 2, in x: weights 3/4 and 1/4.
    const Vec2f quarter(a.x + 0.25f * (b.x - a.x), a.y);
    EXPECT_EQ(image.lookup(quarter, TextureWrap::kRepeat, TextureFilter::kBilinear).rgb,
              numbered(1, 0) * 0.75f + numbered(2, 0) * 0.25f);
    // Halfway down from row 0 to row 1 and halfway across: the mean of four texels.
    const Vec2f middle(0.5f * (a.x + b.x), 0.5f * (a.y + c.y));
    const Rgb mean = (numbered(1, 0) + numbered(2, 0) + numbered(1, 1) + numbered(2, 1)) * 0.25f;
    const Rgb got = image.lookup(middle, TextureWrap::kRepeat, TextureFilter::kBilinear).rgb;
    EXPECT_NEAR(got.r, mean.r, 1e-6f);
    EXPECT_NEAR(got.g, mean.g, 1e-6f);
    EXPECT_NEAR(got.b, mean.b, 1e-5f);
}

TEST(TextureImage, RepeatWrapsAcrossTheSeamAndBeyond) {
    const TextureImage image = numbered_image();
    // u = 0 lies halfway between the last column's centre (wrapped) and the first's.
    const Vec2f edge(0.0f, centre(image, 0, 0).y);
    EXPECT_EQ(image.lookup(edge, TextureWrap::kRepeat, TextureFilter::kBilinear).rgb,
              numbered(3, 0) * 0.5f + numbered(0, 0) * 0.5f);
    // Whole periods away, the same texel.
    for (float shift : {1.0f, -1.0f, 3.0f, -7.0f}) {
        const Vec2f p = centre(image, 2, 1);
        EXPECT_EQ(image.lookup({p.x + shift, p.y}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb, numbered(2, 1));
        EXPECT_EQ(image.lookup({p.x, p.y + shift}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb, numbered(2, 1));
    }
}

TEST(TextureImage, ClampExtendsTheEdgeTexels) {
    const TextureImage image = numbered_image();
    const float row0 = centre(image, 0, 0).y;
    EXPECT_EQ(image.lookup({0.0f, row0}, TextureWrap::kClamp, TextureFilter::kBilinear).rgb, numbered(0, 0));
    EXPECT_EQ(image.lookup({-5.0f, row0}, TextureWrap::kClamp, TextureFilter::kBilinear).rgb, numbered(0, 0));
    EXPECT_EQ(image.lookup({1.0f, row0}, TextureWrap::kClamp, TextureFilter::kBilinear).rgb, numbered(3, 0));
    EXPECT_EQ(image.lookup({7.5f, 9.0f}, TextureWrap::kClamp, TextureFilter::kPoint).rgb, numbered(3, 0));
    EXPECT_EQ(image.lookup({7.5f, -9.0f}, TextureWrap::kClamp, TextureFilter::kPoint).rgb, numbered(3, 1));
}

TEST(TextureImage, BlackIsBlackAndTransparentOutside) {
    const TextureImage image = numbered_image();
    const float row0 = centre(image, 0, 0).y;
    // At the edge, half the first column and half black (alpha too).
    const RgbAlpha edge = image.lookup({0.0f, row0}, TextureWrap::kBlack, TextureFilter::kBilinear);
    EXPECT_EQ(edge.rgb, numbered(0, 0) * 0.5f);
    EXPECT_EQ(edge.alpha, 0.5f);
    for (TextureFilter filter : {TextureFilter::kBilinear, TextureFilter::kPoint}) {
        const RgbAlpha outside = image.lookup({-0.5f, row0}, TextureWrap::kBlack, filter);
        EXPECT_EQ(outside.rgb, Rgb(0.0f));
        EXPECT_EQ(outside.alpha, 0.0f);
        EXPECT_EQ(image.lookup({0.5f, 1.5f}, TextureWrap::kBlack, filter).rgb, Rgb(0.0f));
    }
}

TEST(TextureImage, PointFilterChangesAtTexelBoundaries) {
    const TextureImage image = numbered_image();
    const float row0 = centre(image, 0, 0).y;
    // The boundary between columns 1 and 2 is u = 0.5: just inside each side.
    EXPECT_EQ(image.lookup({std::nextafter(0.5f, 0.0f), row0}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb,
              numbered(1, 0));
    EXPECT_EQ(image.lookup({std::nextafter(0.5f, 1.0f), row0}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb,
              numbered(2, 0));
    // Rows: v above 0.5 is row 0 (the top), below it row 1.
    EXPECT_EQ(image.lookup({0.1f, std::nextafter(0.5f, 1.0f)}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb,
              numbered(0, 0));
    EXPECT_EQ(image.lookup({0.1f, std::nextafter(0.5f, 0.0f)}, TextureWrap::kRepeat, TextureFilter::kPoint).rgb,
              numbered(0, 1));
}

TEST(TextureImage, BytesDecodeThroughTheTable) {
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.channels = 4;
    image.bytes = {0, 1, 2, 255, 3, 4, 5, 51};
    for (int v = 0; v < 256; ++v) image.byte_values[size_t(v)] = float(v) * 0.5f;
    const RgbAlpha a = image.texel(0, 0), b = image.texel(1, 0);
    EXPECT_EQ(a.rgb, Rgb(0.0f, 0.5f, 1.0f));
    EXPECT_EQ(a.alpha, 1.0f);
    EXPECT_EQ(b.rgb, Rgb(1.5f, 2.0f, 2.5f));
    EXPECT_EQ(b.alpha, 51.0f / 255.0f);  // alpha is linear, never through the colour table
}

TEST(TextureImage, NumberIsGreyAlphaOrChannelAverage) {
    const TextureImage grey = float_image(1, 1, 1, {0.3f});
    EXPECT_EQ(grey.number(grey.texel(0, 0)), 0.3f);
    const TextureImage grey_alpha = float_image(1, 1, 2, {0.3f, 0.7f});
    EXPECT_EQ(grey_alpha.texel(0, 0).rgb, Rgb(0.3f));
    EXPECT_EQ(grey_alpha.number(grey_alpha.texel(0, 0)), 0.7f);
    const TextureImage rgb = float_image(1, 1, 3, {0.3f, 0.6f, 0.9f});
    EXPECT_FLOAT_EQ(rgb.number(rgb.texel(0, 0)), 0.6f);
    const TextureImage rgba = float_image(1, 1, 4, {0.3f, 0.6f, 0.9f, 0.25f});
    EXPECT_EQ(rgba.number(rgba.texel(0, 0)), 0.25f);
}

TEST(TextureImage, AnyCoordinateLandsOnATexel) {
    // Coordinates far out or not finite (a mesh file may hold anything) must not be undefined
    // behaviour: they saturate onto some texel, or black.
    const TextureImage image = numbered_image();
    const float inf = std::numeric_limits<float>::infinity();
    for (float u : {1e30f, -1e30f, inf, -inf, std::nanf("")})
        for (TextureWrap wrap : kWraps)
            for (TextureFilter filter : {TextureFilter::kBilinear, TextureFilter::kPoint}) {
                const RgbAlpha v = image.lookup({u, 0.25f}, wrap, filter);
                EXPECT_TRUE(v.rgb.is_finite()) << u;
                EXPECT_GE(v.alpha, 0.0f);
                EXPECT_LE(v.alpha, 1.0f);
            }
}

TEST(TextureImage, MemoryIsTexelsAndTable) {
    TextureImage bytes;
    bytes.bytes.resize(300);
    EXPECT_EQ(bytes.memory_bytes(), 300u + 256 * sizeof(float));
    EXPECT_EQ(numbered_image().memory_bytes(), 24 * sizeof(float) + 256 * sizeof(float));
}

}  // namespace
}  // namespace candela
