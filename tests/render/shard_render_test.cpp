// Shards rendered for real: parts 1..N, each rendered alone and written to its part file, merge
// into exactly the bits of one render of the whole image (N = 1, 2, 5; a box filter and a
// weighted one; both samplers); and a part stopped after a pass and resumed from its part file
// ends as exactly the uninterrupted part, file byte for byte.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "candela/render/renderer.h"
#include "candela/render/job/shard_merge.h"
#include "candela/render/job/shard_part.h"
#include "support/test_scenes.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) { return test::fresh_dir("shard_render_" + name); }

using test::read_bytes;

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// The two arrays hold the same bits (memcmp may not be given the null data() of an empty vector).
template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_bits(const Film& a, const Film& b) {
    return a.width() == b.width() && a.height() == b.height() && a.weighted() == b.weighted() &&
           same_bytes(a.sums(), b.sums()) && same_bytes(a.weights(), b.weights());
}

// Sides not multiples of the 16-pixel tile: 3 x 2 tiles, the right and bottom ones partial.
Scene scene(bool weighted_filter, SamplerType sampler, bool media = false) {
    Scene s = media ? test::media_small_box_scene(37, 23, 4) : test::lit_small_box_scene(37, 23, 4);
    s.sampler.type = sampler;
    if (weighted_filter) {
        FilterSettings mitchell;
        mitchell.type = FilterType::kMitchell;
        mitchell.radius = {2.0f, 2.0f};
        s.film.filter = mitchell;
    }
    return s;
}

constexpr uint64_t kContentHash = 0x5eed;  // any: the parts of one test share it

TEST(ShardRender, MergedPartsAreTheWholeRenderBitForBit) {
    const fs::path dir = temp_dir("merged");
    struct Case {
        bool weighted;
        SamplerType sampler;
        bool media;
    };
    for (Case c : {Case{false, SamplerType::kIndependent, false}, Case{false, SamplerType::kSobol, false},
                   Case{true, SamplerType::kIndependent, false}, Case{true, SamplerType::kSobol, false},
                   Case{false, SamplerType::kSobol, true}}) {
            const bool weighted = c.weighted;
            const Scene s = scene(weighted, c.sampler, c.media);
            const RenderResult whole = render(s, {.threads = 2});
            ASSERT_EQ(whole.state.film.weighted(), weighted);
            for (int n : {1, 2, 5}) {
                std::vector<fs::path> files;
                for (int i = n; i >= 1; --i) {  // in any order, with any threads
                    RenderOptions options{.threads = 1 + i % 3};
                    options.shard = Shard{i, n};
                    const RenderResult part = render(s, options);
                    files.push_back(dir / ("part-" + std::to_string(i) + ".ckpt"));
                    write_shard_part(files.back(), render_identity(s, kContentHash), part_info(s, options.shard),
                                     part.state);
                }
                const MergedRender merged = merge_shard_parts(files);
                EXPECT_TRUE(same_bits(merged.state.film, whole.state.film)) << n << " parts, weighted " << weighted;
                EXPECT_TRUE(same_bits(merged.state.film.resolve(merged.state.samples_done), whole.image))
                    << n << " parts, weighted " << weighted;
                EXPECT_EQ(merged.state.dropped_samples, whole.state.dropped_samples);
            }
        }
}

TEST(ShardRender, StoppedPartResumedFromItsFileIsTheUninterruptedPart) {
    const fs::path dir = temp_dir("resumed");
    for (bool weighted : {false, true}) {
        const Scene s = scene(weighted, SamplerType::kSobol);
        const Shard shard{2, 3};
        const RenderIdentity id = render_identity(s, kContentHash);
        const PartInfo info = part_info(s, shard);
        RenderOptions whole_options{.threads = 2};
        whole_options.shard = shard;
        write_shard_part(dir / "uninterrupted.ckpt", id, info, render(s, whole_options).state);

        int passes = 0;
        RenderOptions stop_early{.threads = 3};
        stop_early.shard = shard;
        stop_early.pass_spp = 1;
        stop_early.on_pass = [&passes](const RenderState&) { ++passes; };
        stop_early.stop = [&passes] { return passes >= 1; };
        const RenderResult stopped = render(s, stop_early);
        ASSERT_EQ(stopped.end, RenderEnd::kStopped);
        ASSERT_EQ(stopped.state.samples_done, 1u);
        write_shard_part(dir / "stopped.ckpt", id, info, stopped.state);

        const ShardPart part = read_shard_part(dir / "stopped.ckpt");
        check_part_matches(dir / "stopped.ckpt", part, id, shard, make_film(s));
        RenderState start{make_film(s), part.samples_done, part.dropped_samples};
        put_part_values(part, start.film);
        RenderOptions rest{.threads = 1};
        rest.shard = shard;
        write_shard_part(dir / "resumed.ckpt", id, info, render(s, rest, std::move(start)).state);
        const std::string resumed = read_bytes(dir / "resumed.ckpt");
        EXPECT_FALSE(resumed.empty());
        EXPECT_TRUE(resumed == read_bytes(dir / "uninterrupted.ckpt")) << "weighted " << weighted;
    }
}

}  // namespace
}  // namespace candela
