// Bad image files and bad images to write: each error names the file and says what is wrong.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::TempDir;
using testing::pattern_image;
using testing::read_test_file;
using testing::write_test_file;

// Runs read_image and returns the SceneError's message, checking it names the file.
std::string read_error(const std::filesystem::path& file) {
    try {
        read_image(file);
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, file.string());
        return e.message();
    }
    ADD_FAILURE() << "read_image(" << file << ") did not throw";
    return "";
}

#define EXPECT_CONTAINS(text, fragment) \
    EXPECT_NE(std::string(text).find(fragment), std::string::npos) << "message: " << (text)

TEST(ImageReadErrors, MissingFile) {
    TempDir dir;
    EXPECT_CONTAINS(read_error(dir / "nothing.exr"), "not found");
}

TEST(ImageReadErrors, Directory) {
    TempDir dir;
    std::filesystem::create_directory(dir / "folder.png");
    EXPECT_CONTAINS(read_error(dir / "folder.png"), "is a directory");
}

TEST(ImageReadErrors, UnknownExtensionListsKnownOnes) {
    TempDir dir;
    write_test_file(dir / "a.jpg", "whatever");
    const std::string message = read_error(dir / "a.jpg");
    EXPECT_CONTAINS(message, "unknown image extension \".jpg\"");
    EXPECT_CONTAINS(message, ".exr, .hdr, .pfm, .png");
    EXPECT_CONTAINS(read_error(dir / "noextension"), "no extension");
}

TEST(ImageReadErrors, PpmIsWriteOnly) {
    TempDir dir;
    write_test_file(dir / "a.ppm", "P3\n1 1\n255\n0 0 0 ");
    EXPECT_CONTAINS(read_error(dir / "a.ppm"), "cannot read .ppm images");
}

TEST(ImageReadErrors, TruncatedPfm) {
    TempDir dir;
    write_image(dir / "a.pfm", pattern_image(4, 3), DisplayEncoding{});
    std::string bytes = read_test_file(dir / "a.pfm");
    bytes.resize(bytes.size() - 5);
    write_test_file(dir / "a.pfm", bytes);
    EXPECT_CONTAINS(read_error(dir / "a.pfm"), "truncated PFM image: expected 144 bytes of pixel data, found 139");
}

TEST(ImageReadErrors, CorruptPfmHeaders) {
    TempDir dir;
    const auto error_for = [&](const std::string& contents) {
        write_test_file(dir / "a.pfm", contents);
        return read_error(dir / "a.pfm");
    };
    EXPECT_CONTAINS(error_for("P6\n1 1\n255\n"), "not a PFM image");
    EXPECT_CONTAINS(error_for("PF\nwide 1\n-1\n"), "expected the width, got \"wide\"");
    EXPECT_CONTAINS(error_for("PF\n1 1\n0\n" + std::string(12, '\0')), "scale must not be 0");
    EXPECT_CONTAINS(error_for("PF\n2"), "truncated PFM header: expected the height");
    EXPECT_CONTAINS(error_for(""), "truncated PFM header");
    EXPECT_CONTAINS(error_for("PF\n0 4\n-1\n"), "zero size");
    EXPECT_CONTAINS(error_for("PF\n70000 1\n-1\n"), "exceeds the limit of 65536 pixels per side");
    EXPECT_CONTAINS(error_for("PF\n60000 60000\n-1\n"), "exceeds the limit of 268435456 pixels");
}

TEST(ImageReadErrors, GarbageExr) {
    TempDir dir;
    write_test_file(dir / "a.exr", "this is not an image at all");
    EXPECT_CONTAINS(read_error(dir / "a.exr"), "not an OpenEXR image");
}

TEST(ImageReadErrors, TruncatedExr) {
    TempDir dir;
    write_image(dir / "a.exr", pattern_image(64, 64), DisplayEncoding{});
    std::string bytes = read_test_file(dir / "a.exr");
    bytes.resize(bytes.size() / 2);
    write_test_file(dir / "a.exr", bytes);
    // Found before the image is allocated, from the chunk table and the chunks' leaders.
    EXPECT_CONTAINS(read_error(dir / "a.exr"), "truncated or corrupt OpenEXR image: the pixel data of row");
}

TEST(ImageReadErrors, GarbageHdr) {
    TempDir dir;
    write_test_file(dir / "a.hdr", "\x01\x02garbage\n\n");
    EXPECT_CONTAINS(read_error(dir / "a.hdr"), "not a Radiance HDR image");
    write_test_file(dir / "a.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n");
    EXPECT_CONTAINS(read_error(dir / "a.hdr"), "unsupported Radiance HDR format \"32-bit_rle_xyze\"");
    write_test_file(dir / "a.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+X 1 -Y 1\n");
    EXPECT_CONTAINS(read_error(dir / "a.hdr"), "expected \"-Y height +X width\"");
    write_test_file(dir / "a.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n");
    EXPECT_CONTAINS(read_error(dir / "a.hdr"), "truncated Radiance HDR header");
}

