#include "candela/render/job/shard_part.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <functional>
#include <string_view>

#include "candela/core/check.h"
#include "candela/core/error.h"
#include "candela/render/job/checkpoint_codec.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
using namespace checkpoint_codec;

// The file's numbering of the output settings (shard_part.h).
static_assert(int(Tonemap::kClamp) == 0 && int(Tonemap::kExposure) == 1 && int(Tonemap::kReinhard) == 2 &&
              int(Tonemap::kAces) == 3);
static_assert(int(Transfer::kSrgb) == 0 && int(Transfer::kGamma) == 1);
// What follows the common header: ten u32, the adaptive settings (with statistics only) and the
// pixel count.
constexpr uint64_t kPartHeaderBytes = 10 * 4 + 2 * 4 + 8;

uint32_t float_bits(float v) { return std::bit_cast<uint32_t>(v); }
float bits_float(uint32_t v) { return std::bit_cast<float>(v); }

uint64_t pixel_count(const std::vector<Tile>& tiles) {
    uint64_t n = 0;
    for (const Tile& t : tiles) n += uint64_t(t.pixels());
    return n;
}

}  // namespace

PartInfo part_info(const Scene& scene, Shard shard) {
    PartInfo info;
    info.shard = shard;
    info.target_spp = uint32_t(scene.sampler.spp);
    info.output.tonemap = scene.film.tonemap;
    info.output.exposure = scene.film.exposure;
    info.output.transfer = scene.film.transfer;
    info.output.gamma = scene.film.gamma;
    return info;
}

void write_shard_part(const fs::path& file, const RenderIdentity& identity, const PartInfo& info,
                      const RenderState& state) {
    const Film& film = state.film;
    RenderIdentity id = identity;
    id.width = film.width();
    id.height = film.height();
    const std::vector<Tile> tiles = shard_tiles(film.width(), film.height(), info.shard);
    Writer w;
    write_common_header(w, kPartFormatVersion, id, state.samples_done, state.dropped_samples);
    w.u32(uint32_t(info.shard.index));
    w.u32(uint32_t(info.shard.count));
    w.u32(info.target_spp);
    w.u32(uint32_t(kShardTileSize));
    w.u32(uint32_t(film.values_per_pixel()));
    w.u32((film.weighted() ? kWeightedFlag : 0u) | (film.has_statistics() ? kStatisticsFlag : 0u) |
          (film.aovs().mask() << kAovFlagShift));
    w.u32(uint32_t(info.output.tonemap));
    w.u32(float_bits(info.output.exposure));
    w.u32(uint32_t(info.output.transfer));
    w.u32(float_bits(info.output.gamma));
    CANDELA_CHECK(film.has_statistics() || !identity.adaptive);
    if (film.has_statistics()) {
        w.u32(identity.adaptive ? uint32_t(identity.adaptive->min_spp) : 0u);
        w.u32(identity.adaptive ? float_bits(identity.adaptive->threshold) : 0u);
    }
    w.u64(pixel_count(tiles));
    std::vector<double> values;
    write_checksummed(file, w, [&](Writer& out, const std::function<void()>& flush) {
        for (const Tile& tile : tiles) {
            values.resize(size_t(tile.pixels()) * size_t(film.values_per_pixel()));
            film.read_region(tile.bounds(), values.data());
            for (double v : values) out.f64(v);
            flush();
        }
    });
}

