#include "merge_command.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "candela/core/error.h"
#include "candela/film/pixel_statistics.h"
#include "candela/image/image_io.h"
#include "candela/image/image_layers.h"
#include "candela/render/job/shard_merge.h"

namespace fs = std::filesystem;

namespace candela::cli {

CLI::App* add_merge_command(CLI::App& app, MergeArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "merge", "Merge the part files of candela render --shard I/N into the images of the whole render");
    cmd->add_option("parts", args.parts, "Part files, parts 1..N of one render, in any order")->required();
    cmd->add_option("-o,--output", args.outputs,
                    "Output image, format by extension: .exr .pfm .hdr (linear), .png .ppm (tone mapped); "
                    "repeatable (one image per -o)")
        ->required()
        ->expected(1)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    return cmd;
}

int run_merge(const MergeArgs& a) {
    for (const std::string& out : a.outputs)
        if (!is_writable_image_extension(out))
            throw SceneError({}, fmt::format("-o {}: unknown image format \"{}\"; expected one of: .exr, .pfm, .hdr, "
                                             ".png, .ppm",
                                             out, fs::path(out).extension().string()));
    const MergedRender merged = merge_shard_parts(std::vector<fs::path>(a.parts.begin(), a.parts.end()));
    const RenderState& state = merged.state;
    const Image image = state.film.resolve(state.samples_done);
    const std::vector<ImageLayer> layers = state.film.resolve_aovs(state.samples_done);
    for (const std::string& out : a.outputs) write_image_with_layers(out, image, layers, merged.output);
    std::string outs;
    for (const std::string& out : a.outputs) outs += (outs.empty() ? "" : ", ") + out;
    const uint64_t dropped = state.dropped_samples;
    std::string statistics;  // as the render's summary line says it (adaptive_summary)
    if (state.film.has_statistics()) {
        const SppSummary spp = spp_summary(state.film);
        statistics = fmt::format(", relMSE ~{:.3g}, spp mean {:.1f} min {:g} max {:g}", estimated_relmse(state.film),
                                 spp.mean, spp.min, spp.max);
    }
    fmt::print(stderr, "candela: merged {} part{} of a {}x{} render, {} spp, {} integrator, {} sampler, seed {}{}{}; wrote {}\n",
               merged.parts, merged.parts == 1 ? "" : "s", image.width, image.height, state.samples_done,
               merged.identity.integrator, merged.identity.sampler, merged.identity.seed,
               dropped ? fmt::format(", {} NaN/Inf samples dropped", dropped) : "", statistics, outs);
    return 0;
}

}  // namespace candela::cli