TEST(ImageReadErrors, TruncatedHdr) {
    TempDir dir;
    for (int width : {5, 40}) {  // flat and run-length encoded rows
        write_image(dir / "a.hdr", pattern_image(width, 6, 0.0f, 10.0f), DisplayEncoding{});
        std::string bytes = read_test_file(dir / "a.hdr");
        bytes.resize(bytes.size() - 10);
        write_test_file(dir / "a.hdr", bytes);
        EXPECT_CONTAINS(read_error(dir / "a.hdr"), "truncated Radiance HDR image: data ends in row 5 of 6");
    }
}

TEST(ImageReadErrors, GarbagePng) {
    TempDir dir;
    write_test_file(dir / "a.png", "GIF89a not a png");
    EXPECT_CONTAINS(read_error(dir / "a.png"), "not a PNG image");
    write_image(dir / "b.png", pattern_image(20, 20), DisplayEncoding{});
    std::string bytes = read_test_file(dir / "b.png");
    bytes.resize(bytes.size() / 2);
    write_test_file(dir / "b.png", bytes);
    EXPECT_CONTAINS(read_error(dir / "b.png"), "corrupt PNG image");
}

TEST(ImageReadErrors, NonFinitePixelInFile) {
    TempDir dir;
    Image image(2, 1);
    image.at(1, 0).g = std::numeric_limits<float>::infinity();
    // Bypass write_image (which refuses such images) with a hand-written PFM.
    std::string bytes = "PF\n2 1\n-1\n";
    for (const Rgb& p : image.pixels)
        for (int c = 0; c < 3; ++c) {
            const float v = p[c];
            bytes.append(reinterpret_cast<const char*>(&v), sizeof(v));
        }
    write_test_file(dir / "inf.pfm", bytes);
    EXPECT_CONTAINS(read_error(dir / "inf.pfm"), "pixel (1, 0) is not finite");
}

TEST(ImageWriteErrors, RefusesNanAndInfinityAndWritesNothing) {
    TempDir dir;
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                      -std::numeric_limits<float>::infinity()}) {
        for (const char* name : {"a.exr", "a.pfm", "a.hdr", "a.png", "a.ppm"}) {
            Image image = pattern_image(3, 2);
            image.at(2, 1).b = bad;
            try {
                write_image(dir / name, image, DisplayEncoding{});
                ADD_FAILURE() << name << " was written with " << bad;
            } catch (const RenderError& e) {
                EXPECT_CONTAINS(e.what(), "pixel (2, 1) is not finite");
            }
        }
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageWriteErrors, UnknownExtensionListsWritableOnes) {
    TempDir dir;
    try {
        write_image(dir / "a.tiff", pattern_image(2, 2), DisplayEncoding{});
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, (dir / "a.tiff").string());
        EXPECT_CONTAINS(e.message(), "unknown image extension \".tiff\"; expected one of: .exr, .hdr, .pfm, .png, .ppm");
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageWriteErrors, MissingFolderThrowsAndLeavesNothing) {
    TempDir dir;
    for (const char* name : {"a.exr", "a.pfm", "a.hdr", "a.png", "a.ppm"}) {
        const auto destination = dir / "missing" / name;
        try {
            write_image(destination, pattern_image(2, 2), DisplayEncoding{});
            ADD_FAILURE() << "expected SceneError for " << name;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().file, destination.string());
            EXPECT_CONTAINS(e.message(), "does not exist");
        }
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageWriteErrors, InconsistentImageIsAnInternalError) {
    TempDir dir;
    Image image(3, 2);
    image.pixels.pop_back();
    EXPECT_THROW(write_image(dir / "a.pfm", image, DisplayEncoding{}), RenderError);
    EXPECT_THROW(write_image(dir / "a.pfm", Image{}, DisplayEncoding{}), RenderError);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageExtensions, KnowsWhatCanBeReadAndWritten) {
    EXPECT_TRUE(is_writable_image_extension("out.PNG"));
    EXPECT_TRUE(is_writable_image_extension("dir.d/out.ppm"));
    EXPECT_FALSE(is_writable_image_extension("out.jpg"));
    EXPECT_FALSE(is_writable_image_extension("out"));
    EXPECT_TRUE(is_readable_image_extension("sky.hdr"));
    EXPECT_TRUE(is_readable_image_extension("sky.Exr"));
    EXPECT_FALSE(is_readable_image_extension("out.ppm"));
}

}  // namespace
}  // namespace candela
