// Texture image files (textures/texture_file.h): the sRGB decode of 8- and 16-bit files against
// the standard formula, linear files untouched, alpha, EXR/HDR/PFM values, the stb formats, headers
// and errors.
#include "candela/textures/texture_file.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"
#include "support/png_bytes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using testing::write_test_file;

// The sRGB EOTF of IEC 61966-2-1, in double, written out here rather than taken from candela.
double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// Within a few float roundings of the exact value.
void expect_close(float got, double expected, const std::string& what) {
    EXPECT_NEAR(double(got), expected, 4e-7 * expected + 1e-9) << what;
}

TEST(TextureFile, EightBitSrgbMatchesTheStandardFormula) {
    TempDir dir;
    std::vector<uint16_t> all(256);
    for (int v = 0; v < 256; ++v) all[size_t(v)] = uint16_t(v);
    write_test_file(dir / "ramp.png", test::make_png(256, 1, 8, 0, 1, all));
    const TextureImage image = read_texture_file(dir / "ramp.png", TextureColorspace::kSrgb);
    ASSERT_EQ(image.width, 256);
    ASSERT_EQ(image.channels, 1);
    EXPECT_EQ(image.bytes.size(), 256u);  // kept as bytes
    EXPECT_TRUE(image.floats.empty());
    for (int v = 0; v < 256; ++v)
        expect_close(image.texel(v, 0).rgb.r, srgb_to_linear(v / 255.0), "byte " + std::to_string(v));
}

TEST(TextureFile, SixteenBitSrgbMatchesTheStandardFormula) {
    TempDir dir;
    // Around the linear segment's end (0.04045 * 65535 = 2650.9) and across the range.
    const std::vector<uint16_t> samples = {0, 1, 2, 100, 2650, 2651, 30000, 65534, 65535};
    write_test_file(dir / "deep.png", test::make_png(int(samples.size()), 1, 16, 0, 1, samples));
    const TextureImage image = read_texture_file(dir / "deep.png", TextureColorspace::kSrgb);
    ASSERT_EQ(image.channels, 1);
    EXPECT_TRUE(image.bytes.empty());
    for (size_t i = 0; i < samples.size(); ++i)
        expect_close(image.texel(int(i), 0).rgb.r, srgb_to_linear(samples[i] / 65535.0),
                     "sample " + std::to_string(samples[i]));
}

TEST(TextureFile, LinearColorspaceIsUntouched) {
    TempDir dir;
    write_test_file(dir / "eight.png", test::make_png(3, 1, 8, 0, 1, {0, 51, 255}));
    const TextureImage eight = read_texture_file(dir / "eight.png", TextureColorspace::kLinear);
    for (int v = 0; v < 256; ++v) EXPECT_EQ(eight.byte_values[size_t(v)], float(v) / 255.0f);
    EXPECT_EQ(eight.texel(1, 0).rgb, Rgb(0.2f));
    write_test_file(dir / "sixteen.png", test::make_png(2, 1, 16, 0, 1, {1000, 65535}));
    const TextureImage sixteen = read_texture_file(dir / "sixteen.png", TextureColorspace::kLinear);
    EXPECT_EQ(sixteen.texel(0, 0).rgb, Rgb(1000.0f / 65535.0f));
    EXPECT_EQ(sixteen.texel(1, 0).rgb, Rgb(1.0f));
}

TEST(TextureFile, GammaColorspaceIsThePowerOfTheValue) {
    // pbrt-v4's GammaColorEncoding: (v / 255)^gamma, (v / 65535)^gamma for 16 bits.
    TempDir dir;
    std::vector<uint16_t> all(256);
    for (int v = 0; v < 256; ++v) all[size_t(v)] = uint16_t(v);
    write_test_file(dir / "ramp.png", test::make_png(256, 1, 8, 0, 1, all));
    const TextureImage eight = read_texture_file(dir / "ramp.png", TextureColorspace::kGamma, 2.2f);
    for (int v = 0; v < 256; ++v)
        expect_close(eight.texel(v, 0).rgb.r, std::pow(v / 255.0, double(2.2f)), "byte " + std::to_string(v));
    const std::vector<uint16_t> samples = {0, 1, 1000, 30000, 65535};
    write_test_file(dir / "deep.png", test::make_png(int(samples.size()), 1, 16, 0, 1, samples));
    const TextureImage sixteen = read_texture_file(dir / "deep.png", TextureColorspace::kGamma, 1.8f);
    for (size_t i = 0; i < samples.size(); ++i)
        expect_close(sixteen.texel(int(i), 0).rgb.r, std::pow(samples[i] / 65535.0, double(1.8f)),
                     "sample " + std::to_string(samples[i]));
}

