// AOV layers as files (image/image_layers.h): inside one OpenEXR file under their conventional
// channel names, read back exactly; beside other formats as one file per layer, named
// <stem>.<layer>.<ext>, each in an encoding that keeps its values.
#include "candela/image/image_layers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using testing::pattern_image;

ImageLayer make_layer(const std::string& name, int channels, std::array<std::string, 3> names, Image image) {
    return ImageLayer{name, channels, std::move(names), std::move(image)};
}

// Layers as the film resolves them (film/aov_layers.h): values a display format cannot hold as
// they are (negative normals and positions, depths over 1, the miss depth).
std::vector<ImageLayer> sample_layers(int w, int h) {
    Image normal(w, h), depth(w, h), position(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            normal.at(x, y) = Rgb(0.0f, 0.6f, -0.8f);
            depth.at(x, y) = Rgb(x == 0 ? 1e10f : 2.0f + float(x) + 0.25f * float(y), 0.0f, 0.0f);
            position.at(x, y) = Rgb(-float(x), float(y), 3.5f);
        }
    return {make_layer("albedo", 3, {"albedo.R", "albedo.G", "albedo.B"}, pattern_image(w, h)),
            make_layer("normal", 3, {"N.X", "N.Y", "N.Z"}, normal), make_layer("depth", 1, {"Z", "", ""}, depth),
            make_layer("position", 3, {"P.X", "P.Y", "P.Z"}, position)};
}

TEST(ImageLayers, ExrHoldsEveryLayerUnderItsChannelNames) {
    TempDir dir;
    const Image beauty = pattern_image(7, 5, 0.0f, 4.0f);
    const std::vector<ImageLayer> layers = sample_layers(7, 5);
    const auto file = dir / "out.exr";
    write_image_with_layers(file, beauty, layers, DisplayEncoding{});
    std::vector<std::string> names = read_exr_channel_names(file);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "N.X", "N.Y", "N.Z", "P.X", "P.Y", "P.Z", "R", "Z",
                                               "albedo.B", "albedo.G", "albedo.R"}));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});  // no side files
    // Float channels: every value back exactly; the beauty still reads as the image.
    const Image back = read_image(file);
    EXPECT_EQ(back.pixels, beauty.pixels);
    for (const ImageLayer& layer : layers) {
        std::vector<std::string> channels(layer.channel_names.begin(), layer.channel_names.begin() + layer.channels);
        const Image values = read_exr_channels(file, channels);
        for (size_t i = 0; i < values.pixels.size(); ++i)
            for (int c = 0; c < layer.channels; ++c)
                ASSERT_EQ(values.pixels[i][c], layer.image.pixels[i][c]) << layer.name << " pixel " << i;
    }
}

TEST(ImageLayers, OtherFormatsWriteOneFileBesideThemPerLayer) {
    TempDir dir;
    const std::vector<ImageLayer> layers = sample_layers(6, 4);
    write_image_with_layers(dir / "out.png", pattern_image(6, 4), layers, DisplayEncoding{});
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.albedo.png", "out.depth.pfm", "out.normal.png", "out.png",
                                                     "out.position.pfm"}));
    // Depth and position linear and exact; the one depth channel as grey.
    const Image depth = read_image(dir / "out.depth.pfm");
    const Image position = read_image(dir / "out.position.pfm");
    for (size_t i = 0; i < depth.pixels.size(); ++i) {
        const float z = layers[2].image.pixels[i].r;
        EXPECT_EQ(depth.pixels[i], Rgb(z)) << i;
        EXPECT_EQ(position.pixels[i], layers[3].image.pixels[i]) << i;
    }
    // Normals mapped from [-1, 1] to [0, 1] and stored linearly: (0, 0.6, -0.8) -> (0.5, 0.8, 0.1)
    // as 8-bit codes 128, 204, 26, which the PNG reader decodes as sRGB.
    const Image normal = read_image(dir / "out.normal.png");
    auto srgb_decode = [](float code) {
        const float v = code / 255.0f;
        return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    };
    EXPECT_NEAR(normal.pixels[0].r, srgb_decode(128.0f), 1e-3f);
    EXPECT_NEAR(normal.pixels[0].g, srgb_decode(204.0f), 1e-3f);
    EXPECT_NEAR(normal.pixels[0].b, srgb_decode(26.0f), 1e-3f);

    // A float output keeps normals as they are.
    TempDir pfm;
    write_image_with_layers(pfm / "out.pfm", pattern_image(6, 4), layers, DisplayEncoding{});
    EXPECT_EQ(read_image(pfm / "out.normal.pfm").pixels[0], Rgb(0.0f, 0.6f, -0.8f));
    EXPECT_EQ(pfm.entries(), (std::vector<std::string>{"out.albedo.pfm", "out.depth.pfm", "out.normal.pfm", "out.pfm",
                                                     "out.position.pfm"}));
}

TEST(ImageLayers, SideFileNames) {
    const ImageLayer albedo = make_layer("albedo", 3, {}, Image(1, 1));
    const ImageLayer depth = make_layer("depth", 1, {}, Image(1, 1));
    EXPECT_EQ(layer_side_file("renders/frame.0001.png", albedo),
              std::filesystem::path("renders/frame.0001.albedo.png"));
    EXPECT_EQ(layer_side_file("renders/frame.hdr", depth), std::filesystem::path("renders/frame.depth.pfm"));
}

TEST(ImageLayers, NonFiniteLayerIsNotWritten) {
    TempDir dir;
    std::vector<ImageLayer> layers = sample_layers(3, 2);
    layers[1].image.pixels[4] = Rgb(0.0f, std::nanf(""), 0.0f);
    EXPECT_THROW(write_image_with_layers(dir / "out.exr", pattern_image(3, 2), layers, DisplayEncoding{}), RenderError);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace candela
