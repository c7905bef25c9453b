#include "convert_command.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_convert.h"
#include "candela/formats/scene_file.h"
#include "candela/render/job/render_overrides.h"

namespace fs = std::filesystem;

namespace candela::cli {

CLI::App* add_convert_command(CLI::App& app, ConvertArgs& args) {
    CLI::App* cmd = app.add_subcommand("convert", "Convert a pbrt-v4 scene into candela's JSON scene format");
    cmd->add_option("scene", args.scene, "pbrt-v4 scene file (.pbrt)")->required();
    cmd->add_option("-o,--output", args.output, "The JSON scene to write; its meshes go beside it (meshes/*.ply)")
        ->required();
    return cmd;
}

int run_convert(const ConvertArgs& a) {
    const fs::path in(a.scene), out(a.output);
    if (!is_pbrt_scene_file(in)) bad_flag(fmt::format("convert reads pbrt-v4 scenes (.pbrt), not {}", in.string()));
    if (out.extension() != ".json") bad_flag(fmt::format("-o {}: the converted scene is JSON (.json)", out.string()));
    const pbrt::ConvertResult result = pbrt::convert_pbrt_scene(in, out);
    for (const std::string& w : result.warnings) fmt::print(stderr, "candela: warning: {}\n", w);
    fmt::print(stderr, "candela: wrote {} ({} mesh file{})\n", out.string(), result.mesh_files,
               result.mesh_files == 1 ? "" : "s");
    return 0;
}

}  // namespace candela::cli
