#pragma once
// One image rendered by all ranks of an MPI job, bit-identical to render() (render/renderer.h) on
// one machine with the same scene, spp, sampler and seed: every rank loads the scene and builds its
// own FrameRenderer, and every tile's pass is computed by FrameRenderer::render_tile from the
// tile's values after the previous pass, whichever rank does it.
//
// Rank 0 runs the render's one pass engine (render/pass_engine.h: pass sizes, decisions, stop,
// deadline, checkpoints), with an executor that cuts each pass into tiles and hands them out on
// request (distributed/tile_scheduler.h: a rank gets back the tiles it computed last, so their
// start values need not travel); it renders tiles itself on its own threads while the calling
// thread answers the others; every result comes home at once, into rank 0's second film, so that
// at each pass boundary rank 0 holds the whole state. This file holds messaging, scheduling and
// rank bookkeeping only.
//
// Bytes per pixel and pass: the result, 8 per value (24, or 32 with weight sums), home to rank
// 0; the start values, as much again, only for a tile that changed rank (docs/CLUSTER.md).
//
// Stops: a rank that receives SIGINT or SIGTERM tells rank 0, which abandons the pass in flight
// and ends the job: it tells every rank to stop, collects their ray counts, and returns the state
// of the last complete pass (rank 0's caller writes the image and the checkpoint).
#include <cstdint>
#include <functional>

#include "candela/render/render_options.h"

namespace candela {

class MpiSession;
struct Scene;

struct MpiRenderOptions {
    // threads: per rank (0: this host's cores shared among its ranks); progress, deadline,
    // on_pass, pass_seconds, pass_spp: rank 0's; stop: this rank's; shard: every rank's.
    RenderOptions render;
    // This rank's stop signal (SIGINT, SIGTERM), 0 while it has received none.
    std::function<int()> stop_signal = [] { return 0; };
    // Rank 0, when the job stops early: called with the state of the last complete pass before
    // the other ranks are told to stop. A rank that died cannot answer that, and mpirun then ends
    // the job within a second or two; what this writes (the checkpoint) is saved by then.
    std::function<void(const RenderState&)> on_stop = {};
};

struct MpiRenderResult {
    // Rank 0: as render() returns it, with rays and samples counted over every rank. Other ranks:
    // `end` only.
    RenderResult result;
    int stop_signal = 0;  // the signal that stopped the job, received by any rank; 0 if none
    int exit_code = 0;    // what the job exits with: 128 + stop_signal when stopped, else 0
    int ranks = 1;
    uint64_t bytes_sent = 0;      // by this rank
    uint64_t bytes_received = 0;  // by this rank
};

// Every rank calls it, with the same scene and options; rank 0 passes the state to start from
// (e.g. a checkpoint's), the others an empty one. Throws RenderError when the start state does not
// fit the scene (PassEngine).
MpiRenderResult render_mpi(const MpiSession& session, const Scene& scene, const MpiRenderOptions& options,
                           RenderState start);

// Render threads for a rank when --threads is 0: the cores this process may use, shared evenly
// among the `ranks_on_host` ranks of its host, at least 1.
int default_threads_per_rank(int ranks_on_host);

}  // namespace candela
