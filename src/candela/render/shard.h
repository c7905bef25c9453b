#pragma once
// Shards: a render split into N disjoint parts that separate jobs (a Slurm job array, a
// Kubernetes indexed job) render independently and `candela merge` puts together, bit-identical to
// one render (each pixel's samples are summed in index order by whichever part has the pixel).
//
// The assignment is fixed and documented (docs/CLUSTER.md): the film is cut into tiles of
// kShardTileSize pixels a side, row-major; the tiles are put in the order of mix_bits(tile index)
// (a fixed pseudo-random permutation, sampling/rng.h), and the j-th tile in that order belongs to
// part (j mod N) + 1. So every part has the same number of tiles, give or take one, scattered
// over the whole image: parts take about the same time however the scene's cost is spread.
#include <optional>
#include <string>
#include <vector>

#include "candela/render/tile.h"

namespace candela {

inline constexpr int kShardTileSize = 16;
inline constexpr int kMaxShards = 1 << 20;

struct Shard {
    int index = 1;  // 1..count
    int count = 1;
    bool operator==(const Shard&) const = default;
};

// "I/N" with 1 <= I <= N <= kMaxShards, else nullopt.
std::optional<Shard> parse_shard(const std::string& text);

// The number of tiles of a width x height film cut for shards (the most parts it can have).
int shard_tile_count(int width, int height);

// The tiles of part `shard` of a width x height film, in row-major order. Part 1/1 has them all.
std::vector<Tile> shard_tiles(int width, int height, Shard shard);

}  // namespace candela
