// PNG files our writer never produces (16-bit, grey, with alpha), built byte by byte: a zlib
// stream of stored (uncompressed) blocks needs no compressor.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "candela/film/tonemap.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace {

using testing::TempDir;

uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void append_be32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xffu);
}

std::string chunk(const std::string& type, const std::string& data) {
    std::string out;
    append_be32(out, uint32_t(data.size()));
    out += type + data;
    append_be32(out, crc32(type + data));
    return out;
}

// A zlib stream (RFC 1950) holding `raw` in one stored deflate block (RFC 1951, 3.2.4).
std::string zlib_stored(const std::string& raw) {
    std::string out = "\x78\x01";
    out += '\x01';  // final block, stored
    const auto len = uint16_t(raw.size());
    out += char(len & 0xffu);
    out += char(len >> 8);
    out += char(~len & 0xffu);
    out += char((~len >> 8) & 0xffu);
    out += raw;
    uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521u;
        b = (b + a) % 65521u;
    }
    append_be32(out, (b << 16) | a);
    return out;
}

// `samples` row-major, channels interleaved, each sample bit_depth bits (8 or 16), big-endian.
std::string make_png(int width, int height, int bit_depth, int color_type, int channels,
                     const std::vector<uint16_t>& samples) {
    std::string ihdr;
    append_be32(ihdr, uint32_t(width));
    append_be32(ihdr, uint32_t(height));
    ihdr += char(bit_depth);
    ihdr += char(color_type);
    ihdr += std::string(3, '\0');  // deflate, adaptive filtering, no interlace
    std::string raw;
    size_t i = 0;
    for (int y = 0; y < height; ++y) {
        raw += '\0';  // filter: none
        for (int s = 0; s < width * channels; ++s, ++i) {
            if (bit_depth == 16) raw += char(samples[i] >> 8);
            raw += char(samples[i] & 0xffu);
        }
    }
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", zlib_stored(raw)) +
           chunk("IEND", "");
}

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
    FilmSettings film;
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
