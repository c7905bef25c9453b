#pragma once
// `candela render`'s flags for adaptive sampling and the noise target (issue 17):
// --noise-threshold, --min-spp, --target-error; kept apart from render_command.cpp.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

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

// Refuses adaptive sampling, --target-error and the variance and spp layers with --shard: part
// files (render/shard_part.h) do not carry the film's statistics yet.
void check_adaptive_alone(const Scene& scene, const RenderOptions& options);

// Refuses (SceneError naming `checkpoint`) a resumed film without the statistics the render needs.
void check_resumed_statistics(const std::string& checkpoint, const Film& film, const Scene& scene,
                              const RenderOptions& options);

// For the summary line: ", relMSE ~E, spp mean/min/max" for films with statistics, else "".
std::string adaptive_summary(const RenderResult& result);

}  // namespace candela::cli
