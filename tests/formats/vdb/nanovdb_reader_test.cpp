// Our NanoVDB reader against files NanoVDB itself wrote (tests/data/vdb/README.md): values at
// known voxels, the index-to-world map, the active bounding box and world bounds, several grids
// in one file, raw grid buffers; and every way a file can be refused, each a SceneError naming it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/vdb/nanovdb_reader.h"
#include "candela/scene/memory_budget.h"
#include "formats/vdb/nvdb_fixtures.h"
#include "support/scene_error_of.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::error_of;
using test::nvdb_fixture;

MemoryBudget plenty() { return MemoryBudget(MemoryLimit{uint64_t(1) << 32, "the test's limit is"}); }

VolumeGrid read(const std::filesystem::path& file, const std::string& name = "density") {
    MemoryBudget budget = plenty();
    return read_nanovdb_grid(file, name, budget);
}

// The pattern of density_8x6x5.nvdb: 1 + (i+3) + 8 (j-2) + 48 (k+1) over [-3,4] x [2,7] x [-1,3],
// but for voxel (0,4,1), left inactive.
float pattern(int i, int j, int k) {
    if (i == 0 && j == 4 && k == 1) return 0.0f;
    return float(1 + (i + 3) + 8 * (j - 2) + 48 * (k + 1));
}

void expect_density_8x6x5(const VolumeGrid& g) {
    EXPECT_EQ(g.name, "density");
    EXPECT_EQ(g.index_min, Vec3<int>(-3, 2, -1));
    EXPECT_EQ(g.nx, 8);
    EXPECT_EQ(g.ny, 6);
    EXPECT_EQ(g.nz, 5);
    ASSERT_EQ(g.values.size(), 240u);
    EXPECT_EQ(g.background, 0.0f);
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i) ASSERT_EQ(g.value_at(i, j, k), pattern(i, j, k)) << i << " " << j << " " << k;
    // x fastest: values[(z*ny + y)*nx + x] is voxel index_min + (x,y,z).
    EXPECT_EQ(g.values[0], pattern(-3, 2, -1));
    EXPECT_EQ(g.values[1], pattern(-2, 2, -1));
    EXPECT_EQ(g.values[8], pattern(-3, 3, -1));
    EXPECT_EQ(g.values[48], pattern(-3, 2, 0));
    EXPECT_EQ(g.value_at(-4, 2, -1), 0.0f);  // outside the block: the background
    EXPECT_EQ(g.value_at(5, 7, 3), 0.0f);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(g.index_to_world[r][c], r == c ? 1.0 : 0.0);
    EXPECT_EQ(g.world_min, Vec3d(-3, 2, -1));  // the cells' box: [min, max + 1]
    EXPECT_EQ(g.world_max, Vec3d(5, 8, 4));
}

TEST(NanoVdbReader, ReadsValuesBoundingBoxAndMapOfADensityGrid) {
    expect_density_8x6x5(read(nvdb_fixture("density_8x6x5.nvdb")));
}

// pbrt-v4 pins NanoVDB 32.3, whose files start with "NanoVDB0"; the layout is the same.
TEST(NanoVdbReader, ReadsAFileOfNanoVdb32_3AsPbrtV4WritesThem) {
    const VolumeGrid g = read(nvdb_fixture("density_8x6x5_v32_3.nvdb"));
    EXPECT_EQ(g.index_min, Vec3<int>(-3, 2, -1));
    EXPECT_EQ(g.voxel_count(), 240u);
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i) ASSERT_EQ(g.value_at(i, j, k), pattern(i, j, k)) << i << " " << j << " " << k;
    EXPECT_EQ(g.index_to_world_point({0, 0, 0}), Vec3d(1, -2, 3));
    EXPECT_EQ(g.index_to_world_point({2, 2, 2}), Vec3d(2, -1, 4));
    EXPECT_EQ(g.world_min, Vec3d(-0.5, -1, 2.5));
    EXPECT_EQ(g.world_max, Vec3d(3.5, 2, 5));
}

TEST(NanoVdbReader, ReadsARawGridBufferAsASegmentFile) {
    expect_density_8x6x5(read(nvdb_fixture("density_8x6x5_raw.nvdb")));
}

