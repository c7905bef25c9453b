#pragma once
// `candela render`'s flags for adaptive sampling and the noise target (issue 17):
// --noise-threshold, --min-spp, --target-error; kept apart from render_command.cpp.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "candela/render/shard.h"

namespace candela {
struct Scene;
struct RenderOptions;
struct RenderResult;
class Film;
}  // namespace candela

namespace candela::cli {

struct AdaptiveArgs {
    std::optional<double> noise_threshold;  // sampler.adaptive.threshold; 0 turns adaptive sampling off
    std::optional<int> min_spp;             // sampler.adaptive.min_spp
    std::optional<double> target_error;     // the image's relMSE to stop at
};

void add_adaptive_flags(CLI::App& cmd, AdaptiveArgs& args);

// The flags' overrides of the scene's sampler.adaptive, checked as the scene key is. An override
// that changes the image also goes into scene_content_hash (checkpoints).
void apply_adaptive_overrides(const AdaptiveArgs& args, Scene& scene);

// The flags' render options (the target error).
void apply_adaptive_options(const AdaptiveArgs& args, RenderOptions& options);

// Refuses --target-error with --shard: a whole-image target is not met by parts that each stop on
// their own pixels' estimate (docs/CLUSTER.md). Adaptive sampling and the variance and spp layers
// do run with --shard: part files carry the film's statistics (render/job/shard_part.h).
void check_target_error_alone(const RenderOptions& options);

// Refuses (SceneError naming `checkpoint`) a resumed film without the statistics the render needs.
void check_resumed_statistics(const std::string& checkpoint, const Film& film, const Scene& scene,
                              const RenderOptions& options);

// For the summary line: ", relMSE ~E, spp mean/min/max" for films with statistics (over the
// shard's pixels for a part), else "".
std::string adaptive_summary(const RenderResult& result, Shard shard = {});

}  // namespace candela::cli
