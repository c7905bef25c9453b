// OpenEXR images through the general FrameBuffer API, so float files are read as float (the
// RGBA convenience interface would round them to half). The image is the file's data window,
// as pbrt-v4 and Mitsuba read it; the display window is ignored.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <ImfTestFile.h>
#include <openexr.h>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/image/exr_attributes.h"
#include "candela/image/image_formats.h"

namespace candela::image_formats {

namespace fs = std::filesystem;

namespace {

std::string channel_names(const Imf::ChannelList& channels) {
    std::string names;
    for (auto it = channels.begin(); it != channels.end(); ++it)
        names += (names.empty() ? "" : ", ") + std::string(it.name());
    return names.empty() ? "none" : names;
}

// Luminance-chroma files (Y with subsampled RY, BY) need the RGBA interface's colour
// conversion; their Y is half precision anyway, so nothing is lost.
void read_luminance_chroma(const fs::path& file, Image& image) {
    Imf::RgbaInputFile in(file.c_str());
    const Imath::Box2i dw = in.dataWindow();
    std::vector<Imf::Rgba> rgba(image.pixels.size());
    // The library indexes the buffer by absolute data-window coordinates.
    Imf::Rgba* origin = rgba.data() - ptrdiff_t(dw.min.x) - ptrdiff_t(dw.min.y) * image.width;
    in.setFrameBuffer(origin, 1, size_t(image.width));
    in.readPixels(dw.min.y, dw.max.y);
    for (size_t i = 0; i < rgba.size(); ++i)
        image.pixels[i] = Rgb(float(rgba[i].r), float(rgba[i].g), float(rgba[i].b));
}

void read_channels(Imf::InputFile& in, const fs::path& file, Image& image) {
    const Imath::Box2i dw = in.header().dataWindow();
    const Imf::ChannelList& channels = in.header().channels();
    const bool has_rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
    const bool has_y = channels.findChannel("Y") != nullptr;
    if (!has_rgb && !has_y)
        fail(file, "OpenEXR image has no R, G, B or Y channel (found: " + channel_names(channels) + ")");
    for (const char* name : {"R", "G", "B", "Y"}) {
        const Imf::Channel* c = channels.findChannel(name);
        if (c && (c->xSampling != 1 || c->ySampling != 1))
            fail(file, std::string("OpenEXR channel ") + name + " is subsampled, which is not supported");
    }

    Imf::FrameBuffer frame;
    const size_t x_stride = sizeof(Rgb);
    const size_t y_stride = sizeof(Rgb) * size_t(image.width);
    Rgb* first = image.pixels.data();
    if (has_rgb) {
        // A missing one of R, G, B reads as 0 (the slice's fill value).
        frame.insert("R", Imf::Slice::Make(Imf::FLOAT, &first->r, dw, x_stride, y_stride));
        frame.insert("G", Imf::Slice::Make(Imf::FLOAT, &first->g, dw, x_stride, y_stride));
        frame.insert("B", Imf::Slice::Make(Imf::FLOAT, &first->b, dw, x_stride, y_stride));
    } else {
        frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, &first->r, dw, x_stride, y_stride));
    }
    in.setFrameBuffer(frame);
    in.readPixels(dw.min.y, dw.max.y);
    if (!has_rgb)
        for (Rgb& p : image.pixels) p = Rgb(p.r);
}

// OpenEXR 3.1's C++ reader allocates every header attribute at the size the file declares
// before reading it (Header::readFrom), so a corrupt 100-byte file could make it allocate 2 GiB
// (found by fuzz/exr_fuzzer.cpp). Its C core (OpenEXRCore) parses headers with every size checked
// against the file's, so the core parses the headers first and a file it complains about is
// refused with its first message, before the C++ reader sees it. (For a bad attribute size the
// core reports the error, skips the attribute and still returns success, so the message counts.)
thread_local std::string* t_core_message = nullptr;

void keep_core_message(exr_const_context_t, exr_result_t, const char* message) {
    if (t_core_message && t_core_message->empty() && message) *t_core_message = message;
}