TEST(NanoVdbReader, ReadsAScaledAndTranslatedMap) {
    const VolumeGrid g = read(nvdb_fixture("scaled_translated.nvdb"));
    EXPECT_EQ(g.index_min, Vec3<int>(0, 0, 0));
    EXPECT_EQ(g.nx, 3);
    EXPECT_EQ(g.ny, 2);
    EXPECT_EQ(g.nz, 2);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i)
                EXPECT_EQ(g.value_at(i, j, k), 2.0f + float(i) + 10.0f * float(j) + 100.0f * float(k));
    const double expected[3][4] = {{0.5, 0, 0, 1}, {0, 0.5, 0, -2}, {0, 0, 0.5, 3}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(g.index_to_world[r][c], expected[r][c]) << r << " " << c;
    EXPECT_EQ(g.index_to_world_point({2, 1, 1}), Vec3d(2, -1.5, 3.5));
    EXPECT_EQ(g.world_min, Vec3d(1, -2, 3));
    EXPECT_EQ(g.world_max, Vec3d(2.5, -1, 4));
}

// OpenVDB's tree converted by NanoVDB: active tiles in lower nodes (the filled box) and a leaf,
// under a rotated, scaled and translated map.
TEST(NanoVdbReader, ReadsTileValuesAndARotatedMap) {
    const VolumeGrid g = read(nvdb_fixture("tiles.nvdb"));
    EXPECT_EQ(g.index_min, Vec3<int>(-8, -8, -8));
    EXPECT_EQ(g.nx, 39);
    EXPECT_EQ(g.ny, 24);
    EXPECT_EQ(g.nz, 16);
    EXPECT_EQ(g.value_at(-8, -8, -8), 0.75f);
    EXPECT_EQ(g.value_at(23, 15, 7), 0.75f);
    EXPECT_EQ(g.value_at(0, 0, 0), 0.75f);
    EXPECT_EQ(g.value_at(24, 0, 0), 0.0f);
    EXPECT_EQ(g.value_at(30, 1, 2), 2.0f);
    EXPECT_EQ(g.value_at(30, 1, 3), 0.0f);
    // world = (-0.25 j + 0.1, 0.25 i + 0.2, 0.25 k + 0.3): a quarter turn about z, scale 1/4.
    const Vec3d p = g.index_to_world_point({1, 2, 3});
    EXPECT_NEAR(p.x, -0.4, 1e-12);
    EXPECT_NEAR(p.y, 0.45, 1e-12);
    EXPECT_NEAR(p.z, 1.05, 1e-12);
    EXPECT_NEAR(g.world_min.x, -0.25 * 16 + 0.1, 1e-12);
    EXPECT_NEAR(g.world_max.x, 0.25 * 8 + 0.1, 1e-12);
    EXPECT_NEAR(g.world_min.y, -0.25 * 8 + 0.2, 1e-12);
    EXPECT_NEAR(g.world_max.y, 0.25 * 31 + 0.2, 1e-12);
    EXPECT_NEAR(g.world_min.z, -0.25 * 8 + 0.3, 1e-12);
    EXPECT_NEAR(g.world_max.z, 0.25 * 8 + 0.3, 1e-12);
}

void expect_two_grids(const std::filesystem::path& file) {
    EXPECT_EQ(nanovdb_grid_names(file), (std::vector<std::string>{"density", "temperature"}));
    const VolumeGrid d = read(file, "density");
    EXPECT_EQ(d.index_min, Vec3<int>(0, 0, 0));
    EXPECT_EQ(d.voxel_count(), 8u);
    for (float v : d.values) EXPECT_EQ(v, 0.5f);
    const VolumeGrid t = read(file, "temperature");
    EXPECT_EQ(t.name, "temperature");
    EXPECT_EQ(t.background, 1.5f);
    EXPECT_EQ(t.index_min, Vec3<int>(5, 5, 5));
    EXPECT_EQ(t.nx, 1);
    EXPECT_EQ(t.ny, 1);
    EXPECT_EQ(t.nz, 3);
    EXPECT_EQ(t.value_at(5, 5, 7), 1007.0f);
    EXPECT_EQ(t.value_at(5, 5, 8), 1.5f);
}

TEST(NanoVdbReader, ReadsBothGridsOfATwoSegmentFile) { expect_two_grids(nvdb_fixture("two_grids.nvdb")); }

TEST(NanoVdbReader, ReadsBothGridsOfOneSegmentWithTwoGrids) {
    expect_two_grids(nvdb_fixture("two_grids_one_segment.nvdb"));
}

