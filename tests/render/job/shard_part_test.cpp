// Shards without rendering: the tile assignment partitions the film evenly, "I/N" parses only
// when it names a part, part files (format version 3) round-trip exactly and refuse damage, and
// merging refuses, naming the file(s), everything that would not give the whole render's image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/shard.h"
#include "candela/render/job/shard_merge.h"
#include "candela/render/job/shard_part.h"
#include "support/render_identity.h"
#include "support/scene_error_of.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) { return test::fresh_dir("shard_part_" + name); }

using test::read_bytes;

void write_bytes(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

using test::error_of;

TEST(ShardTiles, PartitionTheFilmEvenly) {
    for (auto [w, h] : {std::pair{1, 1}, {16, 16}, {17, 33}, {100, 37}, {256, 144}}) {
        const int tiles = shard_tile_count(w, h);
        for (int n : {1, 2, 3, 5, 7, tiles}) {
            if (n > tiles) continue;
            std::vector<int> covered(size_t(w * h), 0);
            size_t fewest = SIZE_MAX, most = 0;
            for (int i = 1; i <= n; ++i) {
                const std::vector<Tile> part = shard_tiles(w, h, Shard{i, n});
                fewest = std::min(fewest, part.size());
                most = std::max(most, part.size());
                for (size_t t = 0; t < part.size(); ++t) {
                    if (t > 0) {  // row-major order
                        const Tile &a = part[t - 1], &b = part[t];
                        EXPECT_TRUE(a.y0 < b.y0 || (a.y0 == b.y0 && a.x0 < b.x0));
                    }
                    EXPECT_TRUE(part[t].x1 - part[t].x0 <= kShardTileSize && part[t].y1 - part[t].y0 <= kShardTileSize);
                    for (int y = part[t].y0; y < part[t].y1; ++y)
                        for (int x = part[t].x0; x < part[t].x1; ++x) ++covered[size_t(y * w + x)];
                }
            }
            for (int c : covered) ASSERT_EQ(c, 1) << w << "x" << h << " in " << n << " parts";  // disjoint, covering
            EXPECT_LE(most - fewest, 1u) << w << "x" << h << " in " << n << " parts";
        }
    }
    EXPECT_EQ(shard_tiles(40, 20, Shard{1, 1}), make_tiles(40, 20, kShardTileSize));
}

TEST(ShardTiles, PartsAreScatteredOverTheImage) {
    // 2 parts of a 20x20-tile film: each has tiles in every quadrant (the assignment is a hash,
    // not bands), so each takes about half the time however the cost is spread.
    for (int i : {1, 2}) {
        int quadrants[4] = {};
        for (const Tile& t : shard_tiles(320, 320, Shard{i, 2})) ++quadrants[(t.x0 >= 160) + 2 * (t.y0 >= 160)];
        for (int q : quadrants) EXPECT_GT(q, 30) << "part " << i;
    }
}

TEST(ParseShard, AcceptsOnlyAPartOfN) {
    EXPECT_EQ(parse_shard("1/1"), (Shard{1, 1}));
    EXPECT_EQ(parse_shard("3/5"), (Shard{3, 5}));
    EXPECT_EQ(parse_shard("1048576/1048576"), (Shard{kMaxShards, kMaxShards}));
    for (const char* bad : {"", "1", "/", "1/", "/3", "0/3", "4/3", "1/0", "-1/3", "1/-3", " 1/3", "1/3 ", "1/3/4",
                            "a/b", "1.0/3", "+1/3", "1/1048577", "99999999999/3", "1:3"})
        EXPECT_FALSE(parse_shard(bad).has_value()) << '"' << bad << '"';
}

RenderIdentity identity() { return test::render_identity_of_size(37, 21); }

// A film whose values need all 64 bits: thirds, a denormal, a negative zero; weight sums if asked.
RenderState state(bool weighted, uint32_t samples = 4) {
    const int w = identity().width, h = identity().height;
    std::vector<PixelSum> sums(size_t(w * h));
    std::vector<double> weights(weighted ? sums.size() : 0);
    for (size_t i = 0; i < sums.size(); ++i) {
        sums[i] = {double(i) / 3.0, std::ldexp(1.0 + double(i), -1060), -double(i) * 1e300};
        if (weighted) weights[i] = -1.0 / 7.0 + double(i) * 1e-3;
    }
    sums[0][0] = -0.0;
    return RenderState{Film(w, h, std::move(sums), std::move(weights)), samples, 3};
}

PartInfo info(Shard shard, uint32_t target_spp = 4) {
    PartInfo p;
    p.shard = shard;
    p.target_spp = target_spp;
    p.output.tonemap = Tonemap::kReinhard;
    p.output.exposure = 0.25f;
    p.output.transfer = Transfer::kGamma;
    p.output.gamma = 1.8f;
    return p;
}

// The bytes before the part's values: the common header (names of 5, 4 and 11 bytes), ten u32
// and the pixel count.
constexpr size_t kCommonHeaderBytes = 8 + 4 + (4 + 5) + (4 + 4) + (4 + 11) + 8 + 8 + 4 + 4 + 4 + 8;
constexpr size_t kHeaderBytes = kCommonHeaderBytes + 10 * 4 + 8;

TEST(ShardPart, RoundTripIsExactAndHoldsOnlyThePartsPixels) {
    const fs::path dir = temp_dir("round_trip");
    for (bool weighted : {false, true}) {
        const RenderState s = state(weighted);
        for (Shard shard : {Shard{1, 1}, Shard{2, 3}}) {
            const fs::path file = dir / "part.ckpt";
            write_shard_part(file, identity(), info(shard), s);
            const std::string bytes = read_bytes(file);
            size_t pixels = 0;
            for (const Tile& t : shard_tiles(37, 21, shard)) pixels += size_t(t.pixels());
            EXPECT_EQ(bytes[8], 3);
            EXPECT_EQ(bytes.size(), kHeaderBytes + pixels * size_t(s.film.values_per_pixel()) * 8 + 8);
            const ShardPart part = read_shard_part(file);
            EXPECT_EQ(part.identity.content_hash, identity().content_hash);
            EXPECT_EQ(part.info.shard, shard);
            EXPECT_EQ(part.info.target_spp, 4u);
            EXPECT_EQ(part.info.output.tonemap, Tonemap::kReinhard);
            EXPECT_EQ(part.info.output.exposure, 0.25f);
            EXPECT_EQ(part.info.output.transfer, Transfer::kGamma);
            EXPECT_EQ(part.info.output.gamma, 1.8f);
            EXPECT_EQ(part.weighted, weighted);
            EXPECT_EQ(part.values_per_pixel, s.film.values_per_pixel());
            EXPECT_EQ(part.samples_done, 4u);
            EXPECT_EQ(part.dropped_samples, 3u);
            // Put into an empty film: the part's pixels bit for bit, the others untouched.
            Film film(37, 21, weighted);
            put_part_values(part, film);
            std::vector<bool> mine(37 * 21, false);
            for (const Tile& t : shard_tiles(37, 21, shard))
                for (int y = t.y0; y < t.y1; ++y)
                    for (int x = t.x0; x < t.x1; ++x) mine[size_t(y * 37 + x)] = true;
            for (int y = 0; y < 21; ++y)
                for (int x = 0; x < 37; ++x) {
                    const PixelSum expected = mine[size_t(y * 37 + x)] ? s.film.sum(x, y) : PixelSum{0, 0, 0};
                    ASSERT_EQ(std::memcmp(film.sum(x, y).data(), expected.data(), sizeof(PixelSum)), 0) << x << "," << y;
                    if (weighted) {
                        const double w = mine[size_t(y * 37 + x)] ? s.film.weight(x, y) : 0.0;
                        ASSERT_EQ(std::memcmp(&film.weight(x, y), &w, sizeof(double)), 0);
                    }
                }
        }
    }
}

// A film with statistics (adaptive sampling, the variance and spp layers): every value distinct.
RenderState statistics_state() {
    const int w = identity().width, h = identity().height;
    Film film(w, h, false, AovLayers{}, true);
    std::vector<double> values(size_t(w * h) * size_t(film.values_per_pixel()));
    for (size_t i = 0; i < values.size(); ++i) values[i] = double(i) / 3.0;
    film.write_region({0, 0, w, h}, values.data());
    return RenderState{std::move(film), 12, 0};
}

// Parts of films with statistics carry them (film flags bit 1) and the adaptive settings (two u32
// after the output settings), bit for bit; damage to them is a clear error.
TEST(ShardPart, StatisticsAndAdaptiveSettingsRoundTrip) {
    const fs::path dir = temp_dir("statistics");
    const fs::path file = dir / "part.ckpt";
    const RenderState s = statistics_state();
    const Shard shard{2, 3};
    for (std::optional<AdaptiveSettings> adaptive : {std::optional<AdaptiveSettings>{},
                                                     std::optional<AdaptiveSettings>{AdaptiveSettings{0.05f, 8}}}) {
        RenderIdentity id = identity();
        id.adaptive = adaptive;
        write_shard_part(file, id, info(shard, 16), s);
        const std::string bytes = read_bytes(file);
        size_t pixels = 0;
        for (const Tile& t : shard_tiles(37, 21, shard)) pixels += size_t(t.pixels());
        EXPECT_EQ(bytes.size(), kHeaderBytes + 8 + pixels * size_t(s.film.values_per_pixel()) * 8 + 8);
        const ShardPart part = read_shard_part(file);
        EXPECT_TRUE(part.statistics);
        EXPECT_EQ(part.identity.adaptive, adaptive);
        EXPECT_EQ(part.values_per_pixel, s.film.values_per_pixel());
        Film film(37, 21, false, AovLayers{}, true);
        put_part_values(part, film);
        for (const Tile& t : shard_tiles(37, 21, shard)) {
            std::vector<double> expected(size_t(t.pixels()) * size_t(film.values_per_pixel())), got(expected.size());
            s.film.read_region(t.bounds(), expected.data());
            film.read_region(t.bounds(), got.data());
            ASSERT_EQ(std::memcmp(expected.data(), got.data(), expected.size() * sizeof(double)), 0);
        }
    }
    const std::string bytes = read_bytes(file);
    // From the film flags to the pixel count (the rest is as in the parts without statistics).
    for (size_t at = kCommonHeaderBytes + 5 * 4; at < kHeaderBytes + 8; ++at) {
        std::string damaged = bytes;
        damaged[at] = char(damaged[at] ^ (at % 2 == 0 ? 0x01 : 0x80));
        write_bytes(file, damaged);
        EXPECT_EQ(error_of([&] { read_shard_part(file); }).rfind(file.string() + ": ", 0), 0u) << at;
        write_bytes(file, bytes.substr(0, at));
        EXPECT_EQ(error_of([&] { read_shard_part(file); }).rfind(file.string() + ": ", 0), 0u) << at;
    }
}

TEST(ShardPart, PartsAndWholeCheckpointsAreNotMistakenForEachOther) {
    const fs::path dir = temp_dir("mistaken");
    write_shard_part(dir / "part.ckpt", identity(), info(Shard{2, 5}), state(false));
    EXPECT_NE(error_of([&] { read_checkpoint(dir / "part.ckpt"); })
                  .find("part 2 of 5 of a shard render, not a checkpoint of the whole image: resume it with --shard 2/5"),
              std::string::npos);
    write_checkpoint(dir / "whole.ckpt", identity(), state(false));
    EXPECT_NE(error_of([&] { read_shard_part(dir / "whole.ckpt"); })
                  .find("a checkpoint of the whole image, not a shard's part file"),
              std::string::npos);
}

TEST(ShardPart, EveryTruncationIsAClearError) {
    const fs::path dir = temp_dir("truncated");
    const fs::path file = dir / "part.ckpt";
    write_shard_part(file, identity(), info(Shard{2, 3}), state(true));
    const std::string bytes = read_bytes(file);
    for (size_t size = 0; size < bytes.size(); size += size < kHeaderBytes ? 1 : 59) {
        write_bytes(file, bytes.substr(0, size));
        const std::string message = error_of([&] { read_shard_part(file); });
        EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << size << ": " << message;
        if (size >= 8) {
            EXPECT_NE(message.find("truncated"), std::string::npos) << size << ": " << message;
        }
    }
    write_bytes(file, bytes + "x");
    EXPECT_NE(error_of([&] { read_shard_part(file); }).find("1 more than part 2 of 3 of a 37x21 film has"),
              std::string::npos);
    write_bytes(file, "PF\n5 3\n-1.0\n");
    EXPECT_NE(error_of([&] { read_shard_part(file); }).find("not a candela checkpoint"), std::string::npos);
}

TEST(ShardPart, EveryCorruptByteIsAClearError) {
    const fs::path dir = temp_dir("corrupt");
    const fs::path file = dir / "part.ckpt";
    write_shard_part(file, identity(), info(Shard{2, 3}), state(true));
    const std::string bytes = read_bytes(file);
    // One bit of every header byte (the low bit of even bytes, the high bit of odd ones), of every
    // 61st value byte, of every checksum byte: never a crash or a silently wrong part.
    for (size_t at = 0; at < bytes.size(); at += at < kHeaderBytes || at + 8 >= bytes.size() ? 1 : 61) {
        std::string damaged = bytes;
        damaged[at] = char(damaged[at] ^ (at % 2 == 0 ? 0x01 : 0x80));
        write_bytes(file, damaged);
        const std::string message = error_of([&] { read_shard_part(file); });
        EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << at << ": " << message;
    }
}

TEST(ShardPart, HugeClaimedSizeIsRefusedWithoutAllocating) {
    // A header claiming a 32768 x 32768 film: its pixel count no longer fits the file (truncated)
    // or the checksum no longer matches; found before any tile list or film is made.
    const fs::path dir = temp_dir("huge");
    const fs::path file = dir / "part.ckpt";
    write_shard_part(file, identity(), info(Shard{2, 3}), state(false));
    std::string bytes = read_bytes(file);
    const size_t width_at = 8 + 4 + (4 + 5) + (4 + 4) + (4 + 11) + 8 + 8;
    for (size_t i : {width_at, width_at + 4}) {
        bytes[i] = 0;
        bytes[i + 1] = char(0x80);  // 32768
    }
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_shard_part(file); }).find("the checksum does not match"), std::string::npos);
    const size_t pixels_at = kHeaderBytes - 8;
    bytes[pixels_at + 3] = 0x20;  // 2^29 pixels and a few
    write_bytes(file, bytes);
    EXPECT_NE(error_of([&] { read_shard_part(file); }).find("truncated part file"), std::string::npos);
}