TEST(TextureFile, RgbKeepsChannelsAndRowOrder) {
    TempDir dir;
    write_test_file(dir / "rgb.png", test::make_png(2, 2, 8, 2, 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0}));
    const TextureImage image = read_texture_file(dir / "rgb.png", TextureColorspace::kLinear);
    ASSERT_EQ(image.channels, 3);
    EXPECT_EQ(image.texel(0, 0).rgb, Rgb(1, 0, 0));  // the file's first row is y = 0 (the top)
    EXPECT_EQ(image.texel(1, 0).rgb, Rgb(0, 1, 0));
    EXPECT_EQ(image.texel(0, 1).rgb, Rgb(0, 0, 1));
    EXPECT_EQ(image.texel(1, 1).rgb, Rgb(0, 0, 0));
}

TEST(TextureFile, OpaqueAlphaIsDroppedOtherAlphaKeptLinear) {
    TempDir dir;
    write_test_file(dir / "opaque.png", test::make_png(2, 1, 8, 6, 4, {10, 20, 30, 255, 40, 50, 60, 255}));
    const TextureImage opaque = read_texture_file(dir / "opaque.png", TextureColorspace::kLinear);
    EXPECT_EQ(opaque.channels, 3);
    EXPECT_EQ(opaque.bytes.size(), 6u);
    EXPECT_EQ(opaque.texel(1, 0).rgb, Rgb(40.0f / 255, 50.0f / 255, 60.0f / 255));

    write_test_file(dir / "cutout.png", test::make_png(2, 1, 8, 6, 4, {10, 20, 30, 255, 40, 50, 60, 51}));
    const TextureImage cutout = read_texture_file(dir / "cutout.png", TextureColorspace::kSrgb);
    ASSERT_EQ(cutout.channels, 4);
    EXPECT_EQ(cutout.texel(1, 0).alpha, 0.2f);  // alpha is not sRGB-decoded
    expect_close(cutout.texel(1, 0).rgb.g, srgb_to_linear(50 / 255.0), "green");

    write_test_file(dir / "grey_alpha.png", test::make_png(1, 1, 16, 4, 2, {65535, 13107}));
    const TextureImage grey_alpha = read_texture_file(dir / "grey_alpha.png", TextureColorspace::kSrgb);
    ASSERT_EQ(grey_alpha.channels, 2);
    EXPECT_EQ(grey_alpha.texel(0, 0).rgb, Rgb(1.0f));
    EXPECT_EQ(grey_alpha.texel(0, 0).alpha, 13107.0f / 65535.0f);
}

TEST(TextureFile, FloatFormatsAreReadLinearAsImageIo) {
    TempDir dir;
    Image image(2, 1);
    image.at(0, 0) = Rgb(0.25f, 1.5f, 7.0f);
    image.at(1, 0) = Rgb(0.0f, 0.125f, 100.0f);
    for (const char* name : {"values.exr", "values.hdr", "values.pfm"}) {
        write_image(dir / name, image, DisplayEncoding{});
        const Image expected = read_image(dir / name);
        const TextureImage texture = read_texture_file(dir / name, TextureColorspace::kLinear);
        ASSERT_EQ(texture.channels, 3) << name;
        EXPECT_EQ(texture.texel(0, 0).rgb, expected.at(0, 0)) << name;
        EXPECT_EQ(texture.texel(1, 0).rgb, expected.at(1, 0)) << name;
    }
    // EXR and PFM hold these floats exactly.
    EXPECT_EQ(read_texture_file(dir / "values.exr", TextureColorspace::kLinear).texel(0, 0).rgb, image.at(0, 0));
    EXPECT_EQ(read_texture_file(dir / "values.pfm", TextureColorspace::kLinear).texel(1, 0).rgb, image.at(1, 0));
}

