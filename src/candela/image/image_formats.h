#pragma once
// The file formats behind image_io.h, one per file, and the checks they share. Internal to
// image/: the rest of candela calls read_image and write_image, which pick one by extension
// (textures/texture_file.cpp, which reads 8- and 16-bit files its own way, shares the checks).
// Readers throw SceneError naming the file; writers replace the file atomically
// (core/atomic_file.h) and may assume the image is non-empty and finite (write_image checks).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "candela/image/display_encoding.h"
#include "candela/image/image.h"

namespace candela::image_formats {

// OpenEXR (exr_file.cpp): R, G, B (or Y alone, or luminance-chroma) in any compression;
// written as 32-bit float R, G, B with ZIP compression.
Image read_exr(const std::filesystem::path& file);
void write_exr(const std::filesystem::path& file, const Image& image);
// With AOV layers: each layer's channels beside R, G, B, under the layer's channel names.
void write_exr(const std::filesystem::path& file, const Image& image, const std::vector<ImageLayer>& layers);

// The channel names of an OpenEXR file, and up to three named channels read into r, g, b.
std::vector<std::string> read_exr_channel_names(const std::filesystem::path& file);
Image read_exr_channels(const std::filesystem::path& file, const std::vector<std::string>& names);

// Portable float map (pfm_file.cpp): "PF" (RGB) or "Pf" (grey), rows bottom to top, the sign of
// the scale giving the byte order; written little-endian with scale -1.
Image read_pfm(const std::filesystem::path& file);
void write_pfm(const std::filesystem::path& file, const Image& image);

// Radiance RGBE .hdr (rgbe_file.cpp); negative values are written as 0 (RGBE cannot hold them).
Image read_rgbe(const std::filesystem::path& file);
void write_rgbe(const std::filesystem::path& file, const Image& image);

// PNG (png_file.cpp): 8- or 16-bit, sRGB-decoded to linear on reading; written as 8-bit RGB
// after the film's tone map and transfer curve.
Image read_png(const std::filesystem::path& file);
void write_png(const std::filesystem::path& file, const Image& image, const DisplayEncoding& film);

// Plain PPM (ppm_file.cpp), byte for byte as smallpt writes it: "P3\nW H\n255\n", then
// "r g b " per pixel, tone mapped and encoded like PNG.
void write_ppm(const std::filesystem::path& file, const Image& image, const DisplayEncoding& film);

// Largest accepted image: 65536 pixels per side and 2^28 pixels in all (3 GiB of RGB floats);
// a header claiming more is far likelier corrupt than a real scene asset.
inline constexpr int64_t kMaxImageSide = 65536;
inline constexpr int64_t kMaxImagePixels = int64_t(1) << 28;

// Throws SceneError{file, message}.
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& message);

// Throws unless 0 < width, height <= kMaxImageSide and width * height <= kMaxImagePixels.
void check_dimensions(const std::filesystem::path& file, int64_t width, int64_t height);

// The whole file's bytes; throws SceneError if it cannot be read.
std::string read_file_contents(const std::filesystem::path& file);

// stb_image_write's write callback for an in-memory file: appends `size` bytes at `data` to the
// std::string at `context` (the PNG and Radiance HDR writers fill a string, then write it atomically).
void append_to_string(void* context, void* data, int size);

}  // namespace candela::image_formats
