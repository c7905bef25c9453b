#pragma once
// What a render is asked (RenderOptions) and what it answers (RenderResult): the pass engine's
// (pass_engine.h) inputs and outputs, whichever executor runs its passes.
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "candela/image/image.h"
#include "candela/integrators/ray_counters.h"
#include "candela/render/render_state.h"
#include "candela/render/shard.h"

namespace candela {

// Every member has a default, so that designated initializers may leave any out.
struct RenderOptions {
    int threads = 0;        // 0: all cores
    int tile_size = 16;     // pixels per tile side; does not change the image
    bool progress = false;  // draw a progress bar on stderr

    // Asked between passes and before each tile, from any render thread (so it must be
    // thread-safe, e.g. read an atomic flag a signal handler sets): true stops the render,
    // abandoning the pass in flight.
    std::function<bool()> stop = {};
    // Stop when reached: passes are sized to end before it, a pass still running then is abandoned.
    std::optional<std::chrono::steady_clock::time_point> deadline = {};
    // Called on the calling thread with the state after each complete pass (periodic checkpoints).
    std::function<void(const RenderState&)> on_pass = {};
    double pass_seconds = 2.0;  // about how long a grown pass lasts
    uint32_t pass_spp = 0;      // > 0: passes of exactly this many samples per pixel (tests)
    // Render only this part of the image (shard.h); the other pixels keep the start state's sums.
    // A part other than 1/1 cuts tiles of kShardTileSize, whatever tile_size says.
    Shard shard = {};
    // > 0: stop at the first decision point (adaptive_sampling.h) where the image's estimated
    // relMSE (film/pixel_statistics.h) is at most this. Needs a film with statistics.
    double target_error = 0.0;
    // Keep per-pixel statistics (film.h) without adaptive sampling or a target, e.g. for the
    // variance and spp outputs (film/pixel_statistics.h: variance_image, spp_image).
    bool statistics = false;
};

// Why render() returned.
enum class RenderEnd {
    kComplete,  // scene.sampler.spp samples per pixel (or more, from the start state)
    kStopped,   // options.stop said so
    kDeadline,  // options.deadline passed
};

struct RenderStats {
    double build_seconds = 0;   // accelerator and light tables
    double render_seconds = 0;  // sampling only
    uint64_t samples = 0;       // camera samples taken in complete passes, in this call (of the shard's pixels)
    uint64_t dropped_samples = 0;  // NaN or Inf samples among them, counted as zero and never written
    RayCounters rays;           // all rays traced, abandoned passes included
    int threads = 0;
    int passes = 0;             // complete passes, in this call
    // Films with statistics: the estimated relMSE of the final image (over the rendered tiles),
    // and whether the render ended because every pixel stopped (adaptive sampling) or the
    // estimate met options.target_error.
    std::optional<double> relmse_estimate;
    bool converged = false;
};

struct RenderResult {
    Image image;        // the mean of state's samples (black when it has none)
    std::vector<ImageLayer> aov_layers;  // the film's AOV layers, resolved like `image`
    RenderStats stats;
    RenderState state;  // the sums after the last complete pass: what a checkpoint saves
    RenderEnd end = RenderEnd::kComplete;
};

}  // namespace candela
