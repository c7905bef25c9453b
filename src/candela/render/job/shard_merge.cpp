#include "candela/render/job/shard_merge.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <system_error>

#include "candela/core/error.h"
#include "candela/render/adaptive_sampling.h"
#include "candela/render/job/checkpoint_codec.h"
#include "candela/render/job/shard_part.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
using checkpoint_codec::fail;  // the located error the checkpoint and part readers throw

// Throws unless `part` (from `file`) belongs to the same render as `first` (from `first_file`).
void check_same_render(const fs::path& file, const ShardPart& part, const fs::path& first_file,
                       const ShardPart& first) {
    auto differ = [&](const std::string& what, const auto& here, const auto& there) {
        fail(file, fmt::format("{} {}, but {} has {} {}: parts of different renders cannot be merged", what, here,
                               first_file.string(), what, there));
    };
    const RenderIdentity &a = part.identity, &b = first.identity;
    if (a.candela_version != b.candela_version) differ("candela version", a.candela_version, b.candela_version);
    if (part.info.shard.count != first.info.shard.count)
        fail(file, fmt::format("part {} of {}, but {} is part {} of {}: parts of different shard counts cannot be "
                               "merged",
                               part.info.shard.index, part.info.shard.count, first_file.string(),
                               first.info.shard.index, first.info.shard.count));
    if (a.width != b.width || a.height != b.height)
        differ("resolution", fmt::format("{}x{}", a.width, a.height), fmt::format("{}x{}", b.width, b.height));
    if (a.seed != b.seed) differ("seed", a.seed, b.seed);
    if (part.info.target_spp != first.info.target_spp) differ("spp", part.info.target_spp, first.info.target_spp);
    if (a.sampler != b.sampler) differ("sampler", a.sampler, b.sampler);
    if (a.integrator != b.integrator) differ("integrator", a.integrator, b.integrator);
    if (a.adaptive != b.adaptive) {
        auto describe = [](const std::optional<AdaptiveSettings>& s) {
            return s ? fmt::format("threshold {:g}, min_spp {}", s->threshold, s->min_spp) : std::string("off");
        };
        differ("adaptive sampling", describe(a.adaptive), describe(b.adaptive));
    }
    // After the adaptive settings, which the content hash also covers, so that they say what differs.
    if (a.content_hash != b.content_hash)
        fail(file, fmt::format("a part of another scene than {} (content hash {:016x}, there {:016x}: the scene file "
                               "or a file it names differs): parts of different renders cannot be merged",
                               first_file.string(), a.content_hash, b.content_hash));
    if (part.values_per_pixel != first.values_per_pixel || part.weighted != first.weighted ||
        part.statistics != first.statistics || !(part.aovs == first.aovs))
        differ("film values per pixel", part.values_per_pixel, first.values_per_pixel);
    const FilmSettings &o = part.info.output, &p = first.info.output;
    if (o.tonemap != p.tonemap || o.exposure != p.exposure || o.transfer != p.transfer || o.gamma != p.gamma)
        fail(file, fmt::format("other output settings (tonemap, exposure, transfer, gamma) than {}: parts of "
                               "different renders cannot be merged",
                               first_file.string()));
}

bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
}

// "part 3 of 5 is missing", "parts 2, 4 of 5 are missing", at most ten numbers named.
std::string missing_message(const std::vector<int>& missing, int count) {
    if (missing.size() == 1) return fmt::format("part {} of {} is missing", missing[0], count);
    std::string list;
    for (size_t i = 0; i < missing.size() && i < 10; ++i) list += (i == 0 ? "" : ", ") + std::to_string(missing[i]);
    if (missing.size() > 10) list += fmt::format(", ... ({} in all)", missing.size());
    return fmt::format("parts {} of {} are missing", list, count);
}

}  // namespace

MergedRender merge_shard_parts(const std::vector<fs::path>& files) {
    if (files.empty()) throw SceneError({}, "no part files to merge");
    MergedRender merged;
    std::optional<ShardPart> first;
    std::vector<std::optional<fs::path>> given;  // by part index - 1: the file that had it
    for (const fs::path& file : files) {
        ShardPart part = read_shard_part(file);
        const Shard shard = part.info.shard;
        if (!first) {
            merged.identity = part.identity;
            merged.parts = shard.count;
            merged.target_spp = part.info.target_spp;
            merged.output = part.info.output;
            merged.state = RenderState{
                Film(part.identity.width, part.identity.height, part.weighted, part.aovs, part.statistics),
                part.samples_done, 0};
            given.resize(size_t(shard.count));
        } else {
            check_same_render(file, part, files.front(), *first);
        }
        if (const std::optional<fs::path>& earlier = given[size_t(shard.index - 1)]) {
            if (same_file(*earlier, file)) fail(file, "given twice: each part may be merged only once");
            fail(file, fmt::format("part {} of {} again: {} is part {} too (each part may be merged only once)",
                                   shard.index, shard.count, earlier->string(), shard.index));
        }
        const std::optional<AdaptiveSettings>& adaptive = part.identity.adaptive;
        if (!adaptive && part.samples_done != merged.state.samples_done && part.samples_done >= part.info.target_spp)
            fail(file, fmt::format("{} spp done, but {} has {}: parts with different sample counts cannot be merged "
                                   "(render them with the same --spp)",
                                   part.samples_done, files.front().string(), merged.state.samples_done));
        put_part_values(part, merged.state.film);
        // An adaptive part is complete when it has its spp or every block of it stopped sampling
        // (adaptive_sampling.h): the point where the whole render would stop for its pixels.
        const bool complete =
            part.samples_done >= part.info.target_spp ||
            (adaptive && is_decision_point(part.samples_done, uint32_t(adaptive->min_spp)) &&
             active_pixels(merged.state.film, shard_tiles(merged.identity.width, merged.identity.height, shard),
                           part.samples_done, *adaptive) == 0);
        if (!complete)
            fail(file, fmt::format("part {} of {} is incomplete: {} of {} spp done{}; finish it with candela render "
                                   "SCENE --shard {}/{} --resume {} -o {}",
                                   shard.index, shard.count, part.samples_done, part.info.target_spp,
                                   adaptive ? " and pixels still sampling" : "", shard.index, shard.count,
                                   file.string(), file.string()));
        given[size_t(shard.index - 1)] = file;
        // Adaptive parts end where their own pixels stop; one render of the whole image ends
        // where the last of them does.
        merged.state.samples_done = std::max(merged.state.samples_done, part.samples_done);
        merged.state.dropped_samples += part.dropped_samples;
        if (!first) {
            part.values = {};  // only its header is needed from here on
            first = std::move(part);
        }
    }
    std::vector<int> missing;
    for (size_t i = 0; i < given.size(); ++i)
        if (!given[i]) missing.push_back(int(i) + 1);
    if (!missing.empty()) throw SceneError({}, missing_message(missing, merged.parts));
    return merged;
}

}  // namespace candela
