// EXR files as other programs write them: luminance only, luminance-chroma, offset data
// windows, half channels, every lossless and lossy compression.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;

// Writes float channels named in `names` over `window`; channel i of pixel (x, y) (image
// coordinates, relative to the window) holds value(x, y, i).
template <class Value>
void write_exr_channels(const std::filesystem::path& file, const Imath::Box2i& window,
                        const std::vector<std::string>& names, Imf::Compression compression,
                        Imf::PixelType type, Value value) {
    const int w = window.max.x - window.min.x + 1;
    const int h = window.max.y - window.min.y + 1;
    Imf::Header header(window, window);
    header.compression() = compression;
    std::vector<std::vector<float>> floats(names.size(), std::vector<float>(size_t(w) * size_t(h)));
    std::vector<std::vector<half>> halves(names.size(), std::vector<half>(size_t(w) * size_t(h)));
    Imf::FrameBuffer frame;
    for (size_t i = 0; i < names.size(); ++i) {
        header.channels().insert(names[i], Imf::Channel(type));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                floats[i][size_t(y) * size_t(w) + size_t(x)] = value(x, y, int(i));
                halves[i][size_t(y) * size_t(w) + size_t(x)] = half(value(x, y, int(i)));
            }
        if (type == Imf::FLOAT)
            frame.insert(names[i], Imf::Slice::Make(Imf::FLOAT, floats[i].data(), window));
        else
            frame.insert(names[i], Imf::Slice::Make(Imf::HALF, halves[i].data(), window));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(h);
}

float channel_value(int x, int y, int c) { return 0.25f * float(x) + 4.0f * float(y) + 100.0f * float(c) + 0.5f; }

// OpenEXR's own decoding of channel `name`, row-major over the data window.
std::vector<float> decode_channel(const std::filesystem::path& file, const char* name) {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    std::vector<float> values(size_t(window.max.x - window.min.x + 1) * size_t(window.max.y - window.min.y + 1));
    Imf::FrameBuffer frame;
    frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return values;
}

TEST(ExrFile, ReadsEveryCompression) {
    TempDir dir;
    const Imath::Box2i window({0, 0}, {18, 6});  // 19 x 7: odd, not a multiple of any block size
    for (Imf::Compression compression :
         {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION,
          Imf::PIZ_COMPRESSION, Imf::PXR24_COMPRESSION, Imf::B44_COMPRESSION, Imf::B44A_COMPRESSION,
          Imf::DWAA_COMPRESSION, Imf::DWAB_COMPRESSION}) {
        for (Imf::PixelType type : {Imf::FLOAT, Imf::HALF}) {
            const auto file = dir / fmt::format("c{}_{}.exr", int(compression), int(type));
            write_exr_channels(file, window, {"R", "G", "B"}, compression, type, channel_value);
            const Image image = read_image(file);
            ASSERT_EQ(image.width, 19);
            ASSERT_EQ(image.height, 7);
            // PXR24 drops 8 bits of each float, B44 and DWA are lossy on half channels: there
            // the reference is OpenEXR's own decoding. The other compressions are lossless and
            // the values exact in half, so those must give back exactly what was written.
            const bool lossy = compression == Imf::PXR24_COMPRESSION || compression == Imf::B44_COMPRESSION ||
                               compression == Imf::B44A_COMPRESSION || compression == Imf::DWAA_COMPRESSION ||
                               compression == Imf::DWAB_COMPRESSION;
            const std::vector<float> decoded[3] = {decode_channel(file, "R"), decode_channel(file, "G"),
                                                   decode_channel(file, "B")};
            for (int y = 0; y < 7; ++y)
                for (int x = 0; x < 19; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const float expected = lossy ? decoded[c][size_t(y) * 19 + size_t(x)] : channel_value(x, y, c);
                        ASSERT_EQ(image.at(x, y)[c], expected)
                            << "compression " << int(compression) << " type " << int(type) << " at " << x << ", " << y;
                        // B44 errs by up to ~6% on these steep 4x4 blocks; this only shows the
                        // reference is the right pixel.
                        ASSERT_NEAR(image.at(x, y)[c], channel_value(x, y, c), 0.1f * channel_value(x, y, c));
                    }
        }
    }
}

