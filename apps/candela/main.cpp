// candela: the command-line program. Thin by design: parse flags, load, render, write; the
// library does the work. Exit codes: 0 ok, 2 bad input (scene, files, flags), 1 internal error.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "candela/render/progress.h"
#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "candela/scene/scene_loader.h"

namespace fs = std::filesystem;
using namespace candela;

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

struct RenderArgs {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> spp;
    std::optional<uint64_t> seed;
    std::optional<int> threads;
    std::optional<std::string> resolution;
    std::optional<std::string> integrator;
    std::optional<std::string> stats;
};

// A flag value the user got wrong: reported like a scene error, without a file.
[[noreturn]] void bad_flag(const std::string& message) { throw SceneError({}, message); }

// The default output: <scene name>.png in the current folder, where the scene name is the file's
// stem, or its folder's name for the conventional scenes/<name>/scene.json.
fs::path default_output(const fs::path& scene) {
    std::string stem = scene.stem().string();
    if (stem == "scene" && scene.has_parent_path()) stem = fs::absolute(scene).parent_path().filename().string();
    return stem + ".png";
}

void apply_overrides(const RenderArgs& a, Scene& scene) {
    if (a.spp) {
        if (*a.spp < 1) bad_flag(fmt::format("--spp: expected an integer >= 1, got {}", *a.spp));
        scene.sampler.spp = *a.spp;
    }
    if (a.seed) scene.sampler.seed = *a.seed;
    if (a.resolution) {
        std::smatch m;
        static const std::regex kWxH(R"((\d{1,6})x(\d{1,6}))");
        if (!std::regex_match(*a.resolution, m, kWxH))
            bad_flag(fmt::format("--resolution: expected WIDTHxHEIGHT (e.g. 640x480), got \"{}\"", *a.resolution));
        int w = std::stoi(m[1]), h = std::stoi(m[2]);
        if (w < 1 || h < 1 || w > 32768 || h > 32768)
            bad_flag(fmt::format("--resolution: each side must be in 1..32768, got {}x{}", w, h));
        scene.camera.width = w;
        scene.camera.height = h;
    }
    if (a.integrator) {
        std::optional<IntegratorType> t = parse_integrator_type(*a.integrator);
        if (!t)
            bad_flag(fmt::format("--integrator: unknown integrator \"{}\"; expected one of: {}", *a.integrator,
                                 names_list(integrator_type_names())));
        scene.integrator.type = *t;
    }
}

// Render statistics as JSON, for scripts (bench/run.sh) that should not parse the summary line.
void write_stats(const fs::path& file, const Scene& scene, const RenderStats& s) {
    std::string json = fmt::format(
        "{{\"integrator\": \"{}\", \"width\": {}, \"height\": {}, \"spp\": {}, \"threads\": {},\n"
        " \"render_seconds\": {:.6f}, \"build_seconds\": {:.6f}, \"samples\": {}, \"dropped_samples\": {},\n"
        " \"rays\": {{\"camera\": {}, \"bounce\": {}, \"shadow\": {}, \"total\": {}}}}}\n",
        integrator_type_name(scene.integrator.type), scene.camera.width, scene.camera.height, scene.sampler.spp,
        s.threads, s.render_seconds, s.build_seconds, s.samples, s.dropped_samples, s.rays.camera, s.rays.bounce,
        s.rays.shadow, s.rays.total());
    write_contents_atomically(file, json);
}

int run_render(const RenderArgs& a) {
    std::vector<fs::path> outputs(a.outputs.begin(), a.outputs.end());
    if (outputs.empty()) outputs.push_back(default_output(a.scene));
    for (const fs::path& out : outputs)
        if (!is_writable_image_extension(out))
            bad_flag(fmt::format("-o {}: unknown image format \"{}\"; expected one of: .exr, .pfm, .hdr, .png, .ppm",
                                 out.string(), out.extension().string()));
    if (a.threads && *a.threads < 0) bad_flag(fmt::format("--threads: expected an integer >= 0, got {}", *a.threads));

    Scene scene = load_scene(a.scene);
    for (const std::string& w : scene.warnings) fmt::print(stderr, "candela: warning: {}\n", w);
    apply_overrides(a, scene);

    RenderOptions options;
    options.threads = a.threads.value_or(0);
    options.progress = isatty(fileno(stderr)) != 0;
    RenderResult result = render(scene, options);
    for (const fs::path& out : outputs) write_image(out, result.image, scene.film);
    if (a.stats) write_stats(*a.stats, scene, result.stats);

    const RenderStats& s = result.stats;
    std::string outs;
    for (const fs::path& out : outputs) outs += (outs.empty() ? "" : ", ") + out.string();
    fmt::print(stderr, "candela: {}x{}, {} spp, {} in {} ({} build), {}rays ({}rays/s), {} threads{}; wrote {}\n",
               result.image.width, result.image.height, scene.sampler.spp, integrator_type_name(scene.integrator.type),
               format_duration(s.render_seconds), format_duration(s.build_seconds), format_count(double(s.rays.total())),
               format_count(s.render_seconds > 0 ? double(s.rays.total()) / s.render_seconds : 0.0), s.threads,
               s.dropped_samples ? fmt::format(", {} NaN/Inf samples dropped", s.dropped_samples) : "", outs);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"candela: a physically based Monte Carlo path tracer", "candela"};
    app.set_version_flag("--version", std::string("candela ") + CANDELA_VERSION);
    app.require_subcommand(1);

    RenderArgs args;
    CLI::App* render_cmd = app.add_subcommand("render", "Render a scene file to one or more images");
    render_cmd->add_option("scene", args.scene, "Scene file (JSON, see docs/SCENE_FORMAT.md)")->required();
    render_cmd->add_option("-o,--output", args.outputs,
                           "Output image, format by extension: .exr .pfm .hdr (linear), .png .ppm (tone mapped); "
                           "repeatable. Default: <scene name>.png");
    render_cmd->add_option("--spp", args.spp, "Samples per pixel (overrides sampler.spp)");
    render_cmd->add_option("--seed", args.seed, "Random seed (overrides sampler.seed)");
    render_cmd->add_option("--threads", args.threads, "Render threads; 0 = all cores (default)");
    render_cmd->add_option("--resolution", args.resolution, "Image size WIDTHxHEIGHT (overrides camera.resolution)");
    render_cmd->add_option("--stats", args.stats, "Also write render statistics (times, samples, rays by kind) as JSON");
    render_cmd->add_option("--integrator", args.integrator,
                           std::string("Integrator (overrides integrator.type): ") + names_list(integrator_type_names()));

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "candela: error: {}\n", e.what());
        return kExitBadInput;
    }

    try {
        return run_render(args);
    } catch (const SceneError& e) {
        fmt::print(stderr, "candela: error: {}\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "candela: internal error: {}\n", e.what());
        return kExitInternal;
    }
}
