// The command-line program as a user meets it: exit codes, one-line located errors, outputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "candela/image/image_layers.h"
#include "support/run_command.h"
#include "support/test_files.h"

namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

struct CliResult {
    int exit_code;
    std::string output;  // stdout and stderr together
};

CliResult run_candela(const std::string& args) {
    const candela::test::CommandResult r = candela::test::run_command(std::string(CANDELA_CLI) + " " + args + " 2>&1");
    return {r.exit_code, r.output};
}

fs::path temp_dir(const std::string& name) { return candela::test::fresh_dir("cli_" + name); }

const std::string kScene = std::string(CANDELA_SOURCE_DIR) + "/scenes/cornell-box/scene.json";

TEST(Cli, VersionAndHelpExitZero) {
    CliResult v = run_candela("--version");
    EXPECT_EQ(v.exit_code, 0);
    EXPECT_NE(v.output.find("candela 0."), std::string::npos) << v.output;
    CliResult h = run_candela("render --help");
    EXPECT_EQ(h.exit_code, 0);
    for (const char* flag : {"--spp", "--seed", "--threads", "--resolution", "--integrator", "-o"})
        EXPECT_NE(h.output.find(flag), std::string::npos) << flag;
}

TEST(Cli, BadSceneGivesOneLocatedLineAndExitTwo) {
    fs::path dir = temp_dir("bad_scene");
    fs::path scene = dir / "bad.json";
    std::ofstream(scene) << "{\n  \"sampler\": {\"spp\": 4},\n  \"camera\": {\"fov\": -3}\n}\n";
    CliResult r = run_candela("render " + scene.string() + " -o " + (dir / "x.png").string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.rfind("candela: error: " + scene.string() + ":3:", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("/camera/fov"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(Cli, BadFlagsExitTwo) {
    EXPECT_EQ(run_candela("render " + kScene + " --resolution 12by4").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --integrator magic").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --spp 0").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --tile-size 0").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " -o out.tiff").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --iso 0").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --exposure-time -1").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --iso 1e38 --exposure-time 1e3").exit_code, 2);
    EXPECT_EQ(run_candela("render /no/such/scene.json").exit_code, 2);
    EXPECT_EQ(run_candela("render").exit_code, 2);
}

TEST(Cli, AdaptiveFlagsAreCheckedAsTheSceneKeys) {
    CliResult r = run_candela("render " + kScene + " --noise-threshold 1.5");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("--noise-threshold: expected a number in [0, 1) (0: no adaptive sampling), got 1.5"),
              std::string::npos)
        << r.output;
    r = run_candela("render " + kScene + " --min-spp 8");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("--min-spp: adaptive sampling is off"), std::string::npos) << r.output;
    EXPECT_EQ(run_candela("render " + kScene + " --noise-threshold 0.1 --min-spp 1").exit_code, 2);
    EXPECT_EQ(run_candela("render " + kScene + " --target-error 0").exit_code, 2);
}

// --target-error stops early and says so; a checkpoint of an adaptive render refuses other settings.
TEST(Cli, TargetErrorAndAdaptiveSummaryAndResume) {
    const fs::path dir = temp_dir("adaptive");
    const std::string out = (dir / "a.exr").string();
    CliResult r = run_candela("render " + kScene + " --resolution 16x16 --spp 4096 --target-error 0.05 -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("of 4096 spp"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(converged), spp mean"), std::string::npos) << r.output;
    // A target met at the first check: the summary says what the estimate cannot see.
    r = run_candela("render " + kScene + " --resolution 16x16 --spp 4096 --target-error 10 -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("min 16 max 16 (stopped at the first check: the estimate cannot see light that no sample "
                            "has found yet)"),
              std::string::npos)
        << r.output;

    r = run_candela("render " + kScene + " --resolution 16x16 --spp 24 --noise-threshold 0.2 --checkpoint-every 100 -o " +
                    out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("spp mean"), std::string::npos) << r.output;
    r = run_candela("render " + kScene + " --resolution 16x16 --spp 32 --noise-threshold 0.3 --resume " + out +
                    ".ckpt -o " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("cannot resume: the checkpoint used adaptive sampling with threshold 0.2 and min_spp 16, "
                            "this render adaptive sampling with threshold 0.3 and min_spp 16"),
              std::string::npos)
        << r.output;
    r = run_candela("render " + kScene + " --resolution 16x16 --spp 32 --noise-threshold 0.2 --resume " + out +
                    ".ckpt -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.output;
}

