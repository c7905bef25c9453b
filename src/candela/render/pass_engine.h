#pragma once
// The one pass loop of every render. A render takes its samples in passes: samples [begin, end)
// of every tile's pixels, read from one film and written to a second, swapped when the whole pass
// is done (so a pass abandoned halfway leaves no trace). The PassEngine owns the policy, written
// once: the second film, each pass's size (pass_schedule.h), the decision points of adaptive
// sampling and of a target error (adaptive_sampling.h, error_allocation.h) and which blocks stay
// active, the stop and the deadline, on_pass, the progress bar, and the final statistics. What
// runs a pass's tiles is a PassExecutor: a thread pool in one process (thread_executor.h, also
// for a shard, whose tiles are its part of the image), rank 0's tile scheduler and the other
// ranks under MPI (distributed/mpi_renderer.cpp). Since every way computes each tile's pass with
// FrameRenderer::render_tile from the same state, every way gives the same bits.
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "candela/film/aov_layers.h"
#include "candela/render/render_options.h"
#include "candela/render/tile.h"
#include "candela/scene/render_settings.h"

namespace candela {

struct Scene;
class FrameRenderer;
class PassEngine;
class ProgressBar;

// One pass, as the engine hands it to an executor: samples [begin, end) of each of the engine's
// tiles, read from `from` and written to `to`.
struct PassWork {
    uint32_t id = 0;  // 1 for the render's first pass (in this call), then 2, ...
    uint32_t begin = 0, end = 0;
    const Film* from = nullptr;
    Film* to = nullptr;
    // --target-error: its allocation's scale at the last decision point (FrameRenderer::render_tile).
    std::optional<double> target_scale;
};

// Runs passes' tiles. An open set (threads, MPI ranks), so virtual; called once per pass.
class PassExecutor {
  public:
    virtual ~PassExecutor() = default;
    // Render threads (per process, under MPI per rank), for the statistics.
    virtual int threads() const = 0;
    // Renders every tile of engine.tiles() for `pass` and returns the NaN/Inf samples it dropped.
    // Asks engine.should_stop() before tiles (from any thread) and returns early when it says so;
    // calls engine.tile_done for each tile rendered.
    virtual uint64_t run_pass(const PassWork& pass, PassEngine& engine) = 0;
    // After the last pass (complete, stopped or out of time) with the state it left: stops the
    // executor's threads (and ranks) and returns every ray they traced.
    virtual RayCounters finish(RenderEnd end, const RenderState& state) = 0;
};

class PassEngine {
  public:
    // A render of `scene` on `frame` (built from it) with `options`, from `start`. Throws
    // RenderError when start cannot continue it (another size, weight sums, AOV layers, or
    // missing statistics that adaptive sampling or a target needs).
    PassEngine(const FrameRenderer& frame, const Scene& scene, const RenderOptions& options, RenderState start);
    ~PassEngine();
    PassEngine(const PassEngine&) = delete;
    PassEngine& operator=(const PassEngine&) = delete;

    // Runs passes through `executor` until the scene's spp are done, every block stopped or the
    // target error is met, options.stop says so or the deadline passes.
    RenderResult run(PassExecutor& executor);

    // The tiles every pass renders (all of the film, or options.shard's).
    const std::vector<Tile>& tiles() const { return tiles_; }

    // For executors, from any thread. Whether the pass in flight is to be abandoned: stopped
    // (options.stop), out of time (options.deadline) or abandoned.
    bool should_stop();
    // Abandons the pass in flight and ends the render (e.g. a stop another MPI rank received).
    void abandon(RenderEnd why);
    // Tile `t` of the pass in flight is done, having traced `rays` rays (the progress bar).
    void tile_done(size_t t, const PassWork& pass, uint64_t rays);

  private:
    bool decide();
    void update_estimate();
    uint64_t update_active();

    const FrameRenderer& frame_;
    const RenderOptions& options_;
    const uint32_t spp_;
    const AovNames aov_names_;  // the channel names of the AOV layers in the result
    const std::optional<AdaptiveSettings> adaptive_;
    const bool target_;      // options.target_error > 0
    const bool decisions_;   // adaptive sampling or a target: passes end at decision points
    const uint32_t first_decision_;
    const std::vector<Tile> tiles_;
    std::vector<PixelBounds> regions_;  // the tiles', for the film's reductions (with statistics)
    uint64_t pixels_ = 0;               // that the tiles cover
    RenderState state_;
    Film next_;  // the second film of a pass, allocated with the first pass
    std::optional<double> target_scale_;
    std::vector<uint64_t> tile_active_;  // decisions: each tile's pixels that take samples
    std::optional<double> relmse_estimate_;
    uint32_t estimate_samples_ = 0;  // the film's count when relmse_estimate_ was made
    bool converged_ = false;
    std::atomic<RenderEnd> end_{RenderEnd::kComplete};
    ProgressBar* progress_ = nullptr;
};

// Whether a render of `scene` with `options` needs a film with statistics: adaptive sampling, a
// target error, options.statistics, or the variance or spp AOV layer.
bool needs_statistics(const Scene& scene, const RenderOptions& options);

// The tiles a render of a width x height film with `options` renders: all of them, or those of
// options.shard. `adaptive`: sizes rounded up to a multiple of the adaptive block size.
std::vector<Tile> render_tiles(int width, int height, const RenderOptions& options, bool adaptive = false);

// Whether `scene` with `options` makes decisions (adaptive sampling or a target error), which
// its tiles' sizes follow (render_tiles' `adaptive`).
bool makes_decisions(const Scene& scene, const RenderOptions& options);

}  // namespace candela
