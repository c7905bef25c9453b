// The OpenVDB reader against .vdb files the test writes with libopenvdb: values, map, bounding
// box and world bounds; the same result as our NanoVDB reader for the same grid (tiles.nvdb was
// converted by NanoVDB from the grid tiles_grid() makes); and its errors, each naming the file.
#include <gtest/gtest.h>

#include <openvdb/io/File.h>
#include <openvdb/math/Transform.h>
#include <openvdb/openvdb.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/json/scene_loader.h"
#include "candela/formats/vdb/nanovdb_reader.h"
#include "candela/formats/vdb/openvdb_reader.h"
#include "candela/scene/memory_budget.h"
#include "formats/vdb/nvdb_fixtures.h"
#include "support/scene_error_of.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::error_of;

MemoryBudget plenty() { return MemoryBudget(MemoryLimit{uint64_t(1) << 32, "the test's limit is"}); }

VolumeGrid read(const std::filesystem::path& file, const std::string& name = "density") {
    MemoryBudget budget = plenty();
    return read_openvdb_grid(file, name, budget);
}

std::filesystem::path write_vdb(const std::string& name, openvdb::GridPtrVec grids) {
    openvdb::initialize();
    // A folder per test: ctest runs the tests of one binary in parallel processes.
    const std::filesystem::path dir = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "openvdb_reader_test" /
                                      ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / name;
    openvdb::io::File out(file.string());
    out.write(grids);
    out.close();
    return file;
}

// density_8x6x5.nvdb's grid: 1 + (i+3) + 8 (j-2) + 48 (k+1) over [-3,4] x [2,7] x [-1,3] but for
// (0,4,1), under a map of voxel size 0.5 translated by (1, -2, 3).
openvdb::FloatGrid::Ptr density_grid() {
    auto g = openvdb::FloatGrid::create(0.0f);
    g->setName("density");
    auto transform = openvdb::math::Transform::createLinearTransform(0.5);
    transform->postTranslate(openvdb::Vec3d(1, -2, 3));
    g->setTransform(transform);
    auto acc = g->getAccessor();
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i)
                if (!(i == 0 && j == 4 && k == 1))
                    acc.setValue(openvdb::Coord(i, j, k), float(1 + (i + 3) + 8 * (j - 2) + 48 * (k + 1)));
    return g;
}

// The grid of tiles.nvdb (tests/data/vdb/README.md).
openvdb::FloatGrid::Ptr tiles_grid() {
    auto g = openvdb::FloatGrid::create(0.0f);
    g->setName("density");
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preScale(openvdb::Vec3d(0.25));
    m.postRotate(openvdb::math::Z_AXIS, M_PI / 2);
    m.postTranslate(openvdb::Vec3d(0.1, 0.2, 0.3));
    g->setTransform(openvdb::math::Transform::createLinearTransform(m));
    g->fill(openvdb::CoordBBox(openvdb::Coord(-8, -8, -8), openvdb::Coord(23, 15, 7)), 0.75f, true);
    g->tree().setValue(openvdb::Coord(30, 1, 2), 2.0f);
    return g;
}

TEST(OpenVdbReader, ReadsValuesBoundingBoxAndMap) {
    openvdb::initialize();
    const VolumeGrid g = read(write_vdb("density.vdb", {density_grid()}));
    EXPECT_EQ(g.name, "density");
    EXPECT_EQ(g.index_min, Vec3<int>(-3, 2, -1));
    EXPECT_EQ(g.nx, 8);
    EXPECT_EQ(g.ny, 6);
    EXPECT_EQ(g.nz, 5);
    for (int k = -1; k < 4; ++k)
        for (int j = 2; j < 8; ++j)
            for (int i = -3; i < 5; ++i)
                ASSERT_EQ(g.value_at(i, j, k),
                          i == 0 && j == 4 && k == 1 ? 0.0f : float(1 + (i + 3) + 8 * (j - 2) + 48 * (k + 1)));
    EXPECT_EQ(g.values[1], 2.0f);  // x fastest
    const double expected[3][4] = {{0.5, 0, 0, 1}, {0, 0.5, 0, -2}, {0, 0, 0.5, 3}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(g.index_to_world[r][c], expected[r][c]) << r << " " << c;
    EXPECT_EQ(g.world_min, Vec3d(-0.5, -1, 2.5));
    EXPECT_EQ(g.world_max, Vec3d(3.5, 2, 5));
}

TEST(OpenVdbReader, MatchesTheNanoVdbReaderOnTheSameGrid) {
    openvdb::initialize();
    const VolumeGrid a = read(write_vdb("tiles.vdb", {tiles_grid()}));
    MemoryBudget budget = plenty();
    const VolumeGrid b = read_nanovdb_grid(test::nvdb_fixture("tiles.nvdb"), "density", budget);
    EXPECT_EQ(a.index_min, b.index_min);
    EXPECT_EQ(a.nx, b.nx);
    EXPECT_EQ(a.ny, b.ny);
    EXPECT_EQ(a.nz, b.nz);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.background, b.background);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.index_to_world[r][c], b.index_to_world[r][c], 1e-15);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(a.world_min[i], b.world_min[i], 1e-12);
        EXPECT_NEAR(a.world_max[i], b.world_max[i], 1e-12);
    }
}