ShardPart read_shard_part(const fs::path& file) {
    const uint64_t size = file_size_of(file);
    std::string data = read_file_start(file, size, kMaxCommonHeaderBytes + kPartHeaderBytes);
    Reader r(std::string_view(data).substr(kMagic.size()));
    const CommonHeader h = read_common_header(file, r, size);
    if (h.format != kPartFormatVersion)
        fail(file, "a checkpoint of the whole image, not a shard's part file (candela render --shard I/N writes "
                   "parts; resume this one without --shard)");
    ShardPart part;
    part.identity = h.identity;
    part.samples_done = h.samples_done;
    part.dropped_samples = h.dropped_samples;
    const uint32_t index = r.u32(), count = r.u32();
    part.info.target_spp = r.u32();
    const uint32_t tile_size = r.u32(), values_per_pixel = r.u32(), flags = r.u32(), tonemap = r.u32();
    part.info.output.exposure = bits_float(r.u32());
    const uint32_t transfer = r.u32();
    part.info.output.gamma = bits_float(r.u32());
    const bool statistics = (flags & kStatisticsFlag) != 0;
    const uint32_t min_spp = statistics ? r.u32() : 0u, threshold_bits = statistics ? r.u32() : 0u;
    const uint64_t pixels = r.u64();
    if (r.truncated()) fail(file, fmt::format("truncated part file: {} bytes, the header alone is longer", size));
    auto corrupt = [&](const std::string& what) { fail(file, "corrupt part file header: " + what); };
    if (count < 1 || count > uint32_t(kMaxShards) || index < 1 || index > count)
        corrupt(fmt::format("part {} of {}", index, count));
    part.info.shard = Shard{int(index), int(count)};
    if (part.info.target_spp < 1) corrupt("target spp 0");
    if (tile_size != uint32_t(kShardTileSize))
        fail(file, fmt::format("a part of tiles of {} pixels; this candela cuts shards into tiles of {}", tile_size,
                               kShardTileSize));
    if ((flags & ~(kWeightedFlag | kStatisticsFlag | (((1u << kAovLayerCount) - 1u) << kAovFlagShift))) != 0)
        corrupt(fmt::format("unknown film flags {:#x}", flags));
    part.weighted = (flags & kWeightedFlag) != 0;
    part.statistics = statistics;
    for (int l = 0; l < kAovLayerCount; ++l)
        if ((flags >> (kAovFlagShift + unsigned(l))) & 1u) part.aovs.add(AovLayer(l));
    part.identity.aov_layers = part.aovs.mask();
    if (min_spp != 0 || threshold_bits != 0) {
        const float threshold = bits_float(threshold_bits);
        if (min_spp < 2 || min_spp > (1u << 24) || !(threshold > 0.0f && threshold < 1.0f))
            corrupt(fmt::format("adaptive sampling settings {}, {:#x}", min_spp, threshold_bits));
        part.identity.adaptive = AdaptiveSettings{threshold, int(min_spp)};
    }
    part.values_per_pixel = Film(1, 1, part.weighted, part.aovs, part.statistics).values_per_pixel();
    if (values_per_pixel != uint32_t(part.values_per_pixel))
        fail(file, fmt::format("a part of a film with {} values per pixel; this candela's film{}{} has {}",
                               values_per_pixel, part.weighted ? " with weight sums" : "",
                               part.statistics ? " with statistics" : "", part.values_per_pixel));
    if (tonemap > 3) corrupt(fmt::format("tone map {}", tonemap));
    if (transfer > 1) corrupt(fmt::format("transfer {}", transfer));
    part.info.output.tonemap = Tonemap(tonemap);
    part.info.output.transfer = Transfer(transfer);
    if (!(part.info.output.exposure >= 0.0f && part.info.output.exposure < 1.0f))
        corrupt(fmt::format("exposure {}", part.info.output.exposure));
    if (!(part.info.output.gamma > 0.0f && std::isfinite(part.info.output.gamma)))
        corrupt(fmt::format("gamma {}", part.info.output.gamma));
    const RenderIdentity& id = part.identity;
    if (pixels > uint64_t(id.width) * uint64_t(id.height))
        corrupt(fmt::format("{} pixels in a part of a {}x{} film", pixels, id.width, id.height));

    // The size the header claims and the checksum first, the tiles (a sort of up to 2^22 of them)
    // only then.
    const size_t header = kMagic.size() + r.position();
    const size_t value_count = size_t(pixels) * values_per_pixel;
    const uint64_t expected = header + value_count * 8 + 8;
    if (size < expected)
        fail(file, fmt::format("truncated part file: {} bytes, part {} of {} of a {}x{} film has {}", size, index,
                               count, id.width, id.height, expected));
    if (size > expected)
        fail(file, fmt::format("corrupt part file: {} bytes, {} more than part {} of {} of a {}x{} film has", size,
                               size - expected, index, count, id.width, id.height));
    data = read_bytes(file, size);
    check_checksum(file, data);
    const uint64_t expected_pixels = pixel_count(shard_tiles(id.width, id.height, part.info.shard));
    if (pixels != expected_pixels)
        corrupt(fmt::format("{} pixels, part {} of {} of a {}x{} film has {}", pixels, index, count, id.width,
                            id.height, expected_pixels));
    Reader body(std::string_view(data).substr(header, value_count * 8));
    part.values.resize(value_count);
    for (size_t i = 0; i < value_count; ++i) {
        part.values[i] = body.f64();
        if (!std::isfinite(part.values[i]))
            fail(file, fmt::format("corrupt part file: its pixel {} has a non-finite value", i / values_per_pixel));
    }
    return part;
}

void put_part_values(const ShardPart& part, Film& film) {
    CANDELA_CHECK(film.width() == part.identity.width && film.height() == part.identity.height &&
                  film.values_per_pixel() == part.values_per_pixel);
    const double* in = part.values.data();
    for (const Tile& tile : shard_tiles(film.width(), film.height(), part.info.shard)) {
        film.write_region(tile.bounds(), in);
        in += size_t(tile.pixels()) * size_t(part.values_per_pixel);
    }
}

void check_part_matches(const fs::path& file, const ShardPart& part, const RenderIdentity& identity, Shard shard,
                        const Film& film) {
    check_checkpoint_matches(file, part.identity, identity);
    const Shard s = part.info.shard;
    if (s != shard)
        fail(file, fmt::format("cannot resume: this is part {} of {}, the render asks for --shard {}/{} (resume it "
                               "with --shard {}/{})",
                               s.index, s.count, shard.index, shard.count, s.index, s.count));
    if (part.values_per_pixel != film.values_per_pixel() || part.weighted != film.weighted() ||
        part.statistics != film.has_statistics() || !(part.aovs == film.aovs()))
        fail(file, fmt::format("cannot resume: the part's film keeps {} values per pixel, this render's {}",
                               part.values_per_pixel, film.values_per_pixel()));
}

}  // namespace candela
