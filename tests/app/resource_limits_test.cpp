// Scenes too large for the memory they may use fail at once, with what they would need and what
// there is (scene/memory_budget.h), through load_scene with an injected limit and through the CLI
// with --memory-limit. Large meshes are sparse files: their headers claim billions of faces, their
// size backs the claim, and no disk space or memory is spent.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/json/scene_loader.h"
#include "support/run_command.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

constexpr uint64_t kGiB = uint64_t(1) << 30;

const MemoryLimit kEightGiB{8 * kGiB, "the test's limit is"};

fs::path temp_dir(const std::string& name) { return test::fresh_dir("resources_" + name); }

fs::path write_file(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

SceneError load_error(const fs::path& scene, const MemoryLimit& limit) {
    try {
        load_scene(scene, LoadOptions{.memory_limit = limit, .meshes = nullptr, .source_map = {}});
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << scene << " loaded within " << limit.bytes << " bytes";
    return SceneError({}, "");
}

uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return uint64_t(usage.ru_maxrss) * 1024;
}

// A binary PLY whose header declares `faces` triangles over 3 vertices, in a sparse file just large
// enough to hold them (so the check of counts against the file size passes); the data is zeros.
fs::path sparse_ply(const fs::path& file, uint64_t faces) {
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face " + std::to_string(faces) +
                               "\nproperty list uchar int vertex_indices\nend_header\n";
    write_file(file, header);
    fs::resize_file(file, header.size() + 3 * 12 + faces * 13);
    struct stat st {};
    EXPECT_EQ(stat(file.c_str(), &st), 0);
    EXPECT_LT(uint64_t(st.st_blocks) * 512, uint64_t(1) << 20) << "the file system does not keep " << file
                                                                << " sparse";
    return file;
}

std::string mesh_scene(const fs::path& mesh) {
    return "{\n  \"camera\": {\"resolution\": [16, 16]},\n  \"materials\": {\"white\": {\"type\": \"diffuse\"}},\n"
           "  \"shapes\": [{\"type\": \"mesh\", \"file\": \"" + mesh.string() + "\", \"material\": \"white\"}]\n}\n";
}

struct CliResult {
    int exit_code;
    std::string err;  // stderr alone
};

CliResult run_candela(const std::string& args) {
    const candela::test::CommandResult r = candela::test::run_command(std::string(CANDELA_CLI) + " " + args + " 2>&1 >/dev/null");
    return {r.exit_code, r.output};
}

// One error line, exit code 2, and `fragment` in it.
void expect_one_line_error(const CliResult& r, const std::string& fragment) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.err.starts_with("candela: error: ")) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
}

TEST(ResourceLimits, FilmBeyondTheLimitIsRefusedAtTheResolutionKey) {
    const fs::path scene =
        write_file(temp_dir("film") / "scene.json", "{\n  \"camera\": {\"resolution\": [32768, 32768]}\n}\n");
    const SceneError e = load_error(scene, kEightGiB);
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().column, 28);
    EXPECT_EQ(e.where().json_pointer, "/camera/resolution");
    EXPECT_EQ(e.message(), "a 32768x32768 film needs about 72.0 GiB of memory, but the test's limit is 8.0 GiB");
}

TEST(ResourceLimits, DefaultResolutionIsCheckedToo) {
    const fs::path scene = write_file(temp_dir("default_film") / "scene.json", "{}\n");
    const SceneError e = load_error(scene, MemoryLimit{1 << 20, "the test's limit is"});
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.message(), "a 512x512 film needs about 18.0 MiB of memory, but the test's limit is 1.0 MiB");
}

TEST(ResourceLimits, ObjMeshIsRefusedAfterItsSurveyBeforeItIsBuilt) {
    const fs::path cube = fs::path(CANDELA_TEST_DATA_DIR) / "meshes" / "cube.obj";
    const fs::path scene = write_file(temp_dir("obj") / "scene.json", mesh_scene(cube));
    const SceneError e = load_error(scene, MemoryLimit{20 << 10, "the test's limit is"});
    EXPECT_EQ(e.where().file, cube.string());
    EXPECT_NE(e.message().find("mesh file \"" + cube.string() + "\" (8 vertices, 12 triangles) needs about"),
              std::string::npos)
        << e.message();
    EXPECT_NE(e.message().find("(referenced by /shapes/0/file at "), std::string::npos) << e.message();
}

