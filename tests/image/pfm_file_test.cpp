// PFM byte layout: header, byte order from the scale's sign, rows bottom to top.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;

std::string float_bytes(const std::vector<float>& values, bool big_endian) {
    std::string out;
    for (float v : values) {
        const auto bits = std::bit_cast<uint32_t>(v);
        for (int i = 0; i < 4; ++i) {
            const int shift = big_endian ? 24 - 8 * i : 8 * i;
            out += char((bits >> shift) & 0xffu);
        }
    }
    return out;
}

TEST(PfmFile, WritesLittleEndianBottomRowFirst) {
    TempDir dir;
    Image image(2, 2);
    image.at(0, 0) = Rgb(1.0f, 2.0f, 3.0f);  // top-left
    image.at(1, 0) = Rgb(4.0f, 5.0f, 6.0f);
    image.at(0, 1) = Rgb(7.0f, 8.0f, 9.0f);  // bottom-left: stored first
    image.at(1, 1) = Rgb(10.0f, 11.0f, 12.0f);
    write_image(dir / "a.pfm", image, DisplayEncoding{});
    const std::string expected =
        "PF\n2 2\n-1\n" + float_bytes({7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6}, false);
    EXPECT_EQ(testing::read_test_file(dir / "a.pfm"), expected);
}

TEST(PfmFile, ReadsBigEndianGreyAndScale) {
    TempDir dir;
    // Positive scale: big-endian; 2 multiplies the values (pbrt's reading).
    testing::write_test_file(dir / "grey.pfm", "Pf\n3 2\n2.0\n" + float_bytes({1, 2, 3, 4, 5, 6}, true));
    const Image image = read_image(dir / "grey.pfm");
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), Rgb(8.0f));  // the last stored row is the top
    EXPECT_EQ(image.at(2, 0), Rgb(12.0f));
    EXPECT_EQ(image.at(0, 1), Rgb(2.0f));
    EXPECT_EQ(image.at(2, 1), Rgb(6.0f));
}

TEST(PfmFile, AcceptsOtherWhitespaceInHeader) {
    TempDir dir;
    testing::write_test_file(dir / "a.pfm", "PF 1  1 -1.0\n" + float_bytes({0.5f, 0.25f, 0.125f}, false));
    EXPECT_EQ(read_image(dir / "a.pfm").at(0, 0), Rgb(0.5f, 0.25f, 0.125f));
}

}  // namespace
}  // namespace candela
