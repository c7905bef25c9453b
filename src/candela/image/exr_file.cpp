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

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
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

}  // namespace

Image read_exr(const fs::path& file) {
    bool tiled = false, deep = false, multi_part = false;
    if (!Imf::isOpenExrFile(file.c_str(), tiled, deep, multi_part))
        fail(file, "not an OpenEXR image (bad magic number or truncated header)");
    if (deep) fail(file, "deep OpenEXR images are not supported");
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

void write_exr(const fs::path& file, const Image& image) {
    std::string bytes;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));

        // Encoded in memory: OutputFile's destructor writes the line offset table and swallows
        // errors there, so writing the file directly could hide a short write.
        Imf::StdOSStream stream;
        {
            Imf::OutputFile out(stream, header);
            Imf::FrameBuffer frame;
            // OpenEXR's Slice takes a mutable pointer but only reads through it when writing.
            char* base = reinterpret_cast<char*>(const_cast<Rgb*>(image.pixels.data()));
            const size_t x_stride = sizeof(Rgb);
            const size_t y_stride = sizeof(Rgb) * size_t(image.width);
            frame.insert("R", Imf::Slice(Imf::FLOAT, base + offsetof(Rgb, r), x_stride, y_stride));
            frame.insert("G", Imf::Slice(Imf::FLOAT, base + offsetof(Rgb, g), x_stride, y_stride));
            frame.insert("B", Imf::Slice(Imf::FLOAT, base + offsetof(Rgb, b), x_stride, y_stride));
            out.setFrameBuffer(frame);
            out.writePixels(image.height);
        }
        bytes = stream.str();
    } catch (const std::exception& e) {
        fail(file, std::string("cannot encode OpenEXR image: ") + e.what());
    }
    write_contents_atomically(file, bytes);
}

}  // namespace candela::image_formats