TEST(OpenVdbReader, ReadsBothGridsOfATwoGridFile) {
    openvdb::initialize();
    auto t = openvdb::FloatGrid::create(1.5f);
    t->setName("temperature");
    for (int k = 5; k < 8; ++k) t->tree().setValue(openvdb::Coord(5, 5, k), 1000.0f + float(k));
    const std::filesystem::path file = write_vdb("two.vdb", {density_grid(), t});
    EXPECT_EQ(openvdb_grid_names(file), (std::vector<std::string>{"density", "temperature"}));
    EXPECT_EQ(read(file, "density").voxel_count(), 240u);
    const VolumeGrid g = read(file, "temperature");
    EXPECT_EQ(g.background, 1.5f);
    EXPECT_EQ(g.index_min, Vec3<int>(5, 5, 5));
    EXPECT_EQ(g.nz, 3);
    EXPECT_EQ(g.value_at(5, 5, 6), 1006.0f);
    const std::string e = error_of([&] { read(file, "heat"); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("no grid named \"heat\"; the OpenVDB file has: \"density\", \"temperature\""), std::string::npos)
        << e;
}

TEST(OpenVdbReader, RefusesAMissingFile) {
    const std::string e = error_of([] { read("no/such/file.vdb"); });
    EXPECT_NE(e.find("no/such/file.vdb"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot open"), std::string::npos) << e;
}

TEST(OpenVdbReader, RefusesATruncatedFile) {
    const std::filesystem::path whole = write_vdb("whole.vdb", {density_grid()});
    const std::string bytes = test::read_bytes(whole);
    // Everywhere: libopenvdb 10 takes a size from a read that failed as if it had read it (a file
    // cut inside its metadata took 60 to 90 s and 14 GB to refuse), so the reader checks that the
    // metadata and the grids' extents fit in the file first (docs/RELIABILITY.md).
    for (size_t length : {size_t(0), size_t(4), size_t(40), size_t(100), size_t(200), size_t(400), size_t(600),
                          size_t(1000), bytes.size() / 2, bytes.size() - 1}) {
        const std::filesystem::path file = whole.parent_path() / "truncated.vdb";
        std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, length);
        const std::string e = error_of([&] { read(file); });
        EXPECT_NE(e.find(file.string()), std::string::npos) << length << ": " << e;
    }
}

TEST(OpenVdbReader, RefusesAGridOfAnotherType) {
    openvdb::initialize();
    auto g = openvdb::DoubleGrid::create(0.0);
    g->setName("density");
    g->tree().setValue(openvdb::Coord(1, 2, 3), 4.0);
    const std::filesystem::path file = write_vdb("double.vdb", {g});
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("grid \"density\" holds double values; candela reads float grids only"), std::string::npos) << e;
}

TEST(OpenVdbReader, RefusesAFrustumTransform) {
    openvdb::initialize();
    auto g = density_grid();
    g->setTransform(openvdb::math::Transform::createFrustumTransform(
        openvdb::BBoxd(openvdb::Vec3d(0), openvdb::Vec3d(10)), 0.5, 2.0, 0.1));
    const std::filesystem::path file = write_vdb("frustum.vdb", {g});
    const std::string e = error_of([&] { read(file); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("non-linear transform"), std::string::npos) << e;
}

TEST(OpenVdbReader, RefusesAGridTooLargeForTheBudgetBeforeAllocatingIt) {
    const std::filesystem::path file = write_vdb("budget.vdb", {density_grid()});
    MemoryBudget tiny(MemoryLimit{500, "the test's limit is"});
    const std::string e = error_of([&] { read_openvdb_grid(file, "density", tiny); });
    EXPECT_NE(e.find(file.string()), std::string::npos) << e;
    EXPECT_NE(e.find("volume grid \"density\""), std::string::npos) << e;
    EXPECT_NE(e.find("needs about"), std::string::npos) << e;
    EXPECT_EQ(tiny.used(), 0u);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace CANDELA_UNITY_ID {

// The grid at world point p of the medium "m" of `scene_json`: its density times sigma_s (1).
float density_at(const std::string& medium_json, const Vec3f& p) {
    const Scene s = load_scene_from_string(R"({"media": {"m": )" + medium_json + "}}",
                                           std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
    return visit([&](const auto& m) { return m.at(p, MediumChannels{}).sigma_s[0]; }, s.media.at(0));
}

// The `nanovdb` and `openvdb` media of a scene file hold the file's voxel values at their world
// positions (NanoVDB's and OpenVDB's trilinear samplers put voxel (i, j, k) at index point
// (i, j, k)), under the file's map and then the medium's transform; the same grid from either
// file gives the same medium.
TEST(VdbMedia, HoldTheFilesVoxelsAtTheirWorldPositions) {
    const std::string nvdb = test::nvdb_fixture("density_8x6x5_v32_3.nvdb").string();
    const std::string vdb = write_vdb("density.vdb", {density_grid()}).string();
    for (const auto& [type, file] : {std::pair{"nanovdb", nvdb}, std::pair{"openvdb", vdb}}) {
        SCOPED_TRACE(type);
        const std::string medium = fmt::format(R"({{"type": "{}", "file": "{}", "sigma_a": 0, "sigma_s": 1)", type, file);
        // Voxel (2, 3, 0): 1 + 5 + 8 + 48 = 62, at 0.5 (2, 3, 0) + (1, -2, 3).
        EXPECT_NEAR(density_at(medium + "}", Vec3f(2.0f, -0.5f, 3.0f)), 62.0f, 1e-4f);
        // Halfway to voxel (3, 3, 0), 63: the average.
        EXPECT_NEAR(density_at(medium + "}", Vec3f(2.25f, -0.5f, 3.0f)), 62.5f, 1e-4f);
        // Moved by the medium's transform.
        EXPECT_NEAR(density_at(medium + R"(, "transform": [{"translate": [10, 0, 0]}]})", Vec3f(12.0f, -0.5f, 3.0f)), 62.0f,
                    1e-4f);
        // Outside the grid: nothing.
        EXPECT_EQ(density_at(medium + "}", Vec3f(50.0f, 0.0f, 0.0f)), 0.0f);
    }
}

TEST(VdbMedia, BadFilesAndGridNamesAreLocatedAtTheFileKey) {
    const std::string scene = R"({"media": {"m": {"type": "nanovdb", "file": )";
    auto load = [](const std::string& json) {
        load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
    };
    EXPECT_NE(error_of([&] { load(scene + R"("missing.nvdb"}}})"); }).find("/media/m/file: NanoVDB file \"missing.nvdb\" not found"),
              std::string::npos);
    const std::string file = test::nvdb_fixture("density_8x6x5_v32_3.nvdb").string();
    const std::string wrong = error_of([&] { load(scene + "\"" + file + R"(", "grid_name": "smoke"}}})"); });
    EXPECT_NE(wrong.find("smoke"), std::string::npos) << wrong;
    EXPECT_NE(wrong.find("referenced by /media/m/file"), std::string::npos) << wrong;
}

TEST(VdbMedia, MemoryEstimateCountsTheMajorantGridOfAVdbMedium) {
    // A NanoVDB medium's majorant grid has 16^3 cells for this fixture's 8 x 6 x 5 voxels
    // (vdb_majorant_resolution: half the largest voxel count, at least 16); the estimate charges two
    // such grids, 32 KiB of floats: far more than the fixture's 240 voxels.
    const std::string file = test::nvdb_fixture("density_8x6x5_v32_3.nvdb").string();
    const Scene s = load_scene_from_string(
        fmt::format(R"({{"camera": {{"resolution": [1, 1]}}, "media": {{"m": {{"type": "nanovdb", "file": "{}"}}}}}})",
                    file),
        std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_GE(scene_memory_bytes(s), film_memory_bytes(1, 1) + 2 * 16 * 16 * 16 * sizeof(float));
}

}  // namespace
}  // namespace candela
