#include "candela/textures/texture_file.h"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/core/file_extension.h"
#include "candela/image/image_formats.h"
#include "candela/image/image_io.h"
#include "candela/image/tonemap.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStbExtensions[] = {".png", ".jpg", ".jpeg", ".tga", ".bmp"};
constexpr const char* kFloatExtensions[] = {".exr", ".hdr", ".pfm"};

template <size_t N>
bool is_one_of(const fs::path& file, const char* const (&extensions)[N]) {
    const std::string ext = lower_extension(file);
    return std::any_of(std::begin(extensions), std::end(extensions), [&](const char* e) { return ext == e; });
}

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown error";
}

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

// Copies `n` texels of `channels` values from `in` to `out`, leaving out an alpha channel that
// is `opaque` everywhere; returns the channels kept.
template <class T>
int copy_texels(const T* in, size_t n, int channels, T opaque, std::vector<T>& out) {
    const bool alpha = channels == 2 || channels == 4;
    bool drop = alpha;
    for (size_t i = 0; drop && i < n; ++i) drop = in[i * size_t(channels) + size_t(channels - 1)] == opaque;
    const int kept = drop ? channels - 1 : channels;
    out.resize(n * size_t(kept));
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < kept; ++c) out[i * size_t(kept) + size_t(c)] = in[i * size_t(channels) + size_t(c)];
    return kept;
}

// The linear value of an encoded v in [0, 1] (kGamma: pbrt-v4's GammaColorEncoding, v^gamma).
float decode(float v, TextureColorspace colorspace, float gamma) {
    if (colorspace == TextureColorspace::kSrgb) return decode_srgb(v);
    if (colorspace == TextureColorspace::kGamma) return std::pow(v, gamma);
    return v;
}

TextureImage read_8_bit(const fs::path& file, const stbi_uc* buffer, int length, TextureColorspace colorspace,
                        float gamma) {
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, StbFree> data(stbi_load_from_memory(buffer, length, &width, &height, &channels, 0));
    if (!data) image_formats::fail(file, "corrupt image: " + stb_reason());
    TextureImage image;
    image.width = width;
    image.height = height;
    image.channels = copy_texels(data.get(), size_t(width) * size_t(height), channels, stbi_uc(255), image.bytes);
    for (int v = 0; v < 256; ++v) image.byte_values[size_t(v)] = decode(float(v) / 255.0f, colorspace, gamma);
    return image;
}

TextureImage read_16_bit(const fs::path& file, const stbi_uc* buffer, int length, TextureColorspace colorspace,
                         float gamma) {
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_us, StbFree> data(stbi_load_16_from_memory(buffer, length, &width, &height, &channels, 0));
    if (!data) image_formats::fail(file, "corrupt image: " + stb_reason());
    std::vector<stbi_us> kept;
    TextureImage image;
    image.width = width;
    image.height = height;
    image.channels = copy_texels(data.get(), size_t(width) * size_t(height), channels, stbi_us(65535), kept);
    data.reset();
    // One decode per distinct value rather than per sample (the sRGB curve is a power).
    std::vector<float> colour(65536);
    for (size_t v = 0; v < colour.size(); ++v) colour[v] = decode(float(v) / 65535.0f, colorspace, gamma);
    const bool alpha = image.has_alpha();
    image.floats.resize(kept.size());
    for (size_t i = 0; i < kept.size(); ++i) {
        const bool is_alpha = alpha && i % size_t(image.channels) == size_t(image.channels - 1);
        image.floats[i] = is_alpha ? float(kept[i]) / 65535.0f : colour[kept[i]];
    }
    return image;
}

TextureImage from_linear_image(const Image& linear) {
    TextureImage image;
    image.width = linear.width;
    image.height = linear.height;
    image.channels = 3;
    image.floats.reserve(linear.pixels.size() * 3);
    for (const Rgb& p : linear.pixels) image.floats.insert(image.floats.end(), {p.r, p.g, p.b});
    return image;
}

}  // namespace

bool is_texture_file_extension(const fs::path& file) {
    return is_one_of(file, kStbExtensions) || is_one_of(file, kFloatExtensions);
}

bool is_float_texture_file(const fs::path& file) { return is_one_of(file, kFloatExtensions); }

const char* texture_file_extensions() { return ".png, .jpg, .jpeg, .tga, .bmp, .exr, .hdr, .pfm"; }

std::optional<TextureFileHeader> read_texture_file_header(const fs::path& file) {
    if (is_float_texture_file(file)) return std::nullopt;
    std::error_code ec;
    const uintmax_t size = fs::file_size(file, ec);
    if (ec) image_formats::fail(file, "cannot read image file: " + ec.message());
    // stbi_info reads only the header, through its own FILE*.
    TextureFileHeader header;
    header.file_bytes = uint64_t(size);
    if (!stbi_info(file.c_str(), &header.width, &header.height, &header.channels))
        image_formats::fail(file, "not a PNG, JPEG, TGA or BMP image, or a corrupt one: " + stb_reason());
    image_formats::check_dimensions(file, header.width, header.height);
    header.bytes_per_channel = stbi_is_16_bit(file.c_str()) ? 4 : 1;
    return header;
}

TextureImage read_texture_file(const fs::path& file, TextureColorspace colorspace, float gamma) {
    if (is_float_texture_file(file)) return from_linear_image(read_image(file));
    const std::string bytes = image_formats::read_file_contents(file);
    if (bytes.size() > size_t(INT_MAX)) image_formats::fail(file, "image file is too large (over 2 GiB)");
    const auto* buffer = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(bytes.size());
    // The header again: the file may have changed since read_texture_file_header.
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(buffer, length, &width, &height, &channels))
        image_formats::fail(file, "not a PNG, JPEG, TGA or BMP image, or a corrupt one: " + stb_reason());
    image_formats::check_dimensions(file, width, height);
    return stbi_is_16_bit_from_memory(buffer, length) ? read_16_bit(file, buffer, length, colorspace, gamma)
                                                      : read_8_bit(file, buffer, length, colorspace, gamma);
}

}  // namespace candela
