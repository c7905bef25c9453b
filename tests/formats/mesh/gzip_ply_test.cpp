// gzip-compressed PLY files (.ply.gz), as pbrt-v4 scenes ship their meshes.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/formats/mesh/gzip_stream.h"
#include "candela/formats/mesh/mesh_loader.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

std::filesystem::path fixture(const std::string& name) {
    return std::filesystem::path(CANDELA_TEST_DATA_DIR) / "meshes" / name;
}

std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "gzip_ply_test";
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path write_bytes(const std::string& name, const std::string& bytes) {
    const std::filesystem::path file = scratch(name);
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

// One gzip member holding `data`, as the gzip tool writes it.
std::string gzip(const std::string& data) {
    z_stream z{};
    EXPECT_EQ(deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

SceneError load_error(const std::filesystem::path& file, const MeshSizeCheck& check = {}) {
    try {
        load_mesh(file, check);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError for " << file;
    return SceneError({}, "");
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// An ascii PLY of an n x n grid of quads: large enough that its header is inflated long before
// its data.
std::string grid_ply(int n) {
    std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string((n + 1) * (n + 1)) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(n * n) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) ply += std::to_string(x) + " " + std::to_string(y) + " 0\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int v = y * (n + 1) + x;
            ply += "4 " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + n + 2) + " " +
                   std::to_string(v + n + 1) + "\n";
        }
    return ply;
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.indices, b.indices);
}

TEST(GzipPly, LoadsAsThePlainFileLoads) {
    for (const char* name : {"cube.ply", "cube_big_endian.ply", "quads_normals_uvs_ascii.ply"}) {
        SCOPED_TRACE(name);
        const TriangleMesh plain = load_mesh(fixture(name));
        const std::filesystem::path gz = write_bytes(std::string(name) + ".gz", gzip(read_bytes(fixture(name))));
        expect_same_mesh(load_mesh(gz), plain);
    }
}

TEST(GzipPly, LoadsTheCommittedFixture) {
    // Written by Python's gzip module (make_binary_fixtures.py), not by the zlib calls above.
    expect_same_mesh(load_mesh(fixture("cube.ply.gz")), load_mesh(fixture("cube.ply")));
}

TEST(GzipPly, RejectsGzippedDataThatIsNotAPlyAtItsFirstLine) {
    const SceneError e = load_error(write_bytes("not_a_ply.ply.gz", gzip(std::string(1 << 20, 'x'))));
    EXPECT_EQ(e.where().line, 1);
    EXPECT_TRUE(contains(e.message(), "not a PLY file"));
}

TEST(GzipPly, ChoosesTheFormatByTheDoubleExtensionIgnoringCase) {
    const std::filesystem::path gz = write_bytes("CUBE.Ply.GZ", gzip(read_bytes(fixture("cube.ply"))));
    EXPECT_EQ(load_mesh(gz).triangle_count(), 12u);
    // ".gz" alone names no mesh format.
    const std::filesystem::path bare = write_bytes("cube.gz", gzip(read_bytes(fixture("cube.ply"))));
    EXPECT_TRUE(contains(load_error(bare).message(), "unknown mesh file extension \".gz\""));
}

TEST(GzipPly, ReadsUncompressedDataNamedPlyGzAsGzreadDoes) {
    const std::filesystem::path file = write_bytes("plain.ply.gz", read_bytes(fixture("cube.ply")));
    expect_same_mesh(load_mesh(file), load_mesh(fixture("cube.ply")));
}

TEST(GzipPly, ReadsConcatenatedMembersAsOneStream) {
    const std::string bytes = read_bytes(fixture("cube.ply"));
    const size_t half = bytes.size() / 2;
    const std::filesystem::path file =
        write_bytes("two_members.ply.gz", gzip(bytes.substr(0, half)) + gzip(bytes.substr(half)));
    expect_same_mesh(load_mesh(file), load_mesh(fixture("cube.ply")));
}

TEST(GzipPly, RejectsATruncatedStream) {
    const std::string gz = gzip(read_bytes(fixture("cube.ply")));
    for (const size_t cut : {size_t{4}, gz.size() / 2, gz.size() - 1}) {
        SCOPED_TRACE(cut);
        const std::filesystem::path file = write_bytes("truncated.ply.gz", gz.substr(0, cut));
        const SceneError e = load_error(file);
        EXPECT_EQ(e.where().file, file.string());
        EXPECT_TRUE(contains(e.message(), "the gzip data ends before the stream does (file truncated?)"));
    }
}

TEST(GzipPly, RejectsCorruptDataWithZlibsReason) {
    std::string gz = gzip(read_bytes(fixture("cube.ply")));
    // The CRC-32 in the trailer no longer matches.
    gz[gz.size() - 6] = static_cast<char>(gz[gz.size() - 6] ^ 0x55);
    const SceneError crc = load_error(write_bytes("bad_crc.ply.gz", gz));
    EXPECT_TRUE(contains(crc.message(), "corrupt gzip data (incorrect data check)"));
    // A deflate block type that does not exist (bits 11 after the 10-byte header's first bit).
    std::string bad_block = gzip(read_bytes(fixture("cube.ply")));
    bad_block[10] = static_cast<char>(0x07);
    const SceneError block = load_error(write_bytes("bad_block.ply.gz", bad_block));
    EXPECT_TRUE(contains(block.message(), "corrupt gzip data (invalid block type) near compressed byte"));
}

TEST(GzipPly, LocatesErrorsInTheInflatedPlyAsInAPlainOne) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    const SceneError plain = load_error(write_bytes("bad_index.ply", ply));
    const SceneError gz = load_error(write_bytes("bad_index.ply.gz", gzip(ply)));
    EXPECT_EQ(gz.where().line, plain.where().line);
    EXPECT_EQ(gz.where().line, 13);
    EXPECT_EQ(gz.message(), plain.message());
    EXPECT_TRUE(contains(gz.message(), "element \"face\", record 1 of 1: vertex index 7 is out of range"));
}

