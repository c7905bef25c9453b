#include "candela/distributed/tile_scheduler.h"

#include <algorithm>

#include "candela/core/check.h"

namespace candela {

TileScheduler::TileScheduler(int tiles, int ranks, bool start_is_zero)
    : tiles_(tiles), done_(tiles), holder_(size_t(tiles), start_is_zero ? kEveryone : 0), pending_(size_t(ranks) + 1) {
    CANDELA_CHECK(ranks >= 1 && tiles >= 0);
}

void TileScheduler::start_pass() {
    for (std::vector<int>& list : pending_) list.clear();
    const int everyone = int(pending_.size()) - 1;
    // Pushed in reverse so that each list hands its tiles out in row-major order (from the back).
    for (int t = tiles_ - 1; t >= 0; --t) pending_[size_t(holder_[size_t(t)] == kEveryone ? everyone : holder_[size_t(t)])].push_back(t);
    pending_count_ = tiles_;
    done_ = 0;
}

std::vector<TileScheduler::Assignment> TileScheduler::take(int rank, int want) {
    CANDELA_CHECK(rank >= 0 && rank + 1 < int(pending_.size()));
    std::vector<Assignment> out;
    auto take_from = [&](std::vector<int>& list, bool send_values) {
        while (int(out.size()) < want && !list.empty()) {
            out.push_back({list.back(), send_values});
            list.pop_back();
        }
    };
    take_from(pending_[size_t(rank)], false);
    take_from(pending_.back(), false);
    while (int(out.size()) < want) {
        // Steal from the rank with the most pending tiles (rank 0 has every tile's values, so
        // it never needs them sent).
        std::vector<int>* victim = nullptr;
        for (size_t r = 0; r + 1 < pending_.size(); ++r)
            if (!pending_[r].empty() && (!victim || pending_[r].size() > victim->size())) victim = &pending_[r];
        if (!victim) break;
        take_from(*victim, rank != 0);
    }
    pending_count_ -= int(out.size());
    return out;
}

void TileScheduler::done(int tile, int rank) {
    CANDELA_CHECK(tile >= 0 && tile < tiles_ && done_ < tiles_);
    holder_[size_t(tile)] = rank;
    ++done_;
}

}  // namespace candela
