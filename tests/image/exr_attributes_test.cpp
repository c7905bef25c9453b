// The walk over OpenEXR header attributes (image/exr_attributes.h) that keeps OpenEXR's C++
// reader from allocating what a corrupt header declares: the inputs the fuzzer found are refused
// with a message, and valid files with attributes of every kind still read.
#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatVectorAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfOutputFile.h>
#include <ImfPreviewImage.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfStringVectorAttribute.h>
#include <ImfVecAttribute.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using testing::read_test_file;
using testing::TempDir;
using testing::write_test_file;

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

// A 4x3 float RGB image with `header`'s extra attributes.
void write_exr(const std::filesystem::path& file, Imf::Header header) {
    std::vector<float> values(4 * 3, 0.5f);
    Imf::FrameBuffer frame;
    for (const char* name : {"R", "G", "B"}) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                      4 * sizeof(float)));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(3);
}

// Inputs fuzz/exr_fuzzer.cpp found: attributes declaring 1 to 1.6 GiB in files of a few hundred
// bytes, one of them hidden from OpenEXR's C core by a channel list whose content is longer than
// its declared size (the C++ reader reads it by content, then takes the following bytes for an
// attribute of 1.6 GiB). Without the check, the C++ reader allocated that much.
TEST(ExrAttributes, FuzzerInputsAreRefusedBeforeAllocating) {
    const std::filesystem::path folder = std::filesystem::path(CANDELA_SOURCE_DIR) / "fuzz/regressions/exr";
    for (const char* name : {"opaque_attribute_size_1.6gib.exr", "opaque_attribute_size_1gib_core_reports.exr",
                             "chlist_content_longer_than_declared.exr"}) {
        SCOPED_TRACE(name);
        EXPECT_CONTAINS(read_error(folder / name), "corrupt OpenEXR header");
    }
    EXPECT_CONTAINS(read_error(folder / "chlist_content_longer_than_declared.exr"),
                    "attribute \"channels\" of type \"chlist\" declares 55 bytes, but its value takes");
}

TEST(ExrAttributes, ValidAttributesOfEveryKindRead) {
    TempDir dir;
    Imf::Header header(4, 3);
    std::vector<Imf::PreviewRgba> preview(2 * 5);
    header.setPreviewImage(Imf::PreviewImage(2, 5, preview.data()));
    header.insert("note", Imf::StringAttribute("a string"));
    header.insert("notes", Imf::StringVectorAttribute({"one", "", "three"}));
    header.insert("weights", Imf::FloatVectorAttribute({1.0f, 2.0f}));
    header.insert("matrix", Imf::M44fAttribute(Imath::M44f()));
    header.insert("dmatrix", Imf::M33dAttribute(Imath::M33d()));
    header.insert("point", Imf::V3fAttribute(Imath::V3f(1, 2, 3)));
    header.insert("count", Imf::IntAttribute(7));
    header.insert("scale", Imf::DoubleAttribute(0.5));
    Imf::addChromaticities(header, Imf::Chromaticities());
    Imf::addTimeCode(header, Imf::TimeCode(1, 2, 3, 4));
    Imf::addKeyCode(header, Imf::KeyCode());
    Imf::addFramesPerSecond(header, Imf::Rational(24, 1));
    Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
    write_exr(dir / "a.exr", header);
    const Image image = read_image(dir / "a.exr");
    EXPECT_EQ(image.width, 4);
    EXPECT_EQ(image.height, 3);
    EXPECT_EQ(image.at(3, 2), Rgb(0.5f));
}

// The declared size of a value the C++ reader reads by its content (an int) changed in a valid
// file: refused, where the reader would have read the following attributes out of step.
TEST(ExrAttributes, DeclaredSizeMustMatchTheValue) {
    TempDir dir;
    Imf::Header header(4, 3);
    header.insert("count", Imf::IntAttribute(7));
    write_exr(dir / "a.exr", header);
    std::string bytes = read_test_file(dir / "a.exr");
    const std::string attribute("count\0int\0", 10);
    const size_t at = bytes.find(attribute);
    ASSERT_NE(at, std::string::npos);
    bytes[at + attribute.size()] = 5;  // little-endian size 4 -> 5
    write_test_file(dir / "a.exr", bytes);
    EXPECT_CONTAINS(read_error(dir / "a.exr"), "corrupt OpenEXR header");
    EXPECT_CONTAINS(read_error(dir / "a.exr"), "count");
}

}  // namespace
}  // namespace candela
