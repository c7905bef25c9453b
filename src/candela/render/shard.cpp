#include "candela/render/shard.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <numeric>

#include "candela/core/mix_bits.h"

namespace candela {

namespace {

std::optional<int> parse_int(const char* begin, const char* end) {
    int value = 0;
    auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || begin == end) return std::nullopt;
    return value;
}

}  // namespace

std::optional<Shard> parse_shard(const std::string& text) {
    const size_t slash = text.find('/');
    if (slash == std::string::npos) return std::nullopt;
    const char* s = text.data();
    std::optional<int> index = parse_int(s, s + slash), count = parse_int(s + slash + 1, s + text.size());
    if (!index || !count || *count < 1 || *count > kMaxShards || *index < 1 || *index > *count) return std::nullopt;
    return Shard{*index, *count};
}

int shard_tile_count(int width, int height) {
    return ((width + kShardTileSize - 1) / kShardTileSize) * ((height + kShardTileSize - 1) / kShardTileSize);
}

std::vector<Tile> shard_tiles(int width, int height, Shard shard) {
    const std::vector<Tile> tiles = make_tiles(width, height, kShardTileSize);
    // Tile indices in the order of their hash (ties, which a bijection cannot have, by index).
    std::vector<uint32_t> order(tiles.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [](uint32_t a, uint32_t b) { return mix_bits(a) < mix_bits(b); });
    std::vector<uint32_t> mine;
    for (size_t j = size_t(shard.index - 1); j < order.size(); j += size_t(shard.count)) mine.push_back(order[j]);
    std::sort(mine.begin(), mine.end());
    std::vector<Tile> result;
    result.reserve(mine.size());
    for (uint32_t i : mine) result.push_back(tiles[i]);
    return result;
}

}  // namespace candela
