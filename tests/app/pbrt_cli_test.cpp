// The CLI with pbrt-v4 scenes (issue 15): `candela convert` and its refusals, `candela render` of
// a .pbrt file writing the Film's "filename", and a 10^6-deep AttributeBegin (made here, 15 MB,
// rather than committed) refused quickly in bounded memory.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.h"
#include "support/test_files.h"

namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

struct CliResult {
    int exit_code;
    std::string output;  // stdout and stderr together
};

// Runs `candela ARGS` in folder `cwd`.
CliResult run_candela_in(const fs::path& cwd, const std::string& args) {
    const candela::test::CommandResult r =
        candela::test::run_command("cd '" + cwd.string() + "' && " + std::string(CANDELA_CLI) + " " + args + " 2>&1");
    return {r.exit_code, r.output};
}

fs::path temp_dir(const std::string& name) { return candela::test::fresh_dir("pbrt_cli_" + name); }

// A small pbrt-v4 scene: a lit triangle mesh (inline, so convert writes a PLY) and a sphere.
constexpr const char* kTinyScene = R"(LookAt 0 0 -5  0 0 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 8 "integer yresolution" 8 "string filename" "out.pfm"
Sampler "independent" "integer pixelsamples" 1
WorldBegin
LightSource "point" "rgb I" [ 10 10 10 ] "point3 from" [ 0 0 -4 ]
Shape "trianglemesh" "point3 P" [ -1 -1 0  1 -1 0  1 1 0  -1 1 0 ] "integer indices" [ 0 1 2  0 2 3 ]
Shape "sphere" "float radius" 0.5
)";

TEST(PbrtCli, ConvertWritesJsonAndMeshes) {
    const fs::path dir = temp_dir("convert");
    std::ofstream(dir / "tiny.pbrt") << kTinyScene;
    const CliResult r = run_candela_in(dir, "convert tiny.pbrt -o converted/tiny.json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(dir / "converted/tiny.json"));
    int ply_files = 0;
    if (fs::is_directory(dir / "converted/meshes"))
        for (const auto& entry : fs::directory_iterator(dir / "converted/meshes"))
            ply_files += entry.path().extension() == ".ply" && fs::file_size(entry.path()) > 0;
    EXPECT_EQ(ply_files, 1) << r.output;
    // The written scene renders.
    const CliResult render = run_candela_in(dir, "render converted/tiny.json --spp 1 -o back.png");
    EXPECT_EQ(render.exit_code, 0) << render.output;
    EXPECT_TRUE(fs::exists(dir / "back.png"));
}

TEST(PbrtCli, ConvertRefusesOtherInputsAndOutputs) {
    const fs::path dir = temp_dir("convert_refusals");
    std::ofstream(dir / "tiny.pbrt") << kTinyScene;
    std::ofstream(dir / "scene.json") << "{}\n";
    const CliResult not_pbrt = run_candela_in(dir, "convert scene.json -o out.json");
    EXPECT_EQ(not_pbrt.exit_code, 2) << not_pbrt.output;
    EXPECT_NE(not_pbrt.output.find("convert reads pbrt-v4 scenes (.pbrt)"), std::string::npos) << not_pbrt.output;
    EXPECT_EQ(std::count(not_pbrt.output.begin(), not_pbrt.output.end(), '\n'), 1) << not_pbrt.output;
    const CliResult not_json = run_candela_in(dir, "convert tiny.pbrt -o out.xml");
    EXPECT_EQ(not_json.exit_code, 2) << not_json.output;
    EXPECT_NE(not_json.output.find("the converted scene is JSON (.json)"), std::string::npos) << not_json.output;
    EXPECT_EQ(std::count(not_json.output.begin(), not_json.output.end(), '\n'), 1) << not_json.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    EXPECT_FALSE(fs::exists(dir / "out.xml"));
}

TEST(PbrtCli, RenderWithoutOutputWritesTheFilmsFilename) {
    const fs::path dir = temp_dir("film_filename");
    std::ofstream(dir / "tiny.pbrt") << kTinyScene;
    const CliResult r = run_candela_in(dir, "render tiny.pbrt --threads 1");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(dir / "out.pfm")) << r.output;
    EXPECT_GT(fs::file_size(dir / "out.pfm"), 8u * 8u * 3u * 4u);
}

// pbrt_importer.cpp bounds AttributeBegin nesting (each level copies the graphics state): a
// million levels must be refused at level 100001, not eat memory or time.
TEST(PbrtCli, MillionDeepAttributeBeginIsRefusedQuickly) {
    const fs::path dir = temp_dir("deep_attributes");
    const fs::path scene = dir / "deep.pbrt";
    {
        std::ofstream out(scene);
        out << "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 45\nWorldBegin\n";
        for (int i = 0; i < 1000000; ++i) out << "AttributeBegin\n";
        out << "Shape \"sphere\"\n";
    }
    const fs::path err_file = dir / "stderr.txt";
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (err < 0 || null < 0 || dup2(err, 2) < 0 || dup2(null, 1) < 0) _exit(126);
        const std::string image = (dir / "out.png").string();
        execl(CANDELA_CLI, CANDELA_CLI, "render", scene.c_str(), "--threads", "1", "-o", image.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    ASSERT_EQ(wait4(pid, &status, 0, &usage), pid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ifstream in(err_file);
    const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(WIFEXITED(status)) << err;
    EXPECT_EQ(WEXITSTATUS(status), 2) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("AttributeBegin nested deeper than 100000 levels"), std::string::npos) << err;
    // A guard against a hang or a quadratic walk, not a benchmark: 0.3-0.8 s in release here, a
    // few times that under ASan on a loaded machine.
    EXPECT_LT(seconds, 30.0);
    EXPECT_LT(usage.ru_maxrss, 1024L * 1024L) << "peak RSS in KiB";  // under 1 GiB
    fs::remove(scene);
}

}  // namespace
