#include "candela/formats/mesh/ply_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "support/fixtures.h"
#include "support/printers.h"

namespace candela {

namespace CANDELA_UNITY_ID {

TriangleMesh parse_fixture(const std::string& name) { return parse_ply(test::read_fixture("meshes/" + name), name); }

// Header lines joined by newlines, ending with end_header.
std::string header(const std::string& format, const std::vector<std::string>& lines) {
    std::string h = "ply\nformat " + format + " 1.0\n";
    for (const std::string& l : lines) h += l + "\n";
    return h + "end_header\n";
}

// Appends binary values in a chosen byte order.
class BinaryWriter {
  public:
    BinaryWriter(std::string start, bool big_endian) : bytes_(std::move(start)), big_endian_(big_endian) {}
    template <class... T>
    BinaryWriter& put(T... values) {
        (put_one(values), ...);
        return *this;
    }
    const std::string& bytes() const { return bytes_; }

  private:
    template <class T>
    void put_one(T value) {
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (big_endian_ != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
        bytes_.append(b, sizeof(T));
    }
    std::string bytes_;
    bool big_endian_;
};

SceneError parse_error(const std::string& bytes) {
    try {
        parse_ply(bytes, "test.ply");
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError";
    return SceneError({}, "");
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// Every triangle of a mesh centred on the origin winds counter-clockwise seen from outside.
void expect_outward_winding(const TriangleMesh& m) {
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
        EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0.0f) << "triangle " << t;
    }
}

const std::vector<Vec3f> kCubePositions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
const std::vector<uint32_t> kCubeIndices = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                            3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};

TEST(PlyLoader, ReadsAsciiTriangles) {
    const TriangleMesh m = parse_fixture("triangles_ascii.ply");
    EXPECT_EQ(m.positions, (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5f}}));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.uvs.empty());
}

TEST(PlyLoader, ReadsAsciiQuadsWithNormalsAndUvsAsStored) {
    const TriangleMesh m = parse_fixture("quads_normals_uvs_ascii.ply");
    ASSERT_EQ(m.positions.size(), 6u);
    EXPECT_EQ(m.positions[3], Vec3f(2, 1, 0));
    // Quads (0 1 4 5) and (1 2 3 4), fanned from their first corner.
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 4, 0, 4, 5, 1, 2, 3, 1, 3, 4}));
    ASSERT_EQ(m.normals.size(), 6u);
    EXPECT_EQ(m.normals[0], Vec3f(0, 0, 1));
    EXPECT_EQ(m.normals[1], Vec3f(0, 0, 2));  // parse_ply keeps it; load_mesh normalizes
    ASSERT_EQ(m.uvs.size(), 6u);
    EXPECT_EQ(m.uvs[1], Vec2f(0.5f, 0));
    EXPECT_EQ(m.uvs[3], Vec2f(1, 1));
}

TEST(PlyLoader, ReadsBinaryLittleEndianCube) {
    const TriangleMesh m = parse_fixture("cube.ply");
    EXPECT_EQ(m.positions, kCubePositions);
    EXPECT_EQ(m.indices, kCubeIndices);
    expect_outward_winding(m);
}

TEST(PlyLoader, ReadsBinaryBigEndianCubeWithDoublesAndUintLists) {
    const TriangleMesh m = parse_fixture("cube_big_endian.ply");
    EXPECT_EQ(m.positions, kCubePositions);
    EXPECT_EQ(m.indices, kCubeIndices);
}

TEST(PlyLoader, SkipsUnknownAsciiElementsAndPropertiesInAnyOrder) {
    const TriangleMesh m = parse_fixture("extra_elements_ascii.ply");
    EXPECT_EQ(m.positions, (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));  // texture_u/v
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));         // vertex_index
    EXPECT_TRUE(m.normals.empty());
}

