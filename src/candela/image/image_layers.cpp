#include "candela/image/image_layers.h"

#include <algorithm>
#include <cctype>

#include "candela/core/error.h"
#include "candela/core/file_extension.h"
#include "candela/image/image_formats.h"
#include "candela/image/image_io.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

// Layers a display format can show as they are (values in [0, 1], or mapped there).
bool keeps_output_format(const ImageLayer& layer) { return layer.name == "albedo" || layer.name == "normal"; }

}  // namespace

fs::path layer_side_file(const fs::path& output, const ImageLayer& layer) {
    fs::path side = output;
    const std::string ext = keeps_output_format(layer) ? output.extension().string() : ".pfm";
    side.replace_filename(output.stem().string() + "." + layer.name + ext);
    return side;
}

void write_image_with_layers(const fs::path& file, const Image& image, const std::vector<ImageLayer>& layers,
                             const DisplayEncoding& film) {
    if (lower_extension(file) == ".exr" && !layers.empty()) {
        // write_image's last line of defence, for every layer.
        auto check = [&](const Image& i, const std::string& what) {
            if (i.width != image.width || i.height != image.height ||
                i.pixels.size() != size_t(i.width) * size_t(i.height))
                throw RenderError("refusing to write " + file.string() + ": " + what + " has the wrong size");
            for (const Rgb& p : i.pixels)
                if (!p.is_finite())
                    throw RenderError("refusing to write " + file.string() + ": " + what + " is not finite");
        };
        check(image, "the image");
        for (const ImageLayer& layer : layers) check(layer.image, "AOV layer " + layer.name);
        image_formats::write_exr(file, image, layers);
        return;
    }
    write_image(file, image, film);
    for (const ImageLayer& layer : layers) {
        const fs::path side = layer_side_file(file, layer);
        const std::string ext = lower_extension(side);
        Image out = layer.image;
        if (layer.channels == 1)
            for (Rgb& p : out.pixels) p = Rgb(p.r);
        DisplayEncoding encoding;  // albedo in 8 bits: clamped, sRGB
        if (layer.name == "normal" && ext != ".pfm" && ext != ".exr") {
            for (Rgb& p : out.pixels) p = Rgb(p.r * 0.5f + 0.5f, p.g * 0.5f + 0.5f, p.b * 0.5f + 0.5f);
            encoding.transfer = Transfer::kGamma;  // linear: the value is the code
            encoding.gamma = 1.0f;
        }
        write_image(side, out, encoding);
    }
}

std::vector<std::string> read_exr_channel_names(const fs::path& file) {
    return image_formats::read_exr_channel_names(file);
}

Image read_exr_channels(const fs::path& file, const std::vector<std::string>& names) {
    return image_formats::read_exr_channels(file, names);
}

}  // namespace candela
