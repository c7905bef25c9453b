#include "candela/render/job/checkpoint.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/core/error.h"
#include "candela/render/job/checkpoint_codec.h"
#include "candela/render/frame_setup.h"
#include "candela/scene/enum_names.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
using namespace checkpoint_codec;

// "albedo, depth", or "none".
std::string aov_layer_list(uint32_t mask) {
    std::string names;
    for (int l = 0; l < kAovLayerCount; ++l)
        if ((mask >> l) & 1u) names += (names.empty() ? "" : ", ") + std::string(kAovLayerInfo[size_t(l)].name);
    return names.empty() ? "none" : names;
}

}  // namespace

RenderIdentity render_identity(const Scene& scene, uint64_t content_hash) {
    RenderIdentity id;
    id.candela_version = CANDELA_VERSION;
    id.integrator = integrator_type_name(scene.integrator.type);
    id.sampler = sampler_type_name(scene.sampler.type);
    id.content_hash = content_hash;
    id.seed = scene.sampler.seed;
    const PixelBounds bounds = render_pixel_bounds(scene);
    id.width = bounds.width();
    id.height = bounds.height();
    id.aov_layers = scene.film.aovs.mask();
    id.adaptive = scene.sampler.adaptive;
    return id;
}

void write_checkpoint(const fs::path& file, const RenderIdentity& identity, const RenderState& state) {
    const Film& film = state.film;
    RenderIdentity id = identity;
    id.width = film.width();
    id.height = film.height();
    // Other films keep the formats they had before AOVs and statistics existed.
    const bool describes_values = !film.aovs().empty() || film.has_statistics() || identity.adaptive.has_value();
    Writer w;
    write_common_header(w,
                        describes_values ? kFilmValuesFormatVersion
                        : film.weighted() ? kWeightedFormatVersion
                                          : kFormatVersion,
                        id, state.samples_done, state.dropped_samples);
    if (describes_values) {
        w.u32((film.weighted() ? kWeightedFlag : 0u) |
              (film.has_statistics() ? kStatisticsFlag | kStatisticsV2Flag : 0u) |
              (film.aovs().mask() << kAovFlagShift));
        w.u32(identity.adaptive ? uint32_t(identity.adaptive->min_spp) : 0u);
        w.u32(identity.adaptive ? std::bit_cast<uint32_t>(identity.adaptive->threshold) : 0u);
    }
    write_checksummed(file, w, [&](Writer& out, const std::function<void()>& flush) {
        // Row by row, each pixel's values in Film::read_region's order.
        std::vector<double> row(size_t(film.width()) * size_t(film.values_per_pixel()));
        for (int y = 0; y < film.height(); ++y) {
            film.read_region(PixelBounds{0, y, film.width(), y + 1}, row.data());
            for (double v : row) out.f64(v);
            flush();
        }
    });
}

