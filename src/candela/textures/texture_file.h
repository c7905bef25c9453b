#pragma once
// Image files as textures (not value code: throws SceneError naming the file). PNG, JPEG, TGA and
// BMP, 8 or 16 bits per channel, through stb_image, sRGB-decoded with the exact piecewise curve
// unless the colorspace is linear; EXR, HDR and PFM through image/image_io.h, linear always.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "candela/textures/texture_image.h"

namespace candela {

// How an 8- or 16-bit file's values become linear: the sRGB EOTF (IEC 61966-2-1), v / max, or
// (v / max)^gamma (pbrt-v4's encoding "gamma G").
enum class TextureColorspace : uint8_t { kSrgb, kLinear, kGamma };

// What a texture file's header says, read before its texels so that the memory they take can be
// checked before it is allocated.
struct TextureFileHeader {
    int width = 0;
    int height = 0;
    int channels = 0;           // in the file: 1 to 4
    int bytes_per_channel = 1;  // 1 (8-bit, kept as bytes) or 4 (16-bit, decoded to float)
    uint64_t file_bytes = 0;
};

// True for the extensions read_texture_file knows (case-insensitive): .png .jpg .jpeg .tga .bmp
// .exr .hdr .pfm.
bool is_texture_file_extension(const std::filesystem::path& file);
// True for the formats that hold linear floats (.exr .hdr .pfm): no colorspace applies.
bool is_float_texture_file(const std::filesystem::path& file);
// "`.png`, `.jpg`, ...": the known extensions, for messages.
const char* texture_file_extensions();

// The header of an 8- or 16-bit file; nothing for float formats (their readers check the size
// against the file before allocating, image_io.h). Throws SceneError for an unreadable or
// corrupt header or a size beyond image_io's limits.
std::optional<TextureFileHeader> read_texture_file_header(const std::filesystem::path& file);

// The file's texels (texture_image.h): 8-bit files as bytes with the colorspace's decoding table,
// 16-bit and float files as floats; an alpha channel that is opaque everywhere is dropped.
// `gamma`: the exponent of kGamma (unused otherwise).
TextureImage read_texture_file(const std::filesystem::path& file, TextureColorspace colorspace, float gamma = 1.0f);

}  // namespace candela
