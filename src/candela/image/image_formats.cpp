#include "candela/image/image_formats.h"

#include <cerrno>
#include <fstream>
#include <sstream>
#include <system_error>

#include "candela/core/error.h"

namespace candela::image_formats {

void fail(const std::filesystem::path& file, const std::string& message) {
    SourceLocation where;
    where.file = file.string();
    throw SceneError{std::move(where), message};
}

void check_dimensions(const std::filesystem::path& file, int64_t width, int64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) fail(file, "image has zero size (" + size + ")");
    if (width > kMaxImageSide || height > kMaxImageSide)
        fail(file, "image size " + size + " exceeds the limit of " + std::to_string(kMaxImageSide) +
                       " pixels per side (corrupt header?)");
    if (width * height > kMaxImagePixels)
        fail(file, "image size " + size + " exceeds the limit of " + std::to_string(kMaxImagePixels) +
                       " pixels (corrupt header?)");
}

std::string read_file_contents(const std::filesystem::path& file) {
    errno = 0;
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        const int error = errno;
        fail(file, "cannot open image file: " +
                       (error != 0 ? std::error_code(error, std::generic_category()).message()
                                   : std::string("unknown error")));
    }
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad()) fail(file, "error while reading the image file");
    return std::move(contents).str();
}

void append_to_string(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

}  // namespace candela::image_formats
