// Radiance RGBE (.hdr), after Greg Ward's format description ("Real Pixels", Graphics Gems II,
// and the Radiance file format notes). Read by our own decoder rather than stb_image, because
// stb decodes a truncated file silently as black rows; an environment map cut short must be an
// error. Written with stb_image_write.
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/image/image_formats.h"

namespace candela::image_formats {

namespace fs = std::filesystem;

namespace {

class RgbeReader {
  public:
    RgbeReader(const fs::path& file, const std::string& bytes) : file_(file), bytes_(bytes) {}

    Image read() {
        read_header();
        check_data_size();
        Image image(width_, height_);
        std::vector<unsigned char> scanline(size_t(width_) * 4);
        for (int y = 0; y < height_; ++y) {
            read_scanline(y, scanline);
            for (int x = 0; x < width_; ++x) image.at(x, y) = decode(&scanline[size_t(x) * 4]);
        }
        return image;
    }

  private:
    // Header lines up to an empty line, then the resolution line "-Y height +X width" (the
    // standard orientation: rows top to bottom, pixels left to right).
    void read_header() {
        const std::string_view magic = line();
        if (magic.substr(0, 2) != "#?")
            fail(file_, "not a Radiance HDR image: expected \"#?RADIANCE\" at the start");
        for (;;) {
            if (pos_ >= bytes_.size()) fail(file_, "truncated Radiance HDR header");
            const std::string_view l = line();
            if (l.empty()) break;
            // EXPOSURE and other header variables are ignored, as stb_image and pbrt do.
            if (l.substr(0, 7) == "FORMAT=" && l != "FORMAT=32-bit_rle_rgbe")
                fail(file_, "unsupported Radiance HDR format \"" + std::string(l.substr(7)) +
                                "\"; expected 32-bit_rle_rgbe");
        }
        const std::string resolution(line());
        long long height = 0, width = 0;
        int used = 0;
        if (std::sscanf(resolution.c_str(), "-Y %lld +X %lld%n", &height, &width, &used) != 2 ||
            size_t(used) != resolution.size())
            fail(file_, "unsupported or corrupt Radiance HDR resolution line \"" + resolution.substr(0, 40) +
                            "\"; expected \"-Y height +X width\"");
        check_dimensions(file_, width, height);
        width_ = int(width);
        height_ = int(height);
    }

    // Before the image is allocated: the rows the header declares must fit in what is left of the
    // file, even at the best compression (runs of 127 pixels in 2 bytes, per component), so a
    // 100-byte file claiming 65536x4096 is refused without allocating 3 GiB.
    void check_data_size() const {
        const uint64_t w = uint64_t(width_), h = uint64_t(height_);
        const uint64_t left = bytes_.size() - pos_;
        if (width_ < 8 || width_ >= 32768) {  // flat rows only: the row where the data ends is known
            if (left / (4 * w) < h)
                fail(file_, "truncated Radiance HDR image: data ends in row " + std::to_string(left / (4 * w)) +
                                " of " + std::to_string(height_));
            return;
        }
        const uint64_t min_row = std::min<uint64_t>(4 + 4 * 2 * ((w + 126) / 127), 4 * w);
        if (left / min_row < h)
            fail(file_, "truncated Radiance HDR image: " + std::to_string(width_) + "x" + std::to_string(height_) +
                            " pixels need at least " + std::to_string(min_row * h) + " bytes of data, the file has " +
                            std::to_string(left) + " after its header");
    }

    std::string_view line() {
        const size_t end = bytes_.find('\n', pos_);
        const size_t stop = end == std::string::npos ? bytes_.size() : end;
        std::string_view l(bytes_.data() + pos_, stop - pos_);
        pos_ = end == std::string::npos ? bytes_.size() : end + 1;
        return l;
    }

    unsigned char byte(int y) {
        if (pos_ >= bytes_.size())
            fail(file_, "truncated Radiance HDR image: data ends in row " + std::to_string(y) + " of " +
                            std::to_string(height_));
        return static_cast<unsigned char>(bytes_[pos_++]);
    }

    // A scanline is either run-length encoded per component (starting 2, 2, then the width in
    // 15 bits) or flat RGBE quadruples; the encoded form exists only for widths in [8, 32767].
    // The obsolete pre-1991 runs (1, 1, 1, n) are read as plain pixels, as stb_image does.
    void read_scanline(int y, std::vector<unsigned char>& out) {
        const bool encoded = width_ >= 8 && width_ < 32768 && pos_ + 2 < bytes_.size() &&
                             bytes_[pos_] == 2 && bytes_[pos_ + 1] == 2 && !(bytes_[pos_ + 2] & 0x80);
        if (!encoded) {
            for (unsigned char& b : out) b = byte(y);
            return;
        }
        pos_ += 2;
        const int length = (int(byte(y)) << 8) | int(byte(y));
        if (length != width_)
            fail(file_, "corrupt Radiance HDR image: row " + std::to_string(y) + " is " + std::to_string(length) +
                            " pixels long, expected " + std::to_string(width_));
        for (int c = 0; c < 4; ++c) {
            for (int x = 0; x < width_;) {
                int count = byte(y);
                const bool run = count > 128;
                if (run) count -= 128;
                if (count == 0 || count > width_ - x)
                    fail(file_, "corrupt Radiance HDR image: bad run length in row " + std::to_string(y));
                const unsigned char value = run ? byte(y) : 0;
                for (int i = 0; i < count; ++i, ++x) out[size_t(x) * 4 + size_t(c)] = run ? value : byte(y);
            }
        }
    }

    // Ward's rgbe2float: mantissa * 2^(exponent - 128 - 8); exponent 0 is black.
    static Rgb decode(const unsigned char* rgbe) {
        if (rgbe[3] == 0) return Rgb(0.0f);
        const float f = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
        return {float(rgbe[0]) * f, float(rgbe[1]) * f, float(rgbe[2]) * f};
    }

    const fs::path& file_;
    const std::string& bytes_;
    size_t pos_ = 0;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace

Image read_rgbe(const fs::path& file) {
    const std::string bytes = read_file_contents(file);
    return RgbeReader(file, bytes).read();
}

void write_rgbe(const fs::path& file, const Image& image) {
    std::vector<float> values;
    values.reserve(image.pixels.size() * 3);
    for (const Rgb& p : image.pixels)
        for (int c = 0; c < 3; ++c) values.push_back(std::max(p[c], 0.0f));
    std::string bytes;
    if (!stbi_write_hdr_to_func(append_to_string, &bytes, image.width, image.height, 3, values.data()))
        fail(file, "cannot encode Radiance HDR image");
    write_contents_atomically(file, bytes);
}

}  // namespace candela::image_formats
