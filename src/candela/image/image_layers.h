#pragma once
// An image with AOV layers (film/aov_layers.h) as files: one OpenEXR file with every layer's
// channels beside R, G, B, or for the other formats the image and one file per layer beside it.
#include <filesystem>
#include <string>
#include <vector>

#include "candela/image/display_encoding.h"
#include "candela/image/image.h"

namespace candela {

// The file a layer goes to beside a non-EXR `output`: <stem>.<layer>.<ext>. Albedo and normal
// keep the output's format (8-bit PNG and PPM encode normals as n / 2 + 1/2, as do RGBE files,
// which cannot hold negative values); layers of unbounded linear values (depth, position, ...)
// are always written as .pfm, linear float.
std::filesystem::path layer_side_file(const std::filesystem::path& output, const ImageLayer& layer);

// Writes `image` to `file` as write_image does, with `layers`: inside it for .exr, else each to
// its layer_side_file. One-channel layers become grey in side files. Albedo in 8-bit formats is
// clamped and sRGB-encoded, whatever the film's tone map; normals are encoded linearly.
void write_image_with_layers(const std::filesystem::path& file, const Image& image,
                             const std::vector<ImageLayer>& layers, const DisplayEncoding& film);

// An OpenEXR file's channel names, and up to three of its channels as an image's r, g, b (for
// reading layers back). Throw SceneError naming the file.
std::vector<std::string> read_exr_channel_names(const std::filesystem::path& file);
Image read_exr_channels(const std::filesystem::path& file, const std::vector<std::string>& names);

}  // namespace candela