TEST(GzipPly, ChecksTheSizeOnceFromTheHeaderBeforeInflatingTheData) {
    // A header that promises a mesh, then data that is corrupt: a refusing check is called (once,
    // with the header's counts) before the corrupt data is reached.
    std::string gz = gzip(grid_ply(40));
    gz.resize(gz.size() / 2);  // the stream cannot end well
    int calls = 0;
    MeshSize seen;
    const SceneError refused = load_error(write_bytes("refused.ply.gz", gz), [&](const MeshSize& size) {
        ++calls;
        seen = size;
        throw SceneError({}, "too large");
    });
    EXPECT_EQ(refused.message(), "too large");
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(seen.vertices, 41u * 41u);
    EXPECT_EQ(seen.triangles, 40u * 40u);
    EXPECT_TRUE(contains(load_error(write_bytes("truncated_grid.ply.gz", gz)).message(), "file truncated?"));
    // An accepting check is called once too.
    calls = 0;
    const TriangleMesh grid =
        load_mesh(write_bytes("accepted.ply.gz", gzip(grid_ply(40))), [&](const MeshSize&) { ++calls; });
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(grid.triangle_count(), 2u * 40u * 40u);
}

TEST(GzipStream, InflatesInPiecesOfAtMostTheAskedSize) {
    std::string data;
    for (int i = 0; i < 100000; ++i) data += std::to_string(i) + " ";
    const std::string gz = gzip(data);
    GzipStream stream(gz, "numbers.gz");
    std::string out;
    ASSERT_TRUE(stream.inflate_some(out, 1000));
    EXPECT_EQ(out.size(), 1000u);
    EXPECT_EQ(out, data.substr(0, 1000));
    stream.inflate_rest(out);
    EXPECT_EQ(out, data);
    EXPECT_FALSE(stream.inflate_some(out, 1000));
    EXPECT_EQ(out, data);
}

TEST(GzipStream, RefusesDataWithoutAGzipHeader) {
    EXPECT_FALSE(is_gzip("ply\n"));
    EXPECT_TRUE(is_gzip(gzip("x")));
    EXPECT_THROW(GzipStream("ply\n", "x.gz"), SceneError);
}

}  // namespace
}  // namespace candela