void check_headers(const fs::path& file) {
    std::string message;
    t_core_message = &message;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = keep_core_message;
    init.max_image_width = init.max_image_height = int(kMaxImageSide);
    init.max_tile_width = init.max_tile_height = int(kMaxImageSide);
    exr_context_t context = nullptr;
    const exr_result_t result = exr_start_read(&context, file.c_str(), &init);
    exr_finish(&context);
    t_core_message = nullptr;
    if (result != EXR_ERR_SUCCESS || !message.empty())
        fail(file, "corrupt OpenEXR header: " + (message.empty() ? std::string(exr_get_default_error_message(result))
                                                                 : message));
}

// OpenEXR checks headers against these limits (Header::sanityCheck) before it sizes anything by
// them, such as the table of chunk offsets; set once, as they are process-wide.
void limit_image_size() {
    static const bool once = [] {
        Imf::Header::setMaxImageSize(int(kMaxImageSide), int(kMaxImageSide));
        Imf::Header::setMaxTileSize(int(kMaxImageSide), int(kMaxImageSide));
        return true;
    }();
    (void)once;
}

// Every chunk of pixel data the C++ reader will read (part 0's scanline blocks, or its level-0
// tiles) must be in the file. That reader finds a missing chunk only in readPixels, after the
// image is allocated: a 130 KB file whose header claims 16384x16384 made us allocate 3 GiB.
// The core reads each chunk's offset and leader here and checks them against the file's size.
void check_chunks_present(const fs::path& file) {
    std::string message;
    t_core_message = &message;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = keep_core_message;
    exr_context_t context = nullptr;
    exr_result_t result = exr_start_read(&context, file.c_str(), &init);
    exr_storage_t storage = EXR_STORAGE_SCANLINE;
    if (result == EXR_ERR_SUCCESS) result = exr_get_storage(context, 0, &storage);
    int64_t first_missing = -1;  // the first row (or tile row) whose chunk is missing
    exr_chunk_info_t chunk{};
    if (result == EXR_ERR_SUCCESS && storage == EXR_STORAGE_SCANLINE) {
        exr_attr_box2i_t dw{};
        int32_t lines = 0;
        result = exr_get_data_window(context, 0, &dw);
        if (result == EXR_ERR_SUCCESS) result = exr_get_scanlines_per_chunk(context, 0, &lines);
        for (int64_t y = dw.min.y; result == EXR_ERR_SUCCESS && lines > 0 && y <= dw.max.y; y += lines) {
            result = exr_read_scanline_chunk_info(context, 0, int(y), &chunk);
            if (result != EXR_ERR_SUCCESS) first_missing = y;
        }
    } else if (result == EXR_ERR_SUCCESS && storage == EXR_STORAGE_TILED) {
        int32_t tile_w = 0, tile_h = 0, level_w = 0, level_h = 0;
        result = exr_get_tile_sizes(context, 0, 0, 0, &tile_w, &tile_h);
        if (result == EXR_ERR_SUCCESS) result = exr_get_level_sizes(context, 0, 0, 0, &level_w, &level_h);
        const int64_t tiles_x = tile_w > 0 ? (int64_t(level_w) + tile_w - 1) / tile_w : 0;
        const int64_t tiles_y = tile_h > 0 ? (int64_t(level_h) + tile_h - 1) / tile_h : 0;
        for (int64_t ty = 0; result == EXR_ERR_SUCCESS && ty < tiles_y; ++ty)
            for (int64_t tx = 0; result == EXR_ERR_SUCCESS && tx < tiles_x; ++tx) {
                result = exr_read_tile_chunk_info(context, 0, int(tx), int(ty), 0, 0, &chunk);
                if (result != EXR_ERR_SUCCESS) first_missing = ty;
            }
    }
    exr_finish(&context);
    t_core_message = nullptr;
    if (result == EXR_ERR_SUCCESS) return;
    const std::string why = message.empty() ? std::string(exr_get_default_error_message(result)) : message;
    fail(file, first_missing >= 0 ? "truncated or corrupt OpenEXR image: the pixel data of " +
                                        std::string(storage == EXR_STORAGE_TILED ? "tile row " : "row ") +
                                        std::to_string(first_missing) + " is missing (" + why + ")"
                                  : "corrupt OpenEXR image: " + why);
}

}  // namespace