// As a user meets it: a render at --resolution 20x12, resumed with --resume alone, continues at
// 20x12; a --resolution that contradicts the checkpoint is refused naming the flag and the file.
TEST(Cli, ResumeTakesTheResolutionFromTheCheckpoint) {
    const fs::path dir = temp_dir("resume_resolution");
    const std::string ckpt = (dir / "ck.ckpt").string();
    CliResult r = run_candela("render " + kScene + " --resolution 20x12 --spp 2 --checkpoint " + ckpt + " -o " +
                              (dir / "a.pfm").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    r = run_candela("render " + kScene + " --spp 4 --resume " + ckpt + " -o " + (dir / "b.pfm").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("candela: 20x12, 4 spp"), std::string::npos) << r.output;
    r = run_candela("render " + kScene + " --resolution 30x30 --spp 4 --resume " + ckpt + " -o " +
                    (dir / "c.pfm").string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output, "candela: error: " + ckpt + ": cannot resume: the checkpoint is 20x12, this render 30x30 "
                        "(--resolution 30x30; without it the render takes the checkpoint's)\n");
}

TEST(Cli, SensorFlagsAreCheckedAsTheFilmKeys) {
    CliResult r = run_candela("render " + kScene + " --white-balance 500");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output,
              "candela: error: --white-balance: expected 0 (no white balance) or a temperature >= 1000 (kelvin), got 500\n");
    r = run_candela("render " + kScene + " --iso -200");
    EXPECT_EQ(r.output, "candela: error: --iso: expected a number > 0 within float range, got -200\n");
    CliResult h = run_candela("render --help");
    for (const char* flag : {"--iso", "--exposure-time", "--white-balance"})
        EXPECT_NE(h.output.find(flag), std::string::npos) << flag;
}

TEST(Cli, BsdfIntegratorFlagRefusesDeltaLights) {
    // The scene file's bsdf is refused by the loader (scene_delta_lights_test.cpp); the flag
    // that sets it after loading is refused too, rather than rendering without the light.
    fs::path dir = temp_dir("bsdf_delta");
    fs::path scene = dir / "point.json";
    std::ofstream(scene) << R"({"materials": {"m": {"type": "diffuse"}},
        "shapes": [{"type": "quad", "corner": [-1, 0, -1], "edge1": [0, 0, 2], "edge2": [2, 0, 0], "material": "m"}],
        "camera": {"position": [0, 2, -3], "look_at": [0, 0, 0], "resolution": [8, 8]},
        "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 3}]})";
    CliResult r = run_candela("render " + scene.string() + " --integrator bsdf -o " + (dir / "x.png").string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output,
              "candela: error: --integrator bsdf: the bsdf integrator finds light only by hitting it, so it "
              "cannot see the scene's point, spot or directional lights (they have no area); use path or "
              "whitted\n");
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    CliResult ok = run_candela("render " + scene.string() + " --integrator whitted --spp 1 -o " +
                               (dir / "y.png").string());
    EXPECT_EQ(ok.exit_code, 0) << ok.output;
    EXPECT_TRUE(fs::exists(dir / "y.png"));
}

TEST(Cli, RendersWithOverridesToEveryFormat) {
    fs::path dir = temp_dir("render");
    std::string outs;
    for (const char* ext : {".png", ".exr", ".pfm", ".hdr", ".ppm"}) outs += " -o " + (dir / (std::string("img") + ext)).string();
    CliResult r = run_candela("render " + kScene + " --spp 1 --resolution 24x16 --threads 2 --integrator normals" + outs);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* ext : {".png", ".exr", ".pfm", ".hdr", ".ppm"})
        EXPECT_GT(fs::file_size(dir / (std::string("img") + ext)), 0u) << ext;
    EXPECT_NE(r.output.find("24x16, 1 spp, normals"), std::string::npos) << r.output;
}

// --aov: layers inside an .exr under their conventional channel names, and files beside a .png.
TEST(Cli, AovFlagWritesLayersIntoExrAndBesideOtherFormats) {
    fs::path dir = temp_dir("aov");
    CliResult r = run_candela("render " + kScene +
                              " --spp 2 --resolution 24x16 --threads 2 --aov albedo,normal,depth,position -o " +
                              (dir / "img.exr").string() + " -o " + (dir / "img.png").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::vector<std::string> names = candela::read_exr_channel_names(dir / "img.exr");
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "N.X", "N.Y", "N.Z", "P.X", "P.Y", "P.Z", "R", "Z", "albedo.B",
                                               "albedo.G", "albedo.R"}));
    for (const char* side : {"img.albedo.png", "img.normal.png", "img.depth.pfm", "img.position.pfm"})
        EXPECT_TRUE(fs::is_regular_file(dir / side)) << side;
    EXPECT_FALSE(fs::exists(dir / "img.albedo.exr"));  // inside the .exr, not beside it
}

