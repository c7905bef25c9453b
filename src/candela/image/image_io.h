#pragma once
// Image files by extension. Reading: .exr, .hdr, .pfm, .png (8-bit sRGB decoded to linear).
// Writing: .exr (linear float), .pfm, .hdr (RGBE) as linear values; .png (8-bit) and .ppm (as
// smallpt writes it) tone mapped and transfer-encoded by `film`. Writes are atomic: a temporary
// file in the same folder, then a rename, so a crash never leaves a half-written image.
#include <filesystem>

#include "candela/image/display_encoding.h"
#include "candela/image/image.h"

namespace candela {

// Extensions are matched case-insensitively. An EXR image is its data window; Y-only files are
// replicated to grey RGB.
// Throws SceneError naming the file on a missing, unreadable or corrupt image, an unknown
// extension, a size over 65536 per side or 2^28 pixels, or a NaN/infinite pixel value.
Image read_image(const std::filesystem::path& file);

// Throws SceneError for an unknown extension (listing the known ones) or a failed write. The
// last line of defence against bad pixels: throws RenderError, writing nothing, if the image has
// a NaN or infinite value (the renderer guarantees none) or its size does not match its pixels.
void write_image(const std::filesystem::path& file, const Image& image, const DisplayEncoding& film);

// True when the extension is one read_image knows (for checking scene files early).
bool is_readable_image_extension(const std::filesystem::path& file);

// True when the extension is one write_image knows (for checking -o before rendering).
bool is_writable_image_extension(const std::filesystem::path& file);

}  // namespace candela
