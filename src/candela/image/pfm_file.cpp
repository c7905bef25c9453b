// Portable float map: a text header "PF" (RGB) or "Pf" (grey), width and height, and a scale
// whose sign gives the byte order (negative: little-endian), one whitespace character, then
// 32-bit floats with the rows stored bottom to top. A scale other than +-1 multiplies the
// values, as pbrt reads it.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "candela/core/atomic_file.h"
#include "candela/image/image_formats.h"

namespace candela::image_formats {

namespace fs = std::filesystem;

namespace {

// Reads the header's whitespace-separated tokens, remembering where the pixel data starts.
class HeaderReader {
  public:
    HeaderReader(const fs::path& file, const std::string& bytes) : file_(file), bytes_(bytes) {}

    std::string token(const char* what) {
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
        const size_t start = pos_;
        while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_])) && pos_ - start < 64)
            ++pos_;
        if (pos_ == start) fail(file_, std::string("truncated PFM header: expected ") + what);
        return bytes_.substr(start, pos_ - start);
    }

    int64_t integer(const char* what) {
        const std::string t = token(what);
        size_t used = 0;
        long long value = 0;
        try {
            value = std::stoll(t, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != t.size()) fail(file_, std::string("corrupt PFM header: expected ") + what + ", got \"" + t + "\"");
        return value;
    }

    float number(const char* what) {
        const std::string t = token(what);
        size_t used = 0;
        float value = 0.0f;
        try {
            value = std::stof(t, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != t.size() || !std::isfinite(value))
            fail(file_, std::string("corrupt PFM header: expected ") + what + ", got \"" + t + "\"");
        return value;
    }

    // The single whitespace character that ends the header.
    size_t data_start() {
        if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_])))
            fail(file_, "corrupt PFM header: expected a line break after the scale");
        return pos_ + 1;
    }

  private:
    const fs::path& file_;
    const std::string& bytes_;
    size_t pos_ = 0;
};

float load_float(const char* bytes, bool little_endian) {
    uint32_t bits = 0;
    std::memcpy(&bits, bytes, sizeof(bits));
    if (little_endian != (std::endian::native == std::endian::little)) bits = __builtin_bswap32(bits);
    return std::bit_cast<float>(bits);
}

void append_little_endian(std::string& out, float value) {
    uint32_t bits = std::bit_cast<uint32_t>(value);
    if constexpr (std::endian::native != std::endian::little) bits = __builtin_bswap32(bits);
    char bytes[4];
    std::memcpy(bytes, &bits, sizeof(bits));
    out.append(bytes, sizeof(bytes));
}

}  // namespace

Image read_pfm(const fs::path& file) {
    const std::string bytes = read_file_contents(file);
    HeaderReader header(file, bytes);
    const std::string magic = header.token("\"PF\" or \"Pf\"");
    if (magic != "PF" && magic != "Pf")
        fail(file, "not a PFM image: expected \"PF\" or \"Pf\" at the start, got \"" + magic.substr(0, 16) + "\"");
    const int channels = magic == "PF" ? 3 : 1;
    const int64_t width = header.integer("the width");
    const int64_t height = header.integer("the height");
    check_dimensions(file, width, height);
    const float scale = header.number("the scale");
    if (scale == 0.0f) fail(file, "corrupt PFM header: the scale must not be 0");
    const size_t start = header.data_start();

    const size_t needed = size_t(width) * size_t(height) * size_t(channels) * sizeof(float);
    const size_t available = bytes.size() - std::min(start, bytes.size());
    if (available < needed)
        fail(file, "truncated PFM image: expected " + std::to_string(needed) + " bytes of pixel data, found " +
                       std::to_string(available));

    const bool little_endian = scale < 0.0f;
    const float multiplier = std::abs(scale);
    Image image(static_cast<int>(width), static_cast<int>(height));
    const char* data = bytes.data() + start;
    for (int y = 0; y < image.height; ++y) {
        const char* row = data + size_t(image.height - 1 - y) * size_t(width) * size_t(channels) * sizeof(float);
        for (int x = 0; x < image.width; ++x) {
            const char* p = row + size_t(x) * size_t(channels) * sizeof(float);
            float v[3];
            for (int c = 0; c < channels; ++c) v[c] = load_float(p + size_t(c) * sizeof(float), little_endian);
            image.at(x, y) = channels == 3 ? Rgb(v[0], v[1], v[2]) : Rgb(v[0]);
            if (multiplier != 1.0f) image.at(x, y) *= multiplier;
        }
    }
    return image;
}

void write_pfm(const fs::path& file, const Image& image) {
    std::string out = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1\n";
    out.reserve(out.size() + image.pixels.size() * 3 * sizeof(float));
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            const Rgb& p = image.at(x, y);
            append_little_endian(out, p.r);
            append_little_endian(out, p.g);
            append_little_endian(out, p.b);
        }
    }
    write_contents_atomically(file, out);
}

}  // namespace candela::image_formats
