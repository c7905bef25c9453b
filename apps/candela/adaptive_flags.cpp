#include "adaptive_flags.h"

#include <fmt/format.h>

#include "candela/film/pixel_statistics.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "candela/render/shard.h"

namespace candela::cli {

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

std::string adaptive_summary(const RenderResult& result, Shard shard) {
    const Film& film = result.state.film;
    if (!film.has_statistics()) return "";
    std::vector<PixelBounds> regions;  // a shard's pixels; empty: the whole film
    if (shard.count > 1)
        for (const Tile& tile : shard_tiles(film.width(), film.height(), shard)) regions.push_back(tile.bounds());
    const SppSummary spp = spp_summary(film, regions);
    // Every pixel stopped at the same count: the render stopped at its first check, where the
    // estimate has seen the fewest samples. It cannot see light that no sample has found yet (a
    // caustic, a lamp behind glass): say so, so that a user can tell why it stopped there.
    const bool at_first_check = result.stats.converged && spp.min == spp.max;
    return fmt::format(", relMSE ~{:.3g}{}, spp mean {:.1f} min {:g} max {:g}{}",
                       result.stats.relmse_estimate.value_or(estimated_relmse(film, regions)),
                       result.stats.converged ? " (converged)" : "", spp.mean, spp.min, spp.max,
                       at_first_check ? " (stopped at the first check: the estimate cannot see light that no "
                                        "sample has found yet)"
                                      : "");
}

}  // namespace candela::cli
