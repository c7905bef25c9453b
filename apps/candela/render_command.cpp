// `candela render`: its flags, turned into a render job (render/job/job.h), and the summary line.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <regex>
#include <string>

#include "candela/core/error.h"
#include "candela/render/job/job.h"
#include "candela/render/progress.h"
#include "candela/scene/enum_names.h"
#include "aov_flag.h"
#include "render_command.h"
#include "render_stats.h"
#include "stop_signals.h"

namespace fs = std::filesystem;

namespace candela::cli {

namespace {

// The command's start, as near as static initialisation gets: the time limit and startup times
// count from here.
const auto kProgramStart = std::chrono::steady_clock::now();

// The flags' syntax, into typed values; the job checks the values (job.h, render_overrides.h).
RenderOverrides overrides_of(const RenderArgs& a) {
    RenderOverrides o{.spp = a.spp, .seed = a.seed, .iso = a.iso, .exposure_time = a.exposure_time,
                      .white_balance = a.white_balance, .noise_threshold = a.adaptive.noise_threshold,
                      .min_spp = a.adaptive.min_spp, .target_error = a.adaptive.target_error};
    if (a.resolution) {
        std::smatch m;
        static const std::regex kWxH(R"((\d{1,6})x(\d{1,6}))");
        if (!std::regex_match(*a.resolution, m, kWxH))
            bad_flag(fmt::format("--resolution: expected WIDTHxHEIGHT (e.g. 640x480), got \"{}\"", *a.resolution));
        o.resolution = Resolution{std::stoi(m[1]), std::stoi(m[2])};
    }
    if (a.integrator) o.integrator = integrator_override("--integrator", *a.integrator);
    if (a.sampler) o.sampler = sampler_override("--sampler", *a.sampler);
    if (a.spectral && a.rgb) bad_flag("--spectral and --rgb: choose one transport mode");
    if (a.spectral || a.rgb) o.spectral = a.spectral;
    if (a.aov) o.aovs = parse_aov_flag(*a.aov);
    return o;
}

RenderJobOptions job_options(const RenderArgs& a) {
    RenderJobOptions o{.scene = a.scene, .overrides = overrides_of(a)};
    if (a.memory_limit) {
        const std::optional<uint64_t> bytes = parse_byte_count(*a.memory_limit);
        if (!bytes) bad_flag(fmt::format("--memory-limit: expected a size such as 512M or 8G, got \"{}\"", *a.memory_limit));
        o.memory_limit = MemoryLimit{*bytes, "--memory-limit is"};
    }
    o.outputs.assign(a.outputs.begin(), a.outputs.end());
    o.threads = a.threads.value_or(0);
    o.tile_size = a.tile_size;
    // Under mpirun a rank's stderr is a pipe even on a terminal, so there the bar is drawn only
    // when asked for.
    o.progress = a.progress || isatty(fileno(stderr)) != 0;
    o.time_limit = a.time_limit;
    if (a.checkpoint) o.checkpoint = *a.checkpoint;
    o.checkpoint_every = a.checkpoint_every;
    if (a.resume) o.resume = *a.resume;
    if (a.shard && !(o.shard = parse_shard(*a.shard)))
        bad_flag(fmt::format("--shard: expected I/N, part I of N with 1 <= I <= N <= {}, got \"{}\"", kMaxShards,
                             *a.shard));
    o.stop = [] { return stop_signal(); };
    o.on_start = [] { install_stop_handlers(); };
    o.message = [](JobMessage kind, const std::string& text) {
        fmt::print(stderr, "candela: {}{}\n", kind == JobMessage::kWarning ? "warning: " : "", text);
    };
    o.started = kProgramStart;
    return o;
}

// Why a render stopped early; empty when it is complete.
std::string stop_reason(const RenderJobResult& r, const RenderArgs& a) {
    if (r.render.end == RenderEnd::kStopped)
        return fmt::format("stopped by {}", r.stop_signal == SIGTERM ? "SIGTERM" : "SIGINT");
    if (r.render.end == RenderEnd::kDeadline)
        return fmt::format("stopped at the time limit ({})", format_duration(*a.time_limit));
    return "";
}

// The summary line: size, samples, integrator, times, rays, threads, what was written.
void print_summary(const RenderJobResult& r, const std::string& stopped) {
    const RenderStats& s = r.render.stats;
    const uint32_t done = r.render.state.samples_done;
    const std::string spp = done < uint32_t(r.spp) ? fmt::format("{} of {}", done, r.spp) : std::to_string(done);
    std::string outs;
    for (const fs::path& out : r.images) outs += (outs.empty() ? "" : ", ") + out.string();
    const std::string checkpoint = r.checkpoint_file.string();
    if (r.shard)
        outs = fmt::format("{} (part {} of {})", checkpoint, r.shard->index, r.shard->count);
    else if (r.checkpoint)
        outs += ", checkpoint " + checkpoint;
    if (!stopped.empty())
        outs += fmt::format(" (continue with {}--resume {}{})",
                            r.shard ? fmt::format("--shard {}/{} ", r.shard->index, r.shard->count) : "", checkpoint,
                            r.shard ? " -o " + checkpoint : "");
    const uint64_t dropped = r.render.state.dropped_samples;
    const std::string threads =
        r.ranks > 1 ? fmt::format("{} ranks x {} threads", r.ranks, s.threads) : fmt::format("{} threads", s.threads);
    fmt::print(stderr, "candela: {}x{}, {} spp, {} in {} ({} build), {}rays ({}rays/s), {}{}{}; {}wrote {}\n",
               r.render.image.width, r.render.image.height, spp, r.integrator, format_duration(s.render_seconds),
               format_duration(s.build_seconds), format_count(double(s.rays.total())),
               format_count(s.render_seconds > 0 ? double(s.rays.total()) / s.render_seconds : 0.0), threads,
               dropped ? fmt::format(", {} NaN/Inf samples dropped", dropped) : "",
               adaptive_summary(r.render, r.shard.value_or(Shard{})), stopped.empty() ? "" : stopped + "; ", outs);
}

}  // namespace

int run_render(const RenderArgs& a) {
    const RenderJobOptions options = job_options(a);
    const JobRanks ranks;  // this process alone, or MPI for as long as the result is printed
    const RenderJobResult r = run_render_job(options, ranks.session());
    if (!r.root) return r.exit_code;
    const std::string stopped = stop_reason(r, a);
    if (r.render.state.samples_done == 0) {
        // An all-black image would replace a good one of an earlier run: the job wrote nothing.
        fmt::print(stderr, "candela: {} before the first pass was complete; nothing written\n", stopped);
        return r.exit_code;
    }
    if (a.stats) write_stats(*a.stats, r);
    print_summary(r, stopped);
    return r.exit_code;
}

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file to one or more images");
    cmd->add_option("scene", args.scene, "Scene file (JSON, see docs/SCENE_FORMAT.md)")->required();
    cmd->add_option("-o,--output", args.outputs,
                    "Output image, format by extension: .exr .pfm .hdr (linear), .png .ppm (tone mapped); "
                    "repeatable. Default: <scene name>.png");
    cmd->add_option("--spp", args.spp, "Samples per pixel (overrides sampler.spp)");
    cmd->add_option("--seed", args.seed, "Random seed (overrides sampler.seed)");
    cmd->add_option("--threads", args.threads,
                    "Render threads; 0 = all cores (default; under MPI: per rank, the host's cores shared by its ranks)");
    cmd->add_flag("--progress", args.progress,
                  "Draw the progress bar even when stderr is not a terminal (under mpirun it never is)");
    cmd->add_option("--tile-size", args.tile_size,
                    "Pixels per side of the tiles threads and MPI ranks take (default 16); does not change the image");
    cmd->add_option("--resolution", args.resolution, "Image size WIDTHxHEIGHT (overrides camera.resolution)");
    cmd->add_option("--stats", args.stats, "Also write render statistics (times, samples, rays by kind) as JSON");
    cmd->add_option("--memory-limit", args.memory_limit,
                    "Refuse scenes estimated to need more memory than SIZE (e.g. 8G); default: the "
                    "machine's memory, or less under a container or ulimit limit");
    cmd->add_option("--sampler", args.sampler,
                    std::string("Sampler (overrides sampler.type): ") + names_list(sampler_type_names()));
    cmd->add_option("--integrator", args.integrator,
                    std::string("Integrator (overrides integrator.type): ") + names_list(integrator_type_names()));
    cmd->add_flag("--spectral", args.spectral,
                  "Transport four wavelengths per path, as pbrt-v4 (overrides integrator.spectral)");
    cmd->add_flag("--rgb", args.rgb, "Transport RGB (overrides integrator.spectral; the default for JSON scenes)");
    cmd->add_option("--time-limit", args.time_limit,
                    "Stop rendering after SECONDS (at a pass boundary); write the image and a checkpoint");
    cmd->add_option("--resume", args.resume,
                    "Continue the render saved in this checkpoint up to the scene's (or --spp's) samples, with the "
                    "resolution, seed, sampler, integrator, AOVs and adaptive settings it was rendered with");
    cmd->add_option("--checkpoint", args.checkpoint, "Checkpoint file. Default: the first output + .ckpt");
    cmd->add_option("--checkpoint-every", args.checkpoint_every, "Also write the checkpoint every SECONDS");
    cmd->add_option("--iso", args.iso, "Sensor sensitivity (overrides film.iso; default 100)");
    cmd->add_option("--exposure-time", args.exposure_time,
                    "Sensor exposure time in seconds (overrides film.exposure_time; default 1)");
    cmd->add_option("--white-balance", args.white_balance,
                    "Make daylight of this temperature (kelvin) white; 0 = none (overrides film.white_balance)");
    cmd->add_option("--shard", args.shard,
                    "Render part I of N (I/N, a fixed set of 16-pixel tiles) to a part file -o PART.ckpt; "
                    "candela merge puts the parts together (docs/CLUSTER.md)");
    cmd->add_option("--aov", args.aov,
                    "Also write these layers, comma-separated: albedo, normal, depth, position (overrides film.aovs; "
                    "EXR layers, or files beside other formats)");
    add_adaptive_flags(*cmd, args.adaptive);
    return cmd;
}

}  // namespace candela::cli