// Merging: N parts of state(), written to `dir`, one file per part.
std::vector<fs::path> write_parts(const fs::path& dir, int n, bool weighted = false) {
    std::vector<fs::path> files;
    for (int i = 1; i <= n; ++i) {
        files.push_back(dir / ("part-" + std::to_string(i) + ".ckpt"));
        write_shard_part(files.back(), identity(), info(Shard{i, n}), state(weighted));
    }
    return files;
}

TEST(ShardMerge, PartsInAnyOrderGiveTheWholeFilm) {
    const fs::path dir = temp_dir("whole");
    for (bool weighted : {false, true}) {
        std::vector<fs::path> files = write_parts(dir, 5, weighted);
        std::swap(files[0], files[3]);
        const MergedRender m = merge_shard_parts(files);
        const RenderState s = state(weighted);
        EXPECT_EQ(m.parts, 5);
        EXPECT_EQ(m.state.samples_done, 4u);
        EXPECT_EQ(m.state.dropped_samples, 5u * 3u);
        EXPECT_EQ(m.output.tonemap, Tonemap::kReinhard);
        EXPECT_EQ(m.output.gamma, 1.8f);
        ASSERT_EQ(m.state.film.weighted(), weighted);
        EXPECT_EQ(std::memcmp(m.state.film.sums().data(), s.film.sums().data(), s.film.sums().size() * sizeof(PixelSum)),
                  0);
        EXPECT_EQ(m.state.film.weights(), s.film.weights());
    }
}

