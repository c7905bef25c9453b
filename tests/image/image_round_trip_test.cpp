// write_image then read_image, per format, on non-square odd sizes so that a flipped, mirrored
// or transposed image fails; (0, 0) is the top-left pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "candela/image/tonemap.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using testing::pattern_image;

// Distinct corners whatever the pattern: a flip or mirror swaps two of them.
void mark_corners(Image& image, float scale) {
    image.at(0, 0) = Rgb(1.0f, 0.0f, 0.0f) * scale;
    image.at(image.width - 1, 0) = Rgb(0.0f, 1.0f, 0.0f) * scale;
    image.at(0, image.height - 1) = Rgb(0.0f, 0.0f, 1.0f) * scale;
    image.at(image.width - 1, image.height - 1) = Rgb(1.0f, 1.0f, 0.0f) * scale;
}

void expect_corners(const Image& image, float scale, float tolerance) {
    const auto expect_near = [&](int x, int y, Rgb expected) {
        const Rgb got = image.at(x, y);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], expected[c] * scale, tolerance) << "corner (" << x << ", " << y << ") channel " << c;
    };
    expect_near(0, 0, Rgb(1.0f, 0.0f, 0.0f));
    expect_near(image.width - 1, 0, Rgb(0.0f, 1.0f, 0.0f));
    expect_near(0, image.height - 1, Rgb(0.0f, 0.0f, 1.0f));
    expect_near(image.width - 1, image.height - 1, Rgb(1.0f, 1.0f, 0.0f));
}

Image round_trip(const Image& image, const std::string& name, const DisplayEncoding& film = {}) {
    TempDir dir;
    write_image(dir / name, image, film);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});  // no temporary left behind
    return read_image(dir / name);
}

class LosslessRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(LosslessRoundTrip, KeepsEveryFloatAndOrientation) {
    for (auto [w, h] : {std::pair{7, 3}, std::pair{3, 7}, std::pair{1, 1}, std::pair{16, 5}}) {
        Image image = pattern_image(w, h, -2.0f, 1000.0f);  // negatives and HDR values survive
        mark_corners(image, 3.5f);
        const Image read = round_trip(image, std::string("img") + GetParam());
        ASSERT_EQ(read.width, w);
        ASSERT_EQ(read.height, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) ASSERT_EQ(read.at(x, y), image.at(x, y)) << x << ", " << y;
        if (w > 1 && h > 1) expect_corners(read, 3.5f, 0.0f);
    }
}

INSTANTIATE_TEST_SUITE_P(FloatFormats, LosslessRoundTrip, ::testing::Values(".exr", ".pfm", ".EXR", ".Pfm"));

TEST(RgbeRoundTrip, KeepsValuesWithinRgbePrecision) {
    // Width 7 is stored flat, 37 run-length encoded: both decoder paths.
    for (auto [w, h] : {std::pair{7, 3}, std::pair{37, 5}, std::pair{3, 9}}) {
        Image image = pattern_image(w, h, 0.001f, 5000.0f);
        for (int x = 0; x < w; ++x) image.at(x, 1) = Rgb(2.0f);  // a constant row makes long runs
        mark_corners(image, 42.0f);
        const Image read = round_trip(image, "img.hdr");
        ASSERT_EQ(read.width, w);
        ASSERT_EQ(read.height, h);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                // 8-bit mantissas share the exponent of the largest channel.
                const float tolerance = image.at(x, y).max_component() / 128.0f;
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(read.at(x, y)[c], image.at(x, y)[c], tolerance) << x << ", " << y << " channel " << c;
            }
        }
        expect_corners(read, 42.0f, 0.0f);  // powers of two and zeros are exact in RGBE
    }
}

TEST(RgbeRoundTrip, NegativeValuesBecomeZero) {
    Image image(2, 1);
    image.at(0, 0) = Rgb(-1.0f, 0.5f, 2.0f);
    image.at(1, 0) = Rgb(-3.0f);
    const Image read = round_trip(image, "neg.hdr");
    EXPECT_EQ(read.at(0, 0), Rgb(0.0f, 0.5f, 2.0f));
    EXPECT_EQ(read.at(1, 0), Rgb(0.0f));
}

TEST(PngRoundTrip, ReadsBackTheToneMappedEncodedValueDecoded) {
    for (Tonemap op : {Tonemap::kClamp, Tonemap::kReinhard}) {
        DisplayEncoding film;
        film.tonemap = op;
        Image image = pattern_image(7, 3, 0.0f, 1.5f);
        mark_corners(image, 1.0f);
        const Image read = round_trip(image, "img.png", film);
        ASSERT_EQ(read.width, 7);
        ASSERT_EQ(read.height, 3);
        for (int y = 0; y < 3; ++y) {
            for (int x = 0; x < 7; ++x) {
                const Rgb mapped = tonemap(image.at(x, y), film);
                for (int c = 0; c < 3; ++c) {
                    // Within half a code value in the encoded domain, then decoded.
                    const float encoded = encode_srgb(mapped[c]);
                    const float lo = decode_srgb(std::max(encoded - 0.5f / 255.0f, 0.0f));
                    const float hi = decode_srgb(std::min(encoded + 0.5f / 255.0f, 1.0f));
                    EXPECT_GE(read.at(x, y)[c], lo - 1e-6f) << x << ", " << y << " channel " << c;
                    EXPECT_LE(read.at(x, y)[c], hi + 1e-6f) << x << ", " << y << " channel " << c;
                }
            }
        }
        if (op == Tonemap::kClamp) expect_corners(read, 1.0f, 1e-6f);  // codes 0 and 255
    }
}

TEST(PpmWrite, WritesSmallptPlainText) {
    TempDir dir;
    Image image(2, 1);
    image.at(0, 0) = Rgb(1.0f, 0.0f, 0.0f);
    image.at(1, 0) = Rgb(0.0f, 0.5f, 4.0f);
    write_image(dir / "out.ppm", image, DisplayEncoding{});  // clamp, sRGB: 0.5 -> 0.73536 -> 188
    EXPECT_EQ(testing::read_test_file(dir / "out.ppm"), "P3\n2 1\n255\n255 0 0 0 188 255 ");
}

TEST(PpmWrite, RowsRunTopToBottom) {
    TempDir dir;
    Image image(1, 2);
    image.at(0, 0) = Rgb(1.0f);
    DisplayEncoding film;
    film.transfer = Transfer::kGamma;
    write_image(dir / "out.PPM", image, film);
    EXPECT_EQ(testing::read_test_file(dir / "out.PPM"), "P3\n1 2\n255\n255 255 255 0 0 0 ");
}

TEST(ImageWrite, OverwritesAnExistingImage) {
    TempDir dir;
    write_image(dir / "img.pfm", pattern_image(5, 4), DisplayEncoding{});
    const Image second = pattern_image(3, 2, 7.0f, 8.0f);
    write_image(dir / "img.pfm", second, DisplayEncoding{});
    const Image read = read_image(dir / "img.pfm");
    ASSERT_EQ(read.width, 3);
    ASSERT_EQ(read.height, 2);
    EXPECT_EQ(read.pixels, second.pixels);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"img.pfm"});
}

}  // namespace
}  // namespace candela
