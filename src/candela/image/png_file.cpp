// PNG through stb_image / stb_image_write. Files are taken to be sRGB-encoded (gAMA, cHRM and
// iCCP chunks are ignored, as by most renderers) and decoded with the exact sRGB curve.
#include <stb_image.h>
#include <stb_image_write.h>

#include <array>
#include <climits>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/image/tonemap.h"
#include "candela/image/image_formats.h"

namespace candela::image_formats {

namespace fs = std::filesystem;

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown error";
}

template <class T>
Image to_linear(const T* data, int width, int height, const auto& decode) {
    Image image(width, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = Rgb(decode(data[3 * i]), decode(data[3 * i + 1]), decode(data[3 * i + 2]));
    return image;
}

}  // namespace

Image read_png(const fs::path& file) {
    const std::string bytes = read_file_contents(file);
    if (bytes.size() < sizeof(kPngSignature) || std::memcmp(bytes.data(), kPngSignature, sizeof(kPngSignature)) != 0)
        fail(file, "not a PNG image (bad signature)");
    if (bytes.size() > size_t(INT_MAX)) fail(file, "PNG file is too large (over 2 GiB)");
    const auto* buffer = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(bytes.size());

    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(buffer, length, &width, &height, &channels))
        fail(file, "corrupt PNG header: " + stb_reason());
    check_dimensions(file, width, height);

    if (stbi_is_16_bit_from_memory(buffer, length)) {
        std::unique_ptr<stbi_us, StbFree> data(stbi_load_16_from_memory(buffer, length, &width, &height, &channels, 3));
        if (!data) fail(file, "corrupt PNG image: " + stb_reason());
        return to_linear(data.get(), width, height, [](stbi_us v) { return decode_srgb(float(v) / 65535.0f); });
    }
    std::unique_ptr<stbi_uc, StbFree> data(stbi_load_from_memory(buffer, length, &width, &height, &channels, 3));
    if (!data) fail(file, "corrupt PNG image: " + stb_reason());
    std::array<float, 256> linear{};
    for (int v = 0; v < 256; ++v) linear[size_t(v)] = decode_srgb(float(v) / 255.0f);
    return to_linear(data.get(), width, height, [&](stbi_uc v) { return linear[v]; });
}

void write_png(const fs::path& file, const Image& image, const DisplayEncoding& film) {
    std::vector<unsigned char> display;
    display.reserve(image.pixels.size() * 3);
    for (const Rgb& p : image.pixels)
        for (uint8_t b : to_display_bytes(p, film)) display.push_back(b);
    std::string bytes;
    const int stride = image.width * 3;
    if (!stbi_write_png_to_func(append_to_string, &bytes, image.width, image.height, 3, display.data(), stride))
        fail(file, "cannot encode PNG image");
    write_contents_atomically(file, bytes);
}

}  // namespace candela::image_formats