TEST(PlyLoader, SkipsUnknownBinaryElementsAndPropertiesInAnyOrder) {
    const TriangleMesh m = parse_fixture("extra_elements_binary.ply");
    EXPECT_EQ(m.positions, (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    EXPECT_EQ(m.normals, std::vector<Vec3f>(4, Vec3f(0, 0, 1)));
    EXPECT_EQ(m.uvs, (std::vector<Vec2f>{{0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}}));  // s/t
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

// One vertex whose eight properties use the eight scalar types, in both byte orders and with
// both spellings of the type names.
TEST(PlyLoader, ReadsEveryBinaryScalarType) {
    const std::vector<std::vector<std::string>> spellings = {
        {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"},
        {"int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"}};
    const std::vector<std::string> names = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};
    for (const bool big : {false, true}) {
        for (const auto& types : spellings) {
            std::vector<std::string> lines = {"element vertex 3"};
            for (size_t i = 0; i < names.size(); ++i)
                lines.push_back("property " + types[i] + " " + names[i]);
            lines.push_back("element face 1");
            lines.push_back("property list uchar int vertex_indices");
            BinaryWriter w(header(big ? "binary_big_endian" : "binary_little_endian", lines), big);
            for (int i = 0; i < 3; ++i)
                w.put(int8_t(-5 + i), uint8_t(200 + i), int16_t(-3000 + i), uint16_t(60000 + i),
                      int32_t(-70000 + i), uint32_t(4000000 + i), 0.25f + float(i), -0.5 + double(i));
            w.put(uint8_t(3), 0, 1, 2);
            const TriangleMesh m = parse_ply(w.bytes(), "types.ply");
            SCOPED_TRACE(types[0] + (big ? " big endian" : " little endian"));
            ASSERT_EQ(m.positions.size(), 3u);
            EXPECT_EQ(m.positions[2], Vec3f(-3, 202, -2998));
            EXPECT_EQ(m.normals[2], Vec3f(60002, -69998, 4000002));
            EXPECT_EQ(m.uvs[2], Vec2f(2.25f, 1.5f));
            EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
        }
    }
}

TEST(PlyLoader, ReadsEveryAsciiScalarType) {
    const std::string bytes =
        header("ascii", {"element vertex 3", "property int8 x", "property uchar y", "property int16 z",
                         "property uint16 nx", "property int ny", "property uint32 nz", "property float32 s",
                         "property double t", "element face 1", "property list uint8 int32 vertex_indices"}) +
        "-128 255 -32768 65535 -2147483648 4294967295 +1.5 -2e-1\n"
        "0 0 0 0 0 0 0 0\n1 1 1 1 1 1 1 1\n3 0 1 2\n";
    const TriangleMesh m = parse_ply(bytes, "types.ply");
    EXPECT_EQ(m.positions[0], Vec3f(-128, 255, -32768));
    EXPECT_EQ(m.normals[0], Vec3f(65535, -2147483648.0f, 4294967295.0f));
    EXPECT_EQ(m.uvs[0], Vec2f(1.5f, -0.2f));
}

TEST(PlyLoader, AcceptsEveryIntegerTypeForFaceCountsAndIndices) {
    const std::vector<std::pair<std::string, std::string>> types = {{"uchar", "int"},     {"uchar", "uint"},
                                                                    {"int", "int"},       {"uint", "uint"},
                                                                    {"ushort", "ushort"}, {"char", "uint8"}};
    for (const auto& [count, index] : types) {
        BinaryWriter w(header("binary_little_endian",
                              {"element vertex 4", "property float x", "property float y", "property float z",
                               "element face 1", "property list " + count + " " + index + " vertex_indices"}),
                       false);
        for (int i = 0; i < 4; ++i) w.put(float(i), 0.0f, 0.0f);
        auto put_as = [&w](const std::string& type, int v) {
            if (type == "int")
                w.put(int32_t(v));
            else if (type == "uint")
                w.put(uint32_t(v));
            else if (type == "ushort")
                w.put(uint16_t(v));
            else if (type == "char")
                w.put(int8_t(v));
            else
                w.put(uint8_t(v));
        };
        put_as(count, 4);
        for (int v : {3, 2, 1, 0}) put_as(index, v);
        SCOPED_TRACE(count + " " + index);
        EXPECT_EQ(parse_ply(w.bytes(), "t.ply").indices, (std::vector<uint32_t>{3, 2, 1, 3, 1, 0}));
    }
}

TEST(PlyLoader, FanTriangulatesPolygonsKeepingWinding) {
    const std::string bytes =
        header("ascii", {"element vertex 6", "property float x", "property float y", "property float z",
                         "element face 1", "property list uchar int vertex_indices"}) +
        "1 0 0\n0.5 0.8 0\n-0.5 0.8 0\n-1 0 0\n-0.5 -0.8 0\n0.5 -0.8 0\n6 0 1 2 3 4 5\n";
    const TriangleMesh m = parse_ply(bytes, "hexagon.ply");
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}));
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3f a = m.positions[m.indices[3 * t]];
        EXPECT_GT(cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a).z,
                  0.0f);
    }
}