// Merging `files` fails with a message starting with `start` and containing `contains`.
void expect_refused(const std::vector<fs::path>& files, const std::string& start, const std::string& contains) {
    const std::string message = error_of([&] { merge_shard_parts(files); });
    EXPECT_EQ(message.rfind(start, 0), 0u) << message;
    EXPECT_NE(message.find(contains), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ShardMerge, PartsOfAnotherRenderAreRefusedNamingBothFiles) {
    const fs::path dir = temp_dir("other_render");
    const std::vector<fs::path> files = write_parts(dir, 3);
    const fs::path odd = dir / "odd.ckpt";
    auto refused_with = [&](const std::function<void(RenderIdentity&, PartInfo&, RenderState&)>& change,
                            const std::string& contains) {
        RenderIdentity id = identity();
        PartInfo p = info(Shard{3, 3});
        RenderState s = state(false);
        change(id, p, s);
        write_shard_part(odd, id, p, s);
        expect_refused({files[0], files[1], odd}, odd.string() + ": ", contains);
    };
    const std::string first = files[0].string();
    refused_with([](RenderIdentity& id, PartInfo&, RenderState&) { id.content_hash ^= 1; },
                 "a part of another scene than " + first);
    refused_with([](RenderIdentity& id, PartInfo&, RenderState&) { id.seed = 7; },
                 "seed 7, but " + first + " has seed 42: parts of different renders cannot be merged");
    refused_with([](RenderIdentity&, PartInfo& p, RenderState& s) { p.target_spp = s.samples_done = 8; },
                 "spp 8, but " + first + " has spp 4");
    refused_with([](RenderIdentity& id, PartInfo&, RenderState&) { id.sampler = "sobol"; },
                 "sampler sobol, but " + first + " has sampler independent");
    refused_with([](RenderIdentity& id, PartInfo&, RenderState&) { id.integrator = "bsdf"; },
                 "integrator bsdf, but " + first + " has integrator path");
    refused_with([](RenderIdentity& id, PartInfo&, RenderState&) { id.candela_version = "0.2.0"; },
                 "candela version 0.2.0, but " + first + " has candela version 0.1.0");
    refused_with([](RenderIdentity&, PartInfo& p, RenderState&) { p.shard = Shard{3, 4}; },
                 "part 3 of 4, but " + first + " is part 1 of 3: parts of different shard counts cannot be merged");
    refused_with([](RenderIdentity&, PartInfo& p, RenderState&) { p.output.gamma = 2.2f; },
                 "other output settings (tonemap, exposure, transfer, gamma) than " + first);
    refused_with([](RenderIdentity&, PartInfo&, RenderState& s) { s = state(true); },
                 "film values per pixel 4, but " + first + " has film values per pixel 3");
    refused_with([](RenderIdentity&, PartInfo&, RenderState& s) { s.samples_done = 6; },
                 "6 spp done, but " + first + " has 4: parts with different sample counts cannot be merged");
}

TEST(ShardMerge, MissingDuplicatedAndIncompletePartsAreRefused) {
    const fs::path dir = temp_dir("missing");
    const std::vector<fs::path> f = write_parts(dir, 5);
    expect_refused({f[0], f[1], f[3], f[4]}, "part 3 of 5 is missing", "");
    expect_refused({f[4], f[1]}, "parts 1, 3, 4 of 5 are missing", "");
    expect_refused({f[0], f[1], f[1], f[2], f[3], f[4]}, f[1].string() + ": given twice", "");
    const fs::path copy = dir / "copy-of-2.ckpt";
    fs::copy_file(f[1], copy);
    expect_refused({f[0], f[1], copy}, copy.string() + ": part 2 of 5 again: " + f[1].string() + " is part 2 too", "");
    const fs::path incomplete = dir / "incomplete.ckpt";
    RenderState s = state(false, 2);
    write_shard_part(incomplete, identity(), info(Shard{4, 5}), s);
    expect_refused({f[0], f[1], f[2], incomplete, f[4]}, incomplete.string() + ": part 4 of 5 is incomplete: 2 of 4 spp done",
                   "finish it with candela render SCENE --shard 4/5 --resume " + incomplete.string());
    expect_refused({}, "no part files to merge", "");
}

TEST(ShardMerge, DamagedFilesAndWholeCheckpointsAreRefusedByName) {
    const fs::path dir = temp_dir("damaged_merge");
    const std::vector<fs::path> f = write_parts(dir, 2);
    const std::string bytes = read_bytes(f[1]);
    const fs::path damaged = dir / "damaged.ckpt";
    write_bytes(damaged, bytes.substr(0, bytes.size() - 100));
    expect_refused({f[0], damaged}, damaged.string() + ": truncated part file", "");
    std::string flipped = bytes;
    flipped[bytes.size() / 2] = char(flipped[bytes.size() / 2] ^ 1);
    write_bytes(damaged, flipped);
    expect_refused({f[0], damaged}, damaged.string() + ": corrupt checkpoint: the checksum does not match", "");
    write_bytes(damaged, "not a checkpoint at all");
    expect_refused({f[0], damaged}, damaged.string() + ": not a candela checkpoint", "");
    write_checkpoint(damaged, identity(), state(false));
    expect_refused({f[0], damaged}, damaged.string() + ": a checkpoint of the whole image, not a shard's part file", "");
    expect_refused({f[0], dir / "absent.ckpt"}, (dir / "absent.ckpt").string() + ": checkpoint not found", "");
}

}  // namespace
}  // namespace candela