TEST(ResourceLimits, PlyOfBillionsOfFacesIsRefusedFromItsHeader) {
    const fs::path dir = temp_dir("ply");
    const fs::path ply = sparse_ply(dir / "huge.ply", 2'000'000'000);
    const fs::path scene = write_file(dir / "scene.json", mesh_scene(ply));
    const uint64_t rss_before = peak_rss_bytes();
    const SceneError e = load_error(scene, MemoryLimit{64 * kGiB, "the test's limit is"});
    EXPECT_NE(e.message().find("but the test's limit is 64.0 GiB"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("(3 vertices, at least 2000000000 triangles) needs about 260.8 GiB of memory"),
              std::string::npos)
        << e.message();
    // Refused from the header: the 26 GB of data were never read.
    EXPECT_LT(peak_rss_bytes() - rss_before, uint64_t(64) << 20);
    fs::remove(ply);
}

TEST(ResourceLimits, PlyOfTenBillionFacesExceedsWhatAMeshCanIndex) {
    const fs::path dir = temp_dir("ply_index");
    const fs::path ply = sparse_ply(dir / "huge.ply", 10'000'000'000);
    const fs::path scene = write_file(dir / "scene.json", mesh_scene(ply));
    const SceneError e = load_error(scene, MemoryLimit::of_this_process());
    EXPECT_EQ(e.where().file, ply.string());
    EXPECT_EQ(e.where().line, 7);
    EXPECT_NE(e.message().find("10000000000 faces are more than the 2^32 - 1 triangles a mesh can index"),
              std::string::npos)
        << e.message();
    fs::remove(ply);
}

TEST(ResourceLimits, EnvironmentMapIsCharged) {
    const fs::path sky = fs::path(CANDELA_TEST_DATA_DIR) / "scenes" / "sky_2x1.hdr";
    const fs::path scene = write_file(temp_dir("environment") / "scene.json",
                                      "{\n  \"camera\": {\"resolution\": [1, 1]},\n  \"lights\": [{\"type\": "
                                      "\"environment\", \"file\": \"" + sky.string() + "\"}]\n}\n");
    const SceneError e = load_error(scene, MemoryLimit{100, "the test's limit is"});
    EXPECT_EQ(e.where().json_pointer, "/lights/0/file");
    EXPECT_NE(e.message().find("(2x1) needs about 72 B of memory (144 B with what the scene holds already)"),
              std::string::npos)
        << e.message();
}

TEST(ResourceLimits, CliCapsEachSideOfTheResolution) {
    const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";
    expect_one_line_error(run_candela("render " + cornell + " --resolution 100000x100000 -o x.png"),
                          "--resolution: each side must be in 1..32768, got 100000x100000");
}

TEST(ResourceLimits, CliRefusesAResolutionFlagBeyondTheMemoryLimit) {
    const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";
    const fs::path out = temp_dir("cli_resolution") / "x.png";
    const CliResult r = run_candela("render " + cornell + " --resolution 32768x32768 --memory-limit 8G -o " +
                                    out.string());
    expect_one_line_error(r, "--resolution 32768x32768: the scene at 32768x32768 pixels (");
    EXPECT_NE(r.err.find("needs about 72.0 GiB of memory, but --memory-limit is 8.0 GiB"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

// --target-error's statistics (64 bytes a pixel) are charged: 16384^2 pixels need 18 GiB without
// them, 34 GiB with them.
TEST(ResourceLimits, CliChargesTheStatisticsOfATargetError) {
    const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";
    const fs::path out = temp_dir("cli_target_error") / "x.png";
    const CliResult r = run_candela("render " + cornell + " --resolution 16384x16384 --target-error 0.01 " +
                                    "--memory-limit 24G -o " + out.string());
    expect_one_line_error(r, "--resolution 16384x16384: the scene at 16384x16384 pixels (");
    EXPECT_NE(r.err.find("needs about 54.0 GiB of memory, but --memory-limit is 24.0 GiB"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(ResourceLimits, CliRefusesASceneResolutionBeyondTheMemoryLimit) {
    const fs::path dir = temp_dir("cli_scene");
    const fs::path scene = write_file(dir / "scene.json", "{\n  \"camera\": {\"resolution\": [32768, 32768]}\n}\n");
    expect_one_line_error(run_candela("render " + scene.string() + " --memory-limit 8G -o " + (dir / "x.png").string()),
                          scene.string() + ":2:28: /camera/resolution: a 32768x32768 film needs about 72.0 GiB");
}

TEST(ResourceLimits, CliRefusesAHugePlyWithoutReadingIt) {
    const fs::path dir = temp_dir("cli_ply");
    const fs::path ply = sparse_ply(dir / "huge.ply", 2'000'000'000);
    const fs::path scene = write_file(dir / "scene.json", mesh_scene(ply));
    const CliResult r =
        run_candela("render " + scene.string() + " --memory-limit 64G -o " + (dir / "x.png").string());
    expect_one_line_error(r, "at least 2000000000 triangles) needs about 260.8 GiB of memory");
    EXPECT_NE(r.err.find("but --memory-limit is 64.0 GiB"), std::string::npos) << r.err;
    fs::remove(ply);
}

TEST(ResourceLimits, CliRejectsAMalformedMemoryLimit) {
    const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";
    expect_one_line_error(run_candela("render " + cornell + " --memory-limit 8X -o x.png"),
                          "--memory-limit: expected a size such as 512M or 8G, got \"8X\"");
}

}  // namespace
}  // namespace candela
