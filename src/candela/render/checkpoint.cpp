#include "candela/render/checkpoint.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <string_view>

#include "candela/core/error.h"
#include "candela/render/checkpoint_codec.h"
#include "candela/render/renderer.h"
#include "candela/scene/enum_names.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
using namespace checkpoint_codec;

constexpr size_t kBytesPerPixel = 3 * 8;
constexpr size_t kWeightedBytesPerPixel = 4 * 8;

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
    return id;
}

void write_checkpoint(const fs::path& file, const RenderIdentity& identity, const RenderState& state) {
    const Film& film = state.film;
    RenderIdentity id = identity;
    id.width = film.width();
    id.height = film.height();
    Writer w;
    write_common_header(w, film.weighted() ? kWeightedFormatVersion : kFormatVersion, id, state.samples_done,
                        state.dropped_samples);
    write_checksummed(file, w, [&](Writer& out, const std::function<void()>& flush) {
        for (size_t i = 0; i < film.sums().size(); ++i) {
            for (double v : film.sums()[i]) out.f64(v);
            if (film.weighted()) out.f64(film.weights()[i]);
            flush();
        }
    });
}

Checkpoint read_checkpoint(const fs::path& file) {
    // The header first: a damaged or foreign file of any size is refused before it is read whole.
    const uint64_t size = file_size_of(file);
    std::string data = read_file_start(file, size, kMaxCommonHeaderBytes + 8);
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
    const bool weighted = h.format == kWeightedFormatVersion;
    const size_t bytes_per_pixel = weighted ? kWeightedBytesPerPixel : kBytesPerPixel;
    Checkpoint c;
    c.identity = h.identity;
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

    Reader body(std::string_view(data).substr(header, pixels * bytes_per_pixel));
    std::vector<PixelSum> sums(pixels);
    std::vector<double> weights(weighted ? pixels : 0);
    auto finite = [&](double v, size_t i) {
        if (!std::isfinite(v))
            fail(file, fmt::format("corrupt checkpoint: pixel ({}, {}) has a non-finite sum", i % width, i / width));
        return v;
    };
    for (size_t i = 0; i < pixels; ++i) {
        for (double& v : sums[i]) v = finite(body.f64(), i);
        if (weighted) weights[i] = finite(body.f64(), i);
    }
    c.state = RenderState{Film(id.width, id.height, std::move(sums), std::move(weights)), samples, dropped};
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
    if (checkpoint.content_hash != render.content_hash)
        refuse(fmt::format("the checkpoint is of a different scene: its content hash is {:016x}, this scene's {:016x} "
                           "(the scene file or a file it names changed; only the sample count may)",
                           checkpoint.content_hash, render.content_hash));
}

}  // namespace candela
