// PNG files our writer never produces (16-bit, grey, with alpha), built byte by byte
// (support/png_bytes.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "candela/image/tonemap.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"
#include "support/png_bytes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using test::make_png;

TEST(PngFile, Reads16BitWithFullPrecision) {
    TempDir dir;
    const std::vector<uint16_t> samples = {0, 65535, 32768, 1000, 2, 40000, 7, 8, 9, 65534, 65533, 1};
    testing::write_test_file(dir / "deep.png", make_png(2, 2, 16, 2, 3, samples));
    const Image image = read_image(dir / "deep.png");
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 2);
    for (size_t i = 0; i < samples.size(); ++i)
        EXPECT_FLOAT_EQ(image.pixels[i / 3][int(i % 3)], decode_srgb(float(samples[i]) / 65535.0f)) << i;
    EXPECT_NE(image.at(0, 0).b, image.at(1, 1).b);  // 32768 vs 1: distinct, not truncated to 8 bits
}

TEST(PngFile, GreyIsReplicatedAndOrientationKept) {
    TempDir dir;
    testing::write_test_file(dir / "grey.png", make_png(3, 2, 8, 0, 1, {0, 51, 102, 153, 204, 255}));
    const Image image = read_image(dir / "grey.png");
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), Rgb(0.0f));
    EXPECT_EQ(image.at(1, 0), Rgb(decode_srgb(0.2f)));
    EXPECT_EQ(image.at(0, 1), Rgb(decode_srgb(0.6f)));
    EXPECT_NEAR(image.at(2, 1).r, 1.0f, 1e-6f);
}

TEST(PngFile, AlphaIsDropped) {
    TempDir dir;
    testing::write_test_file(dir / "rgba.png", make_png(1, 1, 8, 6, 4, {255, 0, 51, 0}));
    const Image image = read_image(dir / "rgba.png");
    EXPECT_NEAR(image.at(0, 0).r, 1.0f, 1e-6f);
    EXPECT_EQ(image.at(0, 0).g, 0.0f);
    EXPECT_EQ(image.at(0, 0).b, decode_srgb(0.2f));
}

TEST(PngFile, WrittenBytesAreTheDisplayBytes) {
    TempDir dir;
    DisplayEncoding film;
    film.tonemap = Tonemap::kAces;
    const Image image = testing::pattern_image(5, 3, 0.0f, 4.0f);
    write_image(dir / "out.png", image, film);
    const Image read = read_image(dir / "out.png");
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            const auto bytes = to_display_bytes(image.at(x, y), film);
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(read.at(x, y)[c], decode_srgb(float(bytes[size_t(c)]) / 255.0f)) << x << ", " << y;
        }
}

}  // namespace
}  // namespace candela
