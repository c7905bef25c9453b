#pragma once
// `candela convert scene.pbrt -o scene.json`: writes the candela scene a pbrt-v4 scene imports as
// (formats/pbrt), with its inline meshes as binary PLY files beside it, so that people can inspect
// and edit what was imported; rendering the converted scene gives the same bits.
#include <CLI/CLI.hpp>

#include <string>

namespace candela::cli {

struct ConvertArgs {
    std::string scene;
    std::string output;
};

CLI::App* add_convert_command(CLI::App& app, ConvertArgs& args);

// Returns the exit code. Bad input throws SceneError.
int run_convert(const ConvertArgs& args);

}  // namespace candela::cli