TEST(PlyLoader, AcceptsCrLfLineEndings) {
    const std::string bytes =
        "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
        "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
        "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    const TriangleMesh m = parse_ply(bytes, "crlf.ply");
    EXPECT_EQ(m.positions[1], Vec3f(1, 0, 0));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(PlyLoader, RejectsTruncatedBinaryFile) {
    const SceneError e = parse_error(test::read_fixture("meshes/truncated_binary.ply"));
    EXPECT_EQ(e.where().file, "test.ply");
    EXPECT_TRUE(contains(e.message(), "element \"face\", record 4 of 6"));
    EXPECT_TRUE(contains(e.message(), "unexpected end of file"));
}

TEST(PlyLoader, RejectsCountsTheDataCannotHoldBeforeAllocating) {
    const std::vector<std::string> lines = {
        "element vertex 4000000000", "property float x", "property float y",
        "property float z",          "element face 0",   "property list uchar int vertex_indices"};
    const SceneError binary = parse_error(header("binary_little_endian", lines) + std::string(64, '\0'));
    EXPECT_EQ(binary.where().line, 3);
    EXPECT_TRUE(contains(binary.message(), "declares 4000000000 records of at least 12 bytes each"));
    const SceneError ascii = parse_error(header("ascii", lines) + "0 0 0\n");
    EXPECT_EQ(ascii.where().line, 3);

    // The largest count there is, in an element the loader would skip: no overflow, no loop.
    std::vector<std::string> extra = {"element vertex 0",
                                      "property float x",
                                      "property float y",
                                      "property float z",
                                      "element face 0",
                                      "property list uchar int vertex_indices",
                                      "element extra 18446744073709551615",
                                      "property uchar a",
                                      "property uchar b"};
    const SceneError skipped = parse_error(header("binary_little_endian", extra) + std::string(64, '\0'));
    EXPECT_EQ(skipped.where().line, 9);
    EXPECT_TRUE(contains(skipped.message(), "declares 18446744073709551615 records of at least 2 bytes"));
}

TEST(PlyLoader, RejectsMoreVerticesThan32BitIndicesReach) {
    const SceneError e =
        parse_error(header("binary_little_endian",
                           {"element vertex 4294967296", "property uchar x", "property uchar y",
                            "property uchar z", "element face 0", "property list uchar int vertex_indices"}));
    EXPECT_EQ(e.where().line, 3);
    EXPECT_TRUE(contains(e.message(), "4294967296 vertices are more than"));
}

TEST(PlyLoader, RejectsCountsThatOverflow) {
    const SceneError e =
        parse_error(header("ascii", {"element vertex 18446744073709551616", "property float x"}));
    EXPECT_EQ(e.where().line, 3);
    EXPECT_TRUE(contains(e.message(), "expected an element count"));
    EXPECT_TRUE(
        contains(parse_error(header("ascii", {"element vertex -3"})).message(), "expected an element count"));
}

TEST(PlyLoader, RejectsHugeListCountsAsTruncation) {
    const std::string start =
        header("binary_little_endian",
               {"element vertex 3", "property float x", "property float y", "property float z",
                "element face 1", "property list uint int vertex_indices"});
    BinaryWriter faces(start, false);
    for (int i = 0; i < 3; ++i) faces.put(0.0f, 0.0f, 0.0f);
    faces.put(uint32_t(4294967295u), 0, 1, 2);
    EXPECT_TRUE(contains(parse_error(faces.bytes()).message(), "unexpected end of file"));

    // The same in a list the loader skips.
    BinaryWriter skipped(
        header("binary_little_endian",
               {"element vertex 3", "property float x", "property float y", "property float z",
                "property list uint double w", "element face 1", "property list uchar int vertex_indices"}),
        false);
    skipped.put(0.0f, 0.0f, 0.0f, uint32_t(4294967295u));
    EXPECT_TRUE(contains(parse_error(skipped.bytes() + std::string(64, '\0')).message(), "record 1 of 3"));
}

TEST(PlyLoader, RejectsOutOfRangeIndexWithItsLine) {
    const SceneError e = parse_error(test::read_fixture("meshes/bad_index.ply"));
    EXPECT_EQ(e.where().line, 14);
    EXPECT_TRUE(contains(e.message(), "vertex index 7 is out of range; the file has 3 vertices"));
    EXPECT_TRUE(contains(e.message(), "element \"face\", record 2 of 2"));
}

TEST(PlyLoader, RejectsNegativeBinaryIndex) {
    BinaryWriter w(header("binary_little_endian",
                          {"element vertex 3", "property float x", "property float y", "property float z",
                           "element face 1", "property list uchar int vertex_indices"}),
                   false);
    for (int i = 0; i < 3; ++i) w.put(0.0f, 0.0f, 0.0f);
    w.put(uint8_t(3), 0, -1, 2);
    EXPECT_TRUE(contains(parse_error(w.bytes()).message(), "vertex index -1 is out of range"));
}

TEST(PlyLoader, RejectsFacesOfFewerThanThreeVertices) {
    const std::string bytes =
        header("ascii", {"element vertex 3", "property float x", "property float y", "property float z",
                         "element face 1", "property list uchar int vertex_indices"}) +
        "0 0 0\n1 0 0\n0 1 0\n2 0 1\n";
    const SceneError e = parse_error(bytes);
    EXPECT_EQ(e.where().line, 13);
    EXPECT_TRUE(contains(e.message(), "a face has 2 vertices; expected at least 3"));
}

TEST(PlyLoader, RejectsBadAsciiValuesWithTheirLine) {
    const std::string start =
        header("ascii", {"element vertex 3", "property float x", "property float y", "property float z",
                         "element face 1", "property list uchar int vertex_indices"});
    const SceneError word = parse_error(start + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(word.where().line, 11);
    EXPECT_TRUE(contains(word.message(), "expected a value of type float, got \"zero\""));
    const SceneError range = parse_error(start + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n");
    EXPECT_EQ(range.where().line, 13);
    EXPECT_TRUE(contains(range.message(), "expected a value of type uchar, got \"300\""));
    const SceneError fraction = parse_error(start + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n");
    EXPECT_TRUE(contains(fraction.message(), "expected a value of type int, got \"1.5\""));
}

TEST(PlyLoader, RejectsTruncatedAsciiFileWithTheLastLine) {
    const std::string bytes =
        header("ascii", {"element vertex 3", "property float x", "property float y", "property float z",
                         "element face 2", "property list uchar int vertex_indices"}) +
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0";
    const SceneError e = parse_error(bytes);
    EXPECT_EQ(e.where().line, 14);
    EXPECT_TRUE(contains(e.message(), "unexpected end of file"));
}

struct HeaderCase {
    std::string bytes;
    int line;
    std::string message;
};

TEST(PlyLoader, RejectsBadHeadersWithTheirLine) {
    const std::string xyz = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string face = "element face 0\nproperty list uchar int vertex_indices\n";
    const std::vector<HeaderCase> cases = {
        {"OFF\n3 1 0\n", 1, "not a PLY file"},
        {"ply\nformat ascii 1.0\n" + xyz + face, 8, "no \"end_header\" line"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\nend_header\n", 4,
         "unknown PLY property type \"flaot\"; expected one of: char, uchar"},
        {"ply\nformat ascii 1.0\nvertex 1\nend_header\n", 3, "unknown PLY header keyword \"vertex\""},
        {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", 3, "a property before any element"},
        {"ply\nformat text 1.0\nend_header\n", 2, "unknown PLY format \"text\""},
        {"ply\nformat ascii 2.0\nend_header\n", 2, "unsupported PLY version"},
        {"ply\n" + xyz + face + "end_header\n", 8, "no \"format\" line"},
        {"ply\nformat ascii 1.0\n" + face + "end_header\n", 5, "declares no \"vertex\" element"},
        {"ply\nformat ascii 1.0\n" + xyz + "end_header\n0 0 0\n", 7, "declares no \"face\" element"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n" + face +
             "end_header\n",
         3, "no \"z\" property"},
        {"ply\nformat ascii 1.0\n" + xyz + "property float nx\nproperty float nz\n" + face + "end_header\n",
         3, "only some of the normal properties"},
        {"ply\nformat ascii 1.0\n" + xyz + "element face 0\nproperty int vertex_indices\nend_header\n", 7,
         "\"vertex_indices\" must be a list"},
        {"ply\nformat ascii 1.0\n" + xyz +
             "element face 0\nproperty list float int vertex_indices\nend_header\n",
         8, "a list count must have an integer type"},
        {"ply\nformat ascii 1.0\n" + xyz +
             "element face 0\nproperty list uchar float vertex_indices\nend_header\n",
         7, "must list integers"},
        {"ply\nformat ascii 1.0\n" + xyz + "element face 0\nproperty list uchar int corners\nend_header\n", 7,
         "no \"vertex_indices\" (or \"vertex_index\") list"},
        {"ply\nformat ascii 1.0\n" + xyz + xyz + face + "end_header\n", 7,
         "element \"vertex\" is declared twice"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty double x\nend_header\n", 5,
         "declares property \"x\" twice"},
    };
    for (const HeaderCase& c : cases) {
        SCOPED_TRACE(c.bytes);
        const SceneError e = parse_error(c.bytes);
        EXPECT_EQ(e.where().file, "test.ply");
        EXPECT_EQ(e.where().line, c.line);
        EXPECT_TRUE(contains(e.message(), c.message));
    }
}

}  // namespace
}  // namespace candela
