// Plain (ASCII) PPM exactly as smallpt writes it, so its output can be compared byte for byte:
// fprintf(f, "P3\n%d %d\n%d\n", w, h, 255), then "%d %d %d " per pixel, no line breaks.
#include <string>

#include "candela/core/atomic_file.h"
#include "candela/image/tonemap.h"
#include "candela/image/image_formats.h"

namespace candela::image_formats {

void write_ppm(const std::filesystem::path& file, const Image& image, const DisplayEncoding& film) {
    std::string out = "P3\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    out.reserve(out.size() + image.pixels.size() * 12);
    for (const Rgb& p : image.pixels) {
        for (uint8_t b : to_display_bytes(p, film)) {
            out += std::to_string(int(b));
            out += ' ';
        }
    }
    write_contents_atomically(file, out);
}

}  // namespace candela::image_formats