TEST(ExrFile, DataWindowWithOffsetIsTheImage) {
    TempDir dir;
    const Imath::Box2i window({-3, 5}, {1, 7});  // 5 x 3, starting left of and below the origin
    write_exr_channels(dir / "offset.exr", window, {"R", "G", "B"}, Imf::ZIP_COMPRESSION, Imf::FLOAT,
                       channel_value);
    const Image image = read_image(dir / "offset.exr");
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 3);
    EXPECT_EQ(image.at(0, 0), Rgb(channel_value(0, 0, 0), channel_value(0, 0, 1), channel_value(0, 0, 2)));
    EXPECT_EQ(image.at(4, 2), Rgb(channel_value(4, 2, 0), channel_value(4, 2, 1), channel_value(4, 2, 2)));
    EXPECT_EQ(image.at(4, 0).r, channel_value(4, 0, 0));
    EXPECT_EQ(image.at(0, 2).r, channel_value(0, 2, 0));
}

TEST(ExrFile, LuminanceOnlyIsReplicatedToGrey) {
    TempDir dir;
    write_exr_channels(dir / "y.exr", Imath::Box2i({0, 0}, {3, 1}), {"Y"}, Imf::PIZ_COMPRESSION, Imf::FLOAT,
                       channel_value);
    const Image image = read_image(dir / "y.exr");
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(3, 1), Rgb(channel_value(3, 1, 0)));
    EXPECT_EQ(image.at(0, 0), Rgb(channel_value(0, 0, 0)));
}

TEST(ExrFile, LuminanceChromaIsConvertedToRgb) {
    TempDir dir;
    const int w = 6, h = 4;
    std::vector<Imf::Rgba> pixels(size_t(w) * size_t(h), Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
    {
        Imf::RgbaOutputFile out((dir / "yc.exr").c_str(), w, h, Imf::WRITE_YC);
        out.setFrameBuffer(pixels.data(), 1, size_t(w));
        out.writePixels(h);
    }
    const Image image = read_image(dir / "yc.exr");
    ASSERT_EQ(image.width, w);
    ASSERT_EQ(image.height, h);
    for (const Rgb& p : image.pixels)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], 0.5f, 0.01f);
}

TEST(ExrFile, MissingGreenAndBlueReadAsZero) {
    TempDir dir;
    write_exr_channels(dir / "r.exr", Imath::Box2i({0, 0}, {1, 0}), {"R", "A"}, Imf::ZIP_COMPRESSION, Imf::FLOAT,
                       channel_value);
    const Image image = read_image(dir / "r.exr");
    EXPECT_EQ(image.at(1, 0), Rgb(channel_value(1, 0, 0), 0.0f, 0.0f));
}

TEST(ExrFile, NoColourChannelIsAnError) {
    TempDir dir;
    write_exr_channels(dir / "z.exr", Imath::Box2i({0, 0}, {1, 0}), {"Z", "A"}, Imf::ZIP_COMPRESSION, Imf::FLOAT,
                       channel_value);
    try {
        read_image(dir / "z.exr");
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(e.message().find("no R, G, B or Y channel (found: A, Z)"), std::string::npos) << e.message();
    }
}

TEST(ExrFile, WritesZipCompressedFloatRgb) {
    TempDir dir;
    write_image(dir / "out.exr", testing::pattern_image(3, 2), DisplayEncoding{});
    Imf::InputFile in((dir / "out.exr").c_str());
    EXPECT_EQ(in.header().compression(), Imf::ZIP_COMPRESSION);
    const Imf::ChannelList& channels = in.header().channels();
    for (const char* name : {"R", "G", "B"}) {
        ASSERT_NE(channels.findChannel(name), nullptr) << name;
        EXPECT_EQ(channels.findChannel(name)->type, Imf::FLOAT) << name;
    }
    EXPECT_EQ(in.header().dataWindow(), Imath::Box2i({0, 0}, {2, 1}));
}

}  // namespace
}  // namespace candela