Checkpoint read_checkpoint(const fs::path& file) {
    // The header first: a damaged or foreign file of any size is refused before it is read whole.
    const uint64_t size = file_size_of(file);
    std::string data = read_file_start(file, size, kMaxCommonHeaderBytes + 12);
    Reader r(std::string_view(data).substr(kMagic.size()));
    const CommonHeader h = read_common_header(file, r, size);
    if (h.format == kPartFormatVersion) {
        const uint32_t index = r.u32(), count = r.u32();
        fail(file, r.truncated() ? std::string("a shard's part file (format version 3), not a checkpoint of the whole "
                                               "image: resume it with --shard, or merge it with candela merge")
                                 : fmt::format("part {} of {} of a shard render, not a checkpoint of the whole image: "
                                               "resume it with --shard {}/{}, or merge the parts with candela merge",
                                               index, count, index, count));
    }
    bool weighted = h.format == kWeightedFormatVersion, statistics = false;
    AovLayers aovs;
    std::optional<AdaptiveSettings> adaptive;
    if (h.format == kFilmValuesFormatVersion) {
        const uint32_t values = r.u32(), min_spp = r.u32(), threshold_bits = r.u32();
        const uint32_t aov_mask = values >> kAovFlagShift;
        if (r.truncated()) fail(file, fmt::format("truncated checkpoint: {} bytes, the header alone is longer", size));
        if ((values & ~(kWeightedFlag | kStatisticsFlag | kStatisticsV2Flag |
                        (((1u << kAovLayerCount) - 1u) << kAovFlagShift))) != 0 ||
            (values & kStatisticsV2Flag && !(values & kStatisticsFlag)))
            fail(file, fmt::format("corrupt checkpoint header: film values {:#x}", values));
        weighted = (values & kWeightedFlag) != 0;
        statistics = (values & kStatisticsFlag) != 0;
        if (statistics && !(values & kStatisticsV2Flag))
            fail(file, "a checkpoint of an adaptive or --target-error render by an earlier build of candela, whose "
                       "per-pixel statistics lack the rays and prefix sums that this build's decisions read: it cannot be resumed "
                       "here; render again, or resume it with the build that wrote it");
        for (int l = 0; l < kAovLayerCount; ++l)
            if ((aov_mask >> l) & 1u) aovs.add(AovLayer(l));
        if (min_spp != 0 || threshold_bits != 0) {
            const float threshold = std::bit_cast<float>(threshold_bits);
            if (!statistics || min_spp < 2 || min_spp > (1u << 24) || !(threshold > 0.0f && threshold < 1.0f))
                fail(file, fmt::format("corrupt checkpoint header: adaptive sampling settings {}, {:#x}", min_spp,
                                       threshold_bits));
            adaptive = AdaptiveSettings{threshold, int(min_spp)};
        }
    }
    // Film::values_per_pixel() of the film below, which is allocated only once the size is right.
    const size_t bytes_per_pixel = size_t((weighted ? 4 : 3) + aovs.value_count() + (statistics ? Film::kStatisticsValues : 0)) * 8;
    Checkpoint c;
    c.identity = h.identity;
    c.identity.aov_layers = aovs.mask();
    c.identity.adaptive = adaptive;
    const RenderIdentity& id = c.identity;
    const uint32_t width = uint32_t(id.width), height = uint32_t(id.height), samples = h.samples_done;
    const uint64_t dropped = h.dropped_samples;

    const size_t pixels = size_t(width) * size_t(height);
    const size_t header = kMagic.size() + r.position();
    const size_t expected = header + pixels * bytes_per_pixel + 8;
    if (size < expected)
        fail(file, fmt::format("truncated checkpoint: {} bytes, a {}x{} checkpoint has {}", size, width, height,
                               expected));
    if (size > expected)
        fail(file, fmt::format("corrupt checkpoint: {} bytes, {} more than a {}x{} checkpoint has", size,
                               size - expected, width, height));
    data = read_bytes(file, size);
    check_checksum(file, data);

    Film film(id.width, id.height, weighted, aovs, statistics);
    Reader body(std::string_view(data).substr(header, pixels * bytes_per_pixel));
    const size_t values = size_t(film.values_per_pixel());
    std::vector<double> row(size_t(width) * values);
    for (uint32_t y = 0; y < height; ++y) {
        for (size_t k = 0; k < row.size(); ++k) {
            row[k] = body.f64();
            if (!std::isfinite(row[k]))
                fail(file, fmt::format("corrupt checkpoint: pixel ({}, {}) has a non-finite sum", k / values, y));
        }
        film.write_region(PixelBounds{0, int(y), int(width), int(y) + 1}, row.data());
    }
    c.state = RenderState{std::move(film), samples, dropped};
    return c;
}

void check_checkpoint_matches(const fs::path& file, const RenderIdentity& checkpoint, const RenderIdentity& render) {
    auto refuse = [&](const std::string& what) { fail(file, "cannot resume: " + what); };
    if (checkpoint.candela_version != render.candela_version)
        refuse(fmt::format("the checkpoint was written by candela {}, this is candela {}; another version may "
                           "compute different samples (render again, or resume with candela {})",
                           checkpoint.candela_version, render.candela_version, checkpoint.candela_version));
    if (checkpoint.width != render.width || checkpoint.height != render.height)
        refuse(fmt::format("the checkpoint is {}x{}, this render {}x{} (give the same --resolution)", checkpoint.width,
                           checkpoint.height, render.width, render.height));
    if (checkpoint.seed != render.seed)
        refuse(fmt::format("the checkpoint has seed {}, this render seed {} (give the same --seed)", checkpoint.seed,
                           render.seed));
    if (checkpoint.sampler != render.sampler)
        refuse(fmt::format("the checkpoint used sampler {}, this render {} (give the same --sampler)",
                           checkpoint.sampler, render.sampler));
    if (checkpoint.integrator != render.integrator)
        refuse(fmt::format("the checkpoint used integrator {}, this render {} (give the same --integrator)",
                           checkpoint.integrator, render.integrator));
    if (checkpoint.aov_layers != render.aov_layers)
        refuse(fmt::format("the checkpoint has the AOV layers {}, this render {} (give the same --aov)",
                           aov_layer_list(checkpoint.aov_layers), aov_layer_list(render.aov_layers)));
    if (checkpoint.adaptive != render.adaptive) {
        auto describe = [](const std::optional<AdaptiveSettings>& a) {
            return a ? fmt::format("adaptive sampling with threshold {:g} and min_spp {}", a->threshold, a->min_spp)
                     : std::string("no adaptive sampling");
        };
        refuse(fmt::format("the checkpoint used {}, this render {} (give the same sampler.adaptive, "
                           "--noise-threshold and --min-spp)",
                           describe(checkpoint.adaptive), describe(render.adaptive)));
    }
    if (checkpoint.content_hash != render.content_hash)
        refuse(fmt::format("the checkpoint is of a different scene: its content hash is {:016x}, this scene's {:016x} "
                           "(the scene file or a file it names changed; only the sample count may)",
                           checkpoint.content_hash, render.content_hash));
}

}  // namespace candela
