#pragma once
// Which rank of an MPI job renders which tile of a pass (distributed/mpi_renderer.h). Rank 0 owns
// the scheduler and hands tiles out on request, so a faster or idler rank simply asks more often:
// no rank is given a fixed share that could hold the frame back.
//
// A tile's pass starts from the tile's values after the previous pass. Rank 0 always has them (every
// result comes home), and the rank that computed them still has them too. So the scheduler
// prefers to give a rank the tiles it computed last (then only the result travels: none of the
// start values), then tiles everybody has (a render from zero: the first pass), and only when a
// rank has none of those left steals from the rank with the most tiles left (then rank 0 sends
// the start values with the tile). In a steady render most tiles stay where they are.
//
// Plain C++ without MPI, so that it is tested without a cluster.
#include <cstdint>
#include <vector>

namespace candela {

class TileScheduler {
  public:
    // `tiles` tiles shared by `ranks` ranks (rank 0 is the root). `start_is_zero`: every rank
    // already has every tile's start values (all zero: a render that starts from nothing).
    TileScheduler(int tiles, int ranks, bool start_is_zero);

    struct Assignment {
        int tile = 0;
        bool send_values = false;  // the rank lacks the tile's start values: send them along
    };

    // Makes every tile pending again for a new pass.
    void start_pass();
    // Up to `want` pending tiles for `rank`, preferring those it holds (see above). Empty when the
    // pass has no pending tile left.
    std::vector<Assignment> take(int rank, int want);
    // The tile's pass was computed by `rank`, which now holds its values (as does rank 0).
    void done(int tile, int rank);

    bool pass_complete() const { return done_ == tiles_; }
    int pending() const { return pending_count_; }
    int tiles() const { return tiles_; }

  private:
    static constexpr int kEveryone = -1;
    int tiles_ = 0;
    int done_ = 0;
    int pending_count_ = 0;
    std::vector<int> holder_;                // per tile: the rank holding its current values
    std::vector<std::vector<int>> pending_;  // per rank: pending tiles it holds; back = kEveryone's
    // pending_[ranks]: the tiles everybody holds.
};

}  // namespace candela
