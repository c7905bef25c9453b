// The MPI renderer's tile scheduler: every tile handed out once per pass, the start values sent
// exactly when the asking rank lacks them, and tiles kept by the rank that computed them.
#include "candela/distributed/tile_scheduler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace candela {
namespace CANDELA_UNITY_ID {

// Takes every tile of a pass by asking the ranks in turn for `want` tiles each, marking each
// done by the rank that took it; returns (tile, rank, send_values) in the order handed out.
struct Handed {
    int tile, rank;
    bool send_values;
};
std::vector<Handed> run_pass(TileScheduler& s, int ranks, int want) {
    s.start_pass();
    std::vector<Handed> handed;
    for (int round = 0; !s.pass_complete(); ++round) {
        const int rank = round % ranks;
        for (const TileScheduler::Assignment& a : s.take(rank, want)) {
            handed.push_back({a.tile, rank, a.send_values});
            s.done(a.tile, rank);
        }
        EXPECT_LT(round, 10000) << "the pass never completes";
        if (round >= 10000) break;
    }
    return handed;
}

TEST(TileScheduler, HandsOutEveryTileOncePerPass) {
    TileScheduler s(37, 4, true);
    for (int pass = 0; pass < 3; ++pass) {
        std::vector<Handed> handed = run_pass(s, 4, 3);
        std::multiset<int> tiles;
        for (const Handed& h : handed) tiles.insert(h.tile);
        ASSERT_EQ(tiles.size(), 37u);
        for (int t = 0; t < 37; ++t) EXPECT_EQ(tiles.count(t), 1u) << "tile " << t << " in pass " << pass;
        EXPECT_EQ(s.pending(), 0);
    }
}

TEST(TileScheduler, FromZeroTheFirstPassSendsNoValues) {
    TileScheduler s(20, 3, true);
    for (const Handed& h : run_pass(s, 3, 2)) EXPECT_FALSE(h.send_values) << "tile " << h.tile;
}

TEST(TileScheduler, FromAResumedStateOnlyOtherRanksAreSentValues) {
    // Rank 0 read the checkpoint: only it has the start values.
    TileScheduler s(20, 3, false);
    for (const Handed& h : run_pass(s, 3, 2)) EXPECT_EQ(h.send_values, h.rank != 0) << "tile " << h.tile;
}

TEST(TileScheduler, ARankGetsBackTheTilesItComputed) {
    TileScheduler s(30, 3, true);
    std::vector<Handed> first = run_pass(s, 3, 2);
    std::vector<int> holder(30);
    for (const Handed& h : first) holder[size_t(h.tile)] = h.rank;
    // The same order of requests: every rank finds its own tiles again, none travels.
    std::vector<Handed> second = run_pass(s, 3, 2);
    for (const Handed& h : second) {
        EXPECT_EQ(h.rank, holder[size_t(h.tile)]) << "tile " << h.tile;
        EXPECT_FALSE(h.send_values);
    }
}

TEST(TileScheduler, AnIdleRankStealsFromTheBusiestWithValues) {
    TileScheduler s(12, 3, true);
    // Pass 1: rank 1 computes tiles 0..7, rank 2 tiles 8..11.
    s.start_pass();
    for (const TileScheduler::Assignment& a : s.take(1, 8)) s.done(a.tile, 1);
    for (const TileScheduler::Assignment& a : s.take(2, 4)) s.done(a.tile, 2);
    ASSERT_TRUE(s.pass_complete());
    s.start_pass();
    // Rank 2 takes its own four, then steals from rank 1 (the one with the most left), with values.
    std::vector<TileScheduler::Assignment> got = s.take(2, 6);
    ASSERT_EQ(got.size(), 6u);
    for (size_t i = 0; i < 4; ++i) EXPECT_FALSE(got[i].send_values);
    for (size_t i = 4; i < 6; ++i) {
        EXPECT_TRUE(got[i].send_values);
        EXPECT_LT(got[i].tile, 8);
    }
    // Rank 0 holds every tile's values: its steals need none.
    for (const TileScheduler::Assignment& a : s.take(0, 2)) EXPECT_FALSE(a.send_values);
    EXPECT_EQ(s.pending(), 4);
    EXPECT_FALSE(s.pass_complete());
}

TEST(TileScheduler, NothingLeftGivesAnEmptyAnswer) {
    TileScheduler s(2, 2, true);
    s.start_pass();
    EXPECT_EQ(s.take(1, 5).size(), 2u);
    EXPECT_TRUE(s.take(0, 1).empty());
    EXPECT_FALSE(s.pass_complete());  // taken is not done
}

}  // namespace
}  // namespace candela