TEST(NanoVdbReader, RefusesAMissingFile) {
    const std::string e = error_of([] { read("no/such/file.nvdb"); });
    EXPECT_NE(e.find("no/such/file.nvdb"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot open"), std::string::npos) << e;
}

TEST(NanoVdbReader, RefusesAMissingGridNameListingTheNamesPresent) {
    const std::filesystem::path file = nvdb_fixture("two_grids.nvdb");
    const std::string e = error_of([&] { read(file, "densty"); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("no grid named \"densty\"; the NanoVDB file has: \"density\", \"temperature\""), std::string::npos)
        << e;
}

TEST(NanoVdbReader, RefusesACompressedGrid) {
    const std::filesystem::path file = nvdb_fixture("density_8x6x5_zip.nvdb");
    EXPECT_EQ(nanovdb_grid_names(file), std::vector<std::string>{"density"});
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("grid \"density\" is compressed (zip)"), std::string::npos) << e;
}

TEST(NanoVdbReader, RefusesAGridOfAnotherType) {
    const std::filesystem::path file = nvdb_fixture("double.nvdb");
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("grid \"density\" holds double values; candela reads float grids only"), std::string::npos) << e;
}

TEST(NanoVdbReader, RefusesAGridTooLargeForTheBudgetBeforeAllocatingIt) {
    const std::filesystem::path file = nvdb_fixture("density_8x6x5.nvdb");
    // Enough for the grid's buffer but not for it and the dense block (240 floats).
    const uint64_t file_bytes = std::filesystem::file_size(file);
    MemoryBudget budget(MemoryLimit{file_bytes, "the test's limit is"});
    const std::string e = error_of([&] { read_nanovdb_grid(file, "density", budget); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("volume grid \"density\" (8x6x5 voxels) needs about"), std::string::npos) << e;
    EXPECT_EQ(budget.used(), 0u);
    // A budget too small for even the buffer refuses before reading it.
    MemoryBudget tiny(MemoryLimit{1000, "the test's limit is"});
    const std::string e2 = error_of([&] { read_nanovdb_grid(file, "density", tiny); });
    EXPECT_NE(e2.find("reading NanoVDB grid \"density\" needs about"), std::string::npos) << e2;
    EXPECT_EQ(tiny.used(), 0u);
    // And a budget that fits is charged the block.
    MemoryBudget fits(MemoryLimit{2 * file_bytes, "the test's limit is"});
    read_nanovdb_grid(file, "density", fits);
    EXPECT_EQ(fits.used(), 240u * sizeof(float));
}

// A file of the test's own (each test its own name: ctest runs them in parallel).
std::filesystem::path with_bytes(const std::string& name, const std::string& bytes) {
    const std::filesystem::path file = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "vdb_fixtures" / name;
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    return file;
}

TEST(NanoVdbReader, RefusesATruncatedFileAtEveryPart) {
    const std::string bytes = test::read_bytes(nvdb_fixture("density_8x6x5.nvdb"));
    // Within the magic, the header, the metadata, the name, GridData, the root, the nodes, the end.
    for (size_t length : {size_t(0), size_t(5), size_t(16), size_t(100), size_t(195), size_t(199), size_t(600),
                          size_t(1000), bytes.size() / 2, bytes.size() - 1}) {
        const std::filesystem::path file = with_bytes("truncated.nvdb", bytes.substr(0, length));
        const std::string e = error_of([&] { read(file); });
        EXPECT_NE(e.find(file.string()), std::string::npos) << length << ": " << e;
        EXPECT_TRUE(e.find("truncated") != std::string::npos || e.find("empty file") != std::string::npos)
            << length << ": " << e;
    }
}

// Byte offsets in density_8x6x5.nvdb: a 16-byte header, 176 bytes of metadata, "density\0", then
// the grid: GridData (672 B), TreeData (its node offsets from byte 672 of the grid).
constexpr size_t kGrid = 16 + 176 + 8;

std::string patched(std::string bytes, size_t at, const void* value, size_t size) {
    std::memcpy(bytes.data() + at, value, size);
    return bytes;
}

TEST(NanoVdbReader, RefusesCorruptOffsetsAndSizes) {
    const std::string bytes = test::read_bytes(nvdb_fixture("density_8x6x5.nvdb"));
    int64_t root_offset;
    std::memcpy(&root_offset, bytes.data() + kGrid + 672 + 24, 8);
    const size_t root = kGrid + 672 + size_t(root_offset);
    struct Case {
        const char* what;
        size_t at;
        uint64_t value;
        size_t size;
        const char* expected;
    };
    const Case cases[] = {
        {"root tile child", root + 64 + 8, 12345, 8, "a child offset of the node at byte"},
        {"root table size", root + 24, 1u << 30, 4, "root table of 1073741824 tiles does not fit"},
        {"leaf count", kGrid + 672 + 32, 1u << 31, 4, "leaf nodes at byte"},
        {"root offset", kGrid + 672 + 24, uint64_t(1) << 40, 8, "the offset 1099511627776 of its root nodes"},
        {"file size", 24, uint64_t(1) << 50, 8, "truncated NanoVDB file: grid \"density\" needs"},
        {"name size", 16 + 136, 1u << 31, 4, "the name of grid 0"},
        {"version", 8, 31u << 21, 4, "NanoVDB version 31.0.0"},
        {"magic", 0, 0x1234, 8, "not a NanoVDB file"},
        {"grid magic", kGrid, 0x1234, 8, "does not start with NanoVDB's grid magic number"},
    };
    for (const Case& c : cases) {
        const std::filesystem::path file = with_bytes("corrupt.nvdb", patched(bytes, c.at, &c.value, c.size));
        const std::string e = error_of([&] { read(file); });
        EXPECT_NE(e.find(file.string()), std::string::npos) << c.what << ": " << e;
        EXPECT_NE(e.find(c.expected), std::string::npos) << c.what << ": " << e;
    }
}

TEST(NanoVdbReader, RefusesTwoSlotsSharingAChild) {
    std::string bytes = test::read_bytes(nvdb_fixture("two_grids.nvdb"));
    // The density grid (2x2x2 at the origin) has one upper node, whose slot 0 holds the lower
    // node; pointing slot 1 at it too (child bit and offset) must be refused, not read twice.
    int64_t upper_offset;
    std::memcpy(&upper_offset, bytes.data() + kGrid + 672 + 16, 8);
    const size_t upper = kGrid + 672 + size_t(upper_offset);
    const size_t child_mask = upper + 32 + 4096, table = upper + 8256;
    uint64_t word;
    std::memcpy(&word, bytes.data() + child_mask, 8);
    ASSERT_EQ(word, 1u);
    word = 3;
    std::memcpy(bytes.data() + child_mask, &word, 8);
    std::memcpy(bytes.data() + table + 8, bytes.data() + table, 8);
    const std::filesystem::path file = with_bytes("shared_child.nvdb", bytes);
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find("is the child of two slots"), std::string::npos) << e;
}

TEST(NanoVdbReader, RefusesANonFiniteValue) {
    std::string bytes = test::read_bytes(nvdb_fixture("scaled_translated.nvdb"));
    int64_t leaf_offset;
    std::memcpy(&leaf_offset, bytes.data() + kGrid + 672, 8);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // Voxel (1, 0, 0) is slot 64 of the one leaf.
    const std::filesystem::path file =
        with_bytes("nan.nvdb", patched(bytes, kGrid + 672 + size_t(leaf_offset) + 96 + 4 * 64, &nan, 4));
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find("voxel (1, 0, 0) is not a finite number"), std::string::npos) << e;
}

