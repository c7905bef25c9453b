#include "candela/render/thread_executor.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <utility>

#include "candela/render/frame_renderer.h"
#include "candela/geometry/accelerator.h"

namespace candela {

struct ThreadExecutor::Pool {
    explicit Pool(int threads) : arena(threads) {}
    tbb::task_arena arena;
    tbb::enumerable_thread_specific<TileTally> tallies;
};

ThreadExecutor::ThreadExecutor(const FrameRenderer& frame, int threads)
    : frame_(frame), threads_(threads > 0 ? threads : tbb::info::default_concurrency()),
      pool_(std::make_unique<Pool>(threads_)) {}

ThreadExecutor::~ThreadExecutor() = default;

// One task per tile (simple_partitioner): the default partitioner hands a thread runs of tiles
// that it then renders alone, so at the end of a pass the other threads idle while it finishes
// its run. With passes that end often, that cost 4% at 2 threads (bench/RESULTS.md); a tile is
// milliseconds of work, far above a task's cost. A stop seen before a tile abandons the rest.
uint64_t ThreadExecutor::run_pass(const PassWork& pass, PassEngine& engine) {
    const std::vector<Tile>& tiles = engine.tiles();
    pool_->arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
            enable_flush_denormals();
            TileTally& tally = pool_->tallies.local();
            for (size_t t = r.begin(); t != r.end(); ++t) {
                if (engine.should_stop()) return;
                const uint64_t rays_before = tally.rays.total();
                frame_.render_tile(tiles[t], pass.begin, pass.end, *pass.from, *pass.to, tally, pass.target_scale);
                engine.tile_done(t, pass, tally.rays.total() - rays_before);
            }
        }, tbb::simple_partitioner());
    });
    uint64_t dropped = 0;
    for (TileTally& t : pool_->tallies) dropped += std::exchange(t.dropped, 0);
    return dropped;
}

RayCounters ThreadExecutor::finish(RenderEnd, const RenderState&) {
    RayCounters rays;
    for (const TileTally& t : pool_->tallies) rays += t.rays;
    return rays;
}

}  // namespace candela
