#include "candela/image/image_io.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

#include "candela/core/error.h"
#include "candela/core/file_extension.h"
#include "candela/image/image_formats.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

using Reader = Image (*)(const fs::path&);
using Writer = void (*)(const fs::path&, const Image&, const DisplayEncoding&);

struct ImageFormat {
    const char* extension;  // lower case, with the dot
    Reader read;            // null: write only
    Writer write;
};

// The one table of formats, in the order error messages list them.
constexpr ImageFormat kFormats[] = {
    {".exr", image_formats::read_exr,
     [](const fs::path& f, const Image& i, const DisplayEncoding&) { image_formats::write_exr(f, i); }},
    {".hdr", image_formats::read_rgbe,
     [](const fs::path& f, const Image& i, const DisplayEncoding&) { image_formats::write_rgbe(f, i); }},
    {".pfm", image_formats::read_pfm,
     [](const fs::path& f, const Image& i, const DisplayEncoding&) { image_formats::write_pfm(f, i); }},
    {".png", image_formats::read_png, image_formats::write_png},
    {".ppm", nullptr, image_formats::write_ppm},
};

const ImageFormat* find_format(const fs::path& file, bool for_writing) {
    const std::string ext = lower_extension(file);
    for (const ImageFormat& f : kFormats)
        if (ext == f.extension && (for_writing ? f.write != nullptr : f.read != nullptr)) return &f;
    return nullptr;
}

std::string known_extensions(bool for_writing) {
    std::string list;
    for (const ImageFormat& f : kFormats)
        if (for_writing ? f.write != nullptr : f.read != nullptr)
            list += (list.empty() ? "" : ", ") + std::string(f.extension);
    return list;
}

std::string extension_error(const fs::path& file, bool for_writing) {
    const std::string ext = lower_extension(file);
    const std::string expected = "; expected one of: " + known_extensions(for_writing);
    if (ext.empty()) return "image file name has no extension" + expected;
    if (!for_writing && find_format(file, true))
        return "cannot read " + ext + " images, only write them" + expected;
    return "unknown image extension \"" + file.extension().string() + "\"" + expected;
}

void require_regular_file(const fs::path& file) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) image_formats::fail(file, "image file not found");
    if (ec) image_formats::fail(file, "cannot access image file: " + ec.message());
    if (status.type() == fs::file_type::directory)
        image_formats::fail(file, "is a directory, expected an image file");
    if (status.type() != fs::file_type::regular) image_formats::fail(file, "is not a regular file");
}

// The first pixel with a NaN or infinite channel, or nullptr.
const Rgb* first_non_finite(const Image& image) {
    for (const Rgb& p : image.pixels)
        if (!p.is_finite()) return &p;
    return nullptr;
}

std::string describe_pixel(const Image& image, const Rgb& p) {
    const size_t i = size_t(&p - image.pixels.data());
    return fmt::format("pixel ({}, {}) is not finite ({}, {}, {})", i % size_t(image.width),
                       i / size_t(image.width), p.r, p.g, p.b);
}

}  // namespace

Image read_image(const fs::path& file) {
    const ImageFormat* format = find_format(file, false);
    if (!format) image_formats::fail(file, extension_error(file, false));
    require_regular_file(file);
    Image image = format->read(file);
    if (const Rgb* bad = first_non_finite(image)) image_formats::fail(file, describe_pixel(image, *bad));
    return image;
}

void write_image(const fs::path& file, const Image& image, const DisplayEncoding& film) {
    const ImageFormat* format = find_format(file, true);
    if (!format) image_formats::fail(file, extension_error(file, true));
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height))
        throw RenderError(fmt::format("refusing to write {}: inconsistent image ({}x{} with {} pixels)",
                                      file.string(), image.width, image.height, image.pixels.size()));
    if (const Rgb* bad = first_non_finite(image))
        throw RenderError("refusing to write " + file.string() + ": " + describe_pixel(image, *bad));
    format->write(file, image, film);
}

bool is_readable_image_extension(const fs::path& file) { return find_format(file, false) != nullptr; }

bool is_writable_image_extension(const fs::path& file) { return find_format(file, true) != nullptr; }

}  // namespace candela