TEST(TextureFile, TgaBmpAndJpegAreRead) {
    TempDir dir;
    const std::vector<unsigned char> rgb = {200, 100, 50, 0, 64, 255, 7, 8, 9, 255, 255, 255};
    ASSERT_TRUE(stbi_write_tga((dir / "a.tga").c_str(), 2, 2, 3, rgb.data()));
    ASSERT_TRUE(stbi_write_bmp((dir / "a.bmp").c_str(), 2, 2, 3, rgb.data()));
    for (const char* name : {"a.tga", "a.bmp"}) {
        const TextureImage image = read_texture_file(dir / name, TextureColorspace::kLinear);
        ASSERT_EQ(image.width, 2) << name;
        ASSERT_EQ(image.channels, 3) << name;
        EXPECT_EQ(image.bytes, std::vector<uint8_t>(rgb.begin(), rgb.end())) << name;
    }
    // JPEG is lossy, but a flat grey image comes back flat within a code or two (stb writes
    // three components whatever it is given).
    const std::vector<unsigned char> grey(3 * 64, 128);
    ASSERT_TRUE(stbi_write_jpg((dir / "a.jpg").c_str(), 8, 8, 3, grey.data(), 95));
    const TextureImage jpeg = read_texture_file(dir / "a.jpg", TextureColorspace::kSrgb);
    ASSERT_EQ(jpeg.width, 8);
    ASSERT_EQ(jpeg.channels, 3);
    for (uint8_t b : jpeg.bytes) EXPECT_NEAR(int(b), 128, 2);
    expect_close(jpeg.byte_values[128], srgb_to_linear(128 / 255.0), "jpeg table");
}

TEST(TextureFile, HeaderGivesSizeChannelsAndStorage) {
    TempDir dir;
    write_test_file(dir / "rgb.png", test::make_png(3, 2, 8, 2, 3, std::vector<uint16_t>(18, 7)));
    write_test_file(dir / "deep.PNG", test::make_png(1, 4, 16, 4, 2, std::vector<uint16_t>(8, 7)));
    const auto rgb = read_texture_file_header(dir / "rgb.png");
    ASSERT_TRUE(rgb);
    EXPECT_EQ(rgb->width, 3);
    EXPECT_EQ(rgb->height, 2);
    EXPECT_EQ(rgb->channels, 3);
    EXPECT_EQ(rgb->bytes_per_channel, 1);
    EXPECT_EQ(rgb->file_bytes, std::filesystem::file_size(dir / "rgb.png"));
    const auto deep = read_texture_file_header(dir / "deep.PNG");
    ASSERT_TRUE(deep);
    EXPECT_EQ(deep->channels, 2);
    EXPECT_EQ(deep->bytes_per_channel, 4);  // 16-bit values are kept as floats
    Image one(1, 1);
    write_image(dir / "one.exr", one, DisplayEncoding{});
    EXPECT_FALSE(read_texture_file_header(dir / "one.exr"));
}

TEST(TextureFile, CorruptFileIsASceneErrorNamingIt) {
    TempDir dir;
    write_test_file(dir / "bad.png", "this is not an image");
    for (auto read : {+[](const std::filesystem::path& f) { (void)read_texture_file_header(f); },
                      +[](const std::filesystem::path& f) { (void)read_texture_file(f, TextureColorspace::kSrgb); }}) {
        try {
            read(dir / "bad.png");
            ADD_FAILURE() << "expected a SceneError";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().file, (dir / "bad.png").string());
            EXPECT_NE(e.message().find("not a PNG, JPEG, TGA or BMP image"), std::string::npos) << e.message();
        }
    }
}

TEST(TextureFile, KnowsItsExtensions) {
    for (const char* name : {"a.png", "a.JPG", "a.jpeg", "a.tga", "a.bmp", "a.exr", "a.hdr", "a.pfm"})
        EXPECT_TRUE(is_texture_file_extension(name)) << name;
    for (const char* name : {"a.gif", "a.psd", "a", "a.png.txt"}) EXPECT_FALSE(is_texture_file_extension(name)) << name;
    EXPECT_TRUE(is_float_texture_file("sky.EXR"));
    EXPECT_FALSE(is_float_texture_file("wood.png"));
}

}  // namespace
}  // namespace candela
