#pragma once
// `candela merge part-*.ckpt -o out.exr`: puts the part files of `candela render --shard I/N`
// together and writes the images one render of the whole image would (render/job/shard_merge.h).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace candela::cli {

struct MergeArgs {
    std::vector<std::string> parts;
    std::vector<std::string> outputs;
};

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args);

// Returns the exit code. Bad input (a part that cannot be merged, a bad -o) throws SceneError.
int run_merge(const MergeArgs& args);

}  // namespace candela::cli
