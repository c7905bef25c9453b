#pragma once
// PNG files built byte by byte, for tests that need what candela's writer never produces (16-bit,
// grey, alpha): a zlib stream of stored (uncompressed) deflate blocks needs no compressor.
#include <cstdint>
#include <string>
#include <vector>

namespace candela::test {

inline uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

inline void append_be32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xffu);
}

inline std::string chunk(const std::string& type, const std::string& data) {
    std::string out;
    append_be32(out, uint32_t(data.size()));
    out += type + data;
    append_be32(out, crc32(type + data));
    return out;
}

// A zlib stream (RFC 1950) holding `raw` in one stored deflate block (RFC 1951, 3.2.4).
inline std::string zlib_stored(const std::string& raw) {
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

// A PNG of `samples`, row-major from the top row, channels interleaved, each sample bit_depth bits
// (8 or 16). color_type is PNG's: 0 grey, 2 RGB, 4 grey and alpha, 6 RGBA, with `channels` to
// match. The image data must stay under 64 KiB (one stored block).
inline std::string make_png(int width, int height, int bit_depth, int color_type, int channels,
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

}  // namespace candela::test