TEST(NanoVdbReader, ReadsAGridWithoutActiveVoxelsAsAnEmptyBlock) {
    const std::string bytes = test::read_bytes(nvdb_fixture("scaled_translated.nvdb"));
    int64_t leaf_offset;
    std::memcpy(&leaf_offset, bytes.data() + kGrid + 672, 8);
    const std::string no_mask(64, '\0');  // the one leaf's value mask, all off
    const VolumeGrid g =
        read(with_bytes("no_active.nvdb", patched(bytes, kGrid + 672 + size_t(leaf_offset) + 16, no_mask.data(), 64)));
    EXPECT_EQ(g.nx, 0);
    EXPECT_EQ(g.ny, 0);
    EXPECT_EQ(g.nz, 0);
    EXPECT_TRUE(g.values.empty());
    EXPECT_EQ(g.value_at(0, 0, 0), 0.0f);
    EXPECT_EQ(g.index_to_world[0][0], 0.5);
}

TEST(NanoVdbReader, RefusesAnOpenVdbFileNamedNvdb) {
    // An OpenVDB file starts with the magic number 0x56444220 (" BDV").
    const std::string bytes = std::string("\x20\x42\x44\x56\0\0\0\0", 8) + std::string(64, '\0');
    const std::filesystem::path file = with_bytes("openvdb.nvdb", bytes);
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find("this is an OpenVDB file"), std::string::npos) << e;
}

}  // namespace
}  // namespace candela
