#include "adaptive_flags.h"

#include <fmt/format.h>

#include <cmath>

#include "candela/core/error.h"
#include "candela/film/pixel_statistics.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "candela/render/shard.h"
#include "candela/scene/scene.h"

namespace candela::cli {

namespace {

[[noreturn]] void bad_flag(const std::string& message) { throw SceneError({}, message); }

constexpr int kMaxSpp = 1 << 24;  // the scene loader's limit

}  // namespace

void add_adaptive_flags(CLI::App& cmd, AdaptiveArgs& args) {
    cmd.add_option("--noise-threshold", args.noise_threshold,
                   "Adaptive sampling: stop sampling 8x8 pixel blocks whose relative error is below this "
                   "(overrides sampler.adaptive.threshold; 0 = off). --spp is then the most a pixel takes");
    cmd.add_option("--min-spp", args.min_spp,
                   "Adaptive sampling: samples every pixel takes first (overrides sampler.adaptive.min_spp; "
                   "default 16)");
    cmd.add_option("--target-error", args.target_error,
                   "Render until the image's estimated relMSE is at most E (or --spp, --time-limit come first)");
}

void apply_adaptive_overrides(const AdaptiveArgs& args, Scene& scene) {
    if (args.noise_threshold) {
        const double t = *args.noise_threshold;
        if (!(t >= 0.0 && t < 1.0))
            bad_flag(fmt::format("--noise-threshold: expected a number in [0, 1) (0: no adaptive sampling), got {}", t));
        if (t == 0.0)
            scene.sampler.adaptive.reset();
        else
            scene.sampler.adaptive = AdaptiveSettings{float(t), scene.sampler.adaptive.value_or(AdaptiveSettings{}).min_spp};
    }
    if (args.min_spp) {
        if (*args.min_spp < 2 || *args.min_spp > kMaxSpp)
            bad_flag(fmt::format("--min-spp: expected an integer in [2, {}], got {}", kMaxSpp, *args.min_spp));
        if (!scene.sampler.adaptive)
            bad_flag("--min-spp: adaptive sampling is off; turn it on with --noise-threshold or sampler.adaptive");
        scene.sampler.adaptive->min_spp = *args.min_spp;
    }
}

void apply_adaptive_options(const AdaptiveArgs& args, RenderOptions& options) {
    if (!args.target_error) return;
    const double e = *args.target_error;
    if (!(e > 0.0) || !std::isfinite(e)) bad_flag(fmt::format("--target-error: expected a relMSE > 0, got {}", e));
    options.target_error = e;
}

void check_target_error_alone(const RenderOptions& options) {
    if (options.target_error > 0.0)
        bad_flag("--target-error does not run with --shard: each part would stop on its own pixels' estimate, and "
                 "the merged image would not meet the target; use --noise-threshold (adaptive sampling, which shards "
                 "and merges bit for bit), or render --target-error in one process or under mpirun");
}

void check_resumed_statistics(const std::string& checkpoint, const Film& film, const Scene& scene,
                              const RenderOptions& options) {
    if (needs_statistics(scene, options) && !film.has_statistics())
        throw SceneError(SourceLocation{checkpoint, 0, 0, ""},
                         "cannot resume: the checkpoint keeps no per-pixel statistics (it was written without "
                         "adaptive sampling or --target-error), which --target-error needs; render again");
}

std::string adaptive_summary(const RenderResult& result, Shard shard) {
    const Film& film = result.state.film;
    if (!film.has_statistics()) return "";
    std::vector<PixelBounds> regions;  // a shard's pixels; empty: the whole film
    if (shard.count > 1)
        for (const Tile& tile : shard_tiles(film.width(), film.height(), shard)) regions.push_back(tile.bounds());
    const SppSummary spp = spp_summary(film, regions);
    return fmt::format(", relMSE ~{:.3g}{}, spp mean {:.1f} min {:g} max {:g}",
                       result.stats.relmse_estimate.value_or(estimated_relmse(film, regions)),
                       result.stats.converged ? " (converged)" : "", spp.mean, spp.min, spp.max);
}

}  // namespace candela::cli
