#pragma once
// `candela render`'s flags for adaptive sampling and the noise target (issue 17):
// --noise-threshold, --min-spp, --target-error, kept apart from render_command.cpp, and what the
// summary line says of them. The render job checks and applies them (render/job/render_overrides.h).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "candela/render/shard.h"

namespace candela {
struct RenderResult;
}  // namespace candela

namespace candela::cli {

struct AdaptiveArgs {
    std::optional<double> noise_threshold;  // sampler.adaptive.threshold; 0 turns adaptive sampling off
    std::optional<int> min_spp;             // sampler.adaptive.min_spp
    std::optional<double> target_error;     // the image's relMSE to stop at
};

void add_adaptive_flags(CLI::App& cmd, AdaptiveArgs& args);

// For the summary line: ", relMSE ~E, spp mean/min/max" for films with statistics (over the
// shard's pixels for a part), else "".
std::string adaptive_summary(const RenderResult& result, Shard shard = {});

}  // namespace candela::cli