// pbrt-v4's Film "gbuffer": candela's AOV layers under pbrt-v4's channel names, in the same EXR,
// with position and normal in camera space (pbrt-v4's default) or world space. The scene: the
// camera at (1, 2, -3) looking along +z at a diffuse wall in the plane z = 5 (8 in front of it).
TEST(Cli, PbrtGbufferFilmWritesPbrtsChannelsInEitherSpace) {
    const fs::path dir = temp_dir("gbuffer");
    for (const std::string space : {"camera", "world"}) {
        const fs::path scene = dir / (space + ".pbrt");
        std::ofstream(scene) << "LookAt 1 2 -3  1 2 5  0 1 0\nCamera \"perspective\" \"float fov\" 30\n"
                                "Sampler \"independent\" \"integer pixelsamples\" 4\n"
                                "Film \"gbuffer\" \"integer xresolution\" 8 \"integer yresolution\" 8 "
                                "\"string coordinatesystem\" \""
                             << space
                             << "\"\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                                "Material \"diffuse\" \"rgb reflectance\" [0.6 0.4 0.2]\n"
                                "Shape \"trianglemesh\" \"point3 P\" [-20 -20 5  20 -20 5  20 20 5  -20 20 5] "
                                "\"integer indices\" [0 1 2 0 2 3]\n";
        const fs::path out = dir / (space + ".exr");
        CliResult r = run_candela("render " + scene.string() + " --threads 2 -o " + out.string());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;  // nothing that works warns
        std::vector<std::string> names = candela::read_exr_channel_names(out);
        std::sort(names.begin(), names.end());
        EXPECT_EQ(names, (std::vector<std::string>{"Albedo.B", "Albedo.G", "Albedo.R", "B", "G", "Ns.X", "Ns.Y", "Ns.Z",
                                                   "P.X", "P.Y", "P.Z", "R", "variance.B", "variance.G",
                                                   "variance.R"}));
        const candela::Image albedo = candela::read_exr_channels(out, {"Albedo.R", "Albedo.G", "Albedo.B"});
        const candela::Image p = candela::read_exr_channels(out, {"P.X", "P.Y", "P.Z"});
        const candela::Image n = candela::read_exr_channels(out, {"Ns.X", "Ns.Y", "Ns.Z"});
        const bool camera = space == "camera";
        double left_x = 0.0, right_x = 0.0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                const size_t i = size_t(y * 8 + x);
                // The wall's reflectance, the same in every pixel (EXR halves: 2^-11 relative).
                EXPECT_NEAR(albedo.pixels[i].r, 0.6f, 1e-3f);
                EXPECT_NEAR(albedo.pixels[i].g, 0.4f, 1e-3f);
                EXPECT_NEAR(albedo.pixels[i].b, 0.2f, 1e-3f);
                // Every hit is on the plane: 8 ahead of the camera, or at world z = 5.
                EXPECT_NEAR(p.pixels[i].b, camera ? 8.0f : 5.0f, 1e-2f) << x << " " << y;
                // The normal faces the camera: -z in both spaces (the camera looks along world +z).
                EXPECT_NEAR(n.pixels[i].b, -1.0f, 1e-3f);
                EXPECT_NEAR(n.pixels[i].r, 0.0f, 1e-3f);
                (x < 4 ? left_x : right_x) += double(p.pixels[i].r) / 32.0;
            }
        // Image right is the camera's +x (world +x here); the camera sits at world x = 1.
        EXPECT_LT(left_x, right_x);
        EXPECT_NEAR(0.5 * (left_x + right_x), camera ? 0.0 : 1.0, 0.05);
    }
}

TEST(Cli, BadAovValuesAreRefused) {
    fs::path dir = temp_dir("aov_bad");
    const std::string out = " -o " + (dir / "x.exr").string();
    CliResult unknown = run_candela("render " + kScene + " --aov albedo,normals" + out);
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.output.find("--aov: unknown AOV layer \"normals\"; expected one of: albedo, normal, depth, "
                                  "position, variance, spp"),
              std::string::npos)
        << unknown.output;
    CliResult twice = run_candela("render " + kScene + " --aov depth,depth" + out);
    EXPECT_EQ(twice.exit_code, 2);
    EXPECT_NE(twice.output.find("AOV layer \"depth\" is listed twice"), std::string::npos) << twice.output;
    CliResult empty = run_candela("render " + kScene + " --aov albedo,,depth" + out);
    EXPECT_EQ(empty.exit_code, 2) << empty.output;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace
