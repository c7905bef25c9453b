#pragma once
// `candela render`: its flags and what it does with them.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "adaptive_flags.h"

namespace candela::cli {

struct RenderArgs {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> spp;
    std::optional<uint64_t> seed;
    std::optional<int> threads;
    std::optional<int> tile_size;  // pixels per tile side
    bool progress = false;         // --progress: draw the bar on stderr whatever it is
    std::optional<std::string> resolution;
    std::optional<std::string> integrator;
    std::optional<std::string> sampler;
    bool spectral = false;  // --spectral
    bool rgb = false;       // --rgb
    std::optional<std::string> stats;
    std::optional<std::string> memory_limit;  // e.g. "8G"; default: what the process can have
    std::optional<double> time_limit;        // seconds
    std::optional<std::string> resume;       // a checkpoint to continue
    std::optional<std::string> checkpoint;   // where checkpoints go
    std::optional<double> checkpoint_every;  // seconds
    std::optional<double> iso;               // the film's sensor (film/sensor.h)
    std::optional<double> exposure_time;     // seconds
    std::optional<double> white_balance;     // kelvin; 0 = none
    std::optional<std::string> shard;        // "I/N": render part I of N to a part file (-o PART.ckpt)
    std::optional<std::string> aov;          // AOV layers, comma-separated (aov_flag.h)
    AdaptiveArgs adaptive;                   // --noise-threshold, --min-spp, --target-error
};

// Adds the subcommand and its flags to the program; parsing fills `args`.
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);

// Renders as the flags say; returns the exit code. Bad input throws SceneError.
int run_render(const RenderArgs& args);

}  // namespace candela::cli
