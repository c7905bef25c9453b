// Writes small seed images for the hdr and exr fuzz targets into the folder given as argument:
// every encoding the readers have a separate path for, so the fuzzers start inside each one.
//   hdr: flat scanlines (width < 8) and RLE scanlines with runs and literals (stb's writer).
//   exr: every compression, float and half, scanline and tiled, RGB, Y-only, luminance-chroma,
//        and a data window away from the origin.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "candela/image/image_io.h"

namespace {

namespace fs = std::filesystem;

float value(int x, int y, int c) { return 0.25f * float(x) + 0.5f * float(y % 3) + 0.1f * float(c); }

candela::Image test_image(int width, int height) {
    candela::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.at(x, y) = {value(x, y, 0), value(x, y, 1), value(x, y, 2)};
    return image;
}

// Channels `names` of `type` over `window`, scanline or tiled (4x4 tiles).
void write_exr(const fs::path& file, const Imath::Box2i& window, const std::vector<std::string>& names,
               Imf::Compression compression, Imf::PixelType type, bool tiled) {
    const int w = window.max.x - window.min.x + 1, h = window.max.y - window.min.y + 1;
    Imf::Header header(window, window);
    header.compression() = compression;
    if (tiled) header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    std::vector<std::vector<float>> floats(names.size(), std::vector<float>(size_t(w) * size_t(h)));
    std::vector<std::vector<half>> halves(names.size(), std::vector<half>(size_t(w) * size_t(h)));
    Imf::FrameBuffer frame;
    for (size_t i = 0; i < names.size(); ++i) {
        header.channels().insert(names[i], Imf::Channel(type));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                floats[i][size_t(y * w + x)] = value(x, y, int(i));
                halves[i][size_t(y * w + x)] = half(value(x, y, int(i)));
            }
        frame.insert(names[i], type == Imf::FLOAT ? Imf::Slice::Make(Imf::FLOAT, floats[i].data(), window)
                                                  : Imf::Slice::Make(Imf::HALF, halves[i].data(), window));
    }
    if (tiled) {
        Imf::TiledOutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    } else {
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(h);
    }
}

void write_luminance_chroma(const fs::path& file, int w, int h) {
    std::vector<Imf::Rgba> pixels(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pixels[size_t(y * w + x)] = Imf::Rgba(value(x, y, 0), value(x, y, 1), value(x, y, 2));
    Imf::RgbaOutputFile out(file.c_str(), w, h, Imf::WRITE_YC);
    out.setFrameBuffer(pixels.data(), 1, size_t(w));
    out.writePixels(h);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s FOLDER\n", argv[0]);
        return 2;
    }
    const fs::path folder = argv[1];
    fs::create_directories(folder);
    const candela::DisplayEncoding film;
    candela::write_image(folder / "flat_4x3.hdr", test_image(4, 3), film);
    candela::write_image(folder / "rle_19x5.hdr", test_image(19, 5), film);
    candela::write_image(folder / "rle_40x2.hdr", candela::Image(40, 2), film);  // long runs of zeros

    const Imath::Box2i window({0, 0}, {9, 5});  // 10 x 6: not a multiple of any block size
    int n = 0;
    for (Imf::Compression compression :
         {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION,
          Imf::PXR24_COMPRESSION, Imf::B44_COMPRESSION, Imf::B44A_COMPRESSION, Imf::DWAA_COMPRESSION,
          Imf::DWAB_COMPRESSION})
        for (Imf::PixelType type : {Imf::FLOAT, Imf::HALF})
            write_exr(folder / ("rgb_" + std::to_string(n++) + ".exr"), window, {"R", "G", "B"}, compression, type,
                      false);
    write_exr(folder / "tiled_zip.exr", window, {"R", "G", "B"}, Imf::ZIP_COMPRESSION, Imf::HALF, true);
    write_exr(folder / "tiled_none.exr", window, {"R", "G", "B"}, Imf::NO_COMPRESSION, Imf::FLOAT, true);
    write_exr(folder / "y_only.exr", window, {"Y"}, Imf::ZIP_COMPRESSION, Imf::HALF, false);
    write_exr(folder / "rgba.exr", window, {"A", "B", "G", "R"}, Imf::NO_COMPRESSION, Imf::HALF, false);
    write_exr(folder / "offset_window.exr", Imath::Box2i({-3, 5}, {4, 8}), {"R", "G", "B"}, Imf::RLE_COMPRESSION,
              Imf::FLOAT, false);
    write_luminance_chroma(folder / "luminance_chroma.exr", 8, 6);
    return 0;
}