Image read_exr(const fs::path& file) {
    bool tiled = false, deep = false, multi_part = false;
    if (!Imf::isOpenExrFile(file.c_str(), tiled, deep, multi_part))
        fail(file, "not an OpenEXR image (bad magic number or truncated header)");
    if (deep) fail(file, "deep OpenEXR images are not supported");
    check_headers(file);
    check_exr_attributes(file, multi_part);
    check_chunks_present(file);
    limit_image_size();
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i dw = in.header().dataWindow();
        const int64_t width = int64_t(dw.max.x) - int64_t(dw.min.x) + 1;
        const int64_t height = int64_t(dw.max.y) - int64_t(dw.min.y) + 1;
        check_dimensions(file, width, height);
        Image image(static_cast<int>(width), static_cast<int>(height));
        const Imf::ChannelList& channels = in.header().channels();
        const bool luminance_chroma = channels.findChannel("Y") &&
                                      (channels.findChannel("RY") || channels.findChannel("BY")) &&
                                      !channels.findChannel("R");
        if (luminance_chroma)
            read_luminance_chroma(file, image);
        else
            read_channels(in, file, image);
        return image;
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        // Iex::BaseExc is a std::exception: corrupt headers, truncated or undecodable pixel data.
        fail(file, std::string("cannot read OpenEXR image: ") + e.what());
    }
}

void write_exr(const fs::path& file, const Image& image) { write_exr(file, image, {}); }

void write_exr(const fs::path& file, const Image& image, const std::vector<ImageLayer>& layers) {
    std::string bytes;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        for (const ImageLayer& layer : layers)
            for (int c = 0; c < layer.channels; ++c)
                header.channels().insert(layer.channel_names[size_t(c)], Imf::Channel(Imf::FLOAT));

        // Encoded in memory: OutputFile's destructor writes the line offset table and swallows
        // errors there, so writing the file directly could hide a short write.
        Imf::StdOSStream stream;
        {
            Imf::OutputFile out(stream, header);
            Imf::FrameBuffer frame;
            const size_t x_stride = sizeof(Rgb);
            const size_t y_stride = sizeof(Rgb) * size_t(image.width);
            // Channel c of an image: r, g or b of each pixel. OpenEXR's Slice takes a mutable
            // pointer but only reads through it when writing.
            auto insert = [&](const std::string& name, const Image& from, int c) {
                char* base = reinterpret_cast<char*>(const_cast<Rgb*>(from.pixels.data()));
                const size_t offset = c == 0 ? offsetof(Rgb, r) : c == 1 ? offsetof(Rgb, g) : offsetof(Rgb, b);
                frame.insert(name, Imf::Slice(Imf::FLOAT, base + offset, x_stride, y_stride));
            };
            insert("R", image, 0);
            insert("G", image, 1);
            insert("B", image, 2);
            for (const ImageLayer& layer : layers)
                for (int c = 0; c < layer.channels; ++c) insert(layer.channel_names[size_t(c)], layer.image, c);
            out.setFrameBuffer(frame);
            out.writePixels(image.height);
        }
        bytes = stream.str();
    } catch (const std::exception& e) {
        fail(file, std::string("cannot encode OpenEXR image: ") + e.what());
    }
    write_contents_atomically(file, bytes);
}

std::vector<std::string> read_exr_channel_names(const fs::path& file) {
    try {
        Imf::InputFile in(file.c_str());
        std::vector<std::string> names;
        const Imf::ChannelList& channels = in.header().channels();
        for (auto it = channels.begin(); it != channels.end(); ++it) names.emplace_back(it.name());
        return names;
    } catch (const std::exception& e) {
        fail(file, std::string("cannot read OpenEXR image: ") + e.what());
    }
}

Image read_exr_channels(const fs::path& file, const std::vector<std::string>& names) {
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i dw = in.header().dataWindow();
        Image image(dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1);
        Imf::FrameBuffer frame;
        float* first[3] = {&image.pixels.data()->r, &image.pixels.data()->g, &image.pixels.data()->b};
        for (size_t c = 0; c < names.size() && c < 3; ++c) {
            if (!in.header().channels().findChannel(names[c])) fail(file, "OpenEXR image has no channel " + names[c]);
            frame.insert(names[c],
                         Imf::Slice::Make(Imf::FLOAT, first[c], dw, sizeof(Rgb), sizeof(Rgb) * size_t(image.width)));
        }
        in.setFrameBuffer(frame);
        in.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        fail(file, std::string("cannot read OpenEXR image: ") + e.what());
    }
}

}  // namespace candela::image_formats
