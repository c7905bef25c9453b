// `candela render`: load a scene file, render it, write the images (and checkpoints).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "candela/core/atomic_file.h"
#include "candela/core/error.h"
#include "candela/distributed/mpi_launch.h"
#include "candela/image/image_io.h"
#include "candela/image/image_layers.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/progress.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "candela/render/job/shard_part.h"
#include "candela/scene/content_hash.h"
#include "candela/scene/enum_names.h"
#include "candela/formats/scene_file.h"
#include "aov_flag.h"
#include "cli_exit_codes.h"
#include "render_command.h"
#include "stop_signals.h"

#if CANDELA_HAVE_MPI
#include "candela/distributed/mpi_renderer.h"
#include "candela/distributed/mpi_session.h"
#else
namespace candela {
class MpiSession;  // never made without MPI: `mpi` is then always null
}
#endif

namespace fs = std::filesystem;

namespace candela::cli {

namespace {

// The command's start, as near as static initialisation gets: startup times count from here.
const auto kProgramStart = std::chrono::steady_clock::now();

double seconds_since_start() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - kProgramStart).count();
}

// For --stats: scene loading, and the whole time from the command's start to the first sample.
struct StartupTimes {
    double load_seconds = 0;
    double startup_seconds = 0;
};

// The process's peak resident memory so far (Linux reports ru_maxrss in KiB).
uint64_t peak_rss_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return uint64_t(usage.ru_maxrss) * 1024;
}

// A flag value the user got wrong: reported like a scene error, without a file.
[[noreturn]] void bad_flag(const std::string& message) { throw SceneError({}, message); }

// The default output: <scene name>.png in the current folder, where the scene name is the file's
// stem, or its folder's name for the conventional scenes/<name>/scene.json.
fs::path default_output(const fs::path& scene) {
    std::string stem = scene.stem().string();
    if (stem == "scene" && scene.has_parent_path()) stem = fs::absolute(scene).parent_path().filename().string();
    return stem + ".png";
}

// The film's sensor flags, checked as the scene file's film keys are (scene_loader.cpp).
void apply_sensor_overrides(const RenderArgs& a, FilmSettings& film) {
    auto positive_float = [](const char* flag, double v) {
        if (!(v > 0) || !(v <= double(std::numeric_limits<float>::max())))
            bad_flag(fmt::format("{}: expected a number > 0 within float range, got {}", flag, v));
        return float(v);
    };
    if (a.iso) film.iso = positive_float("--iso", *a.iso);
    if (a.exposure_time) film.exposure_time = positive_float("--exposure-time", *a.exposure_time);
    const float ratio = imaging_ratio(film);
    if (!(ratio > 0.0f && std::isfinite(ratio)))
        bad_flag(fmt::format("--iso, --exposure-time: the imaging ratio exposure_time * iso / 100 = {:g} * {:g} / 100 is {}",
                             film.exposure_time, film.iso, ratio > 0.0f ? "beyond float range" : "below float range (0)"));
    if (a.white_balance) {
        const double t = *a.white_balance;
        if (!(t == 0 || (t >= double(kMinWhiteBalanceKelvin) && t <= double(std::numeric_limits<float>::max()))))
            bad_flag(fmt::format("--white-balance: expected 0 (no white balance) or a temperature >= {} (kelvin), got {}",
                                 kMinWhiteBalanceKelvin, t));
        film.white_balance = float(t);
    }
}

// An override that changes the image must also go into scene_content_hash (checkpoints).
void apply_overrides(const RenderArgs& a, Scene& scene) {
    if (a.spp) {
        if (*a.spp < 1) bad_flag(fmt::format("--spp: expected an integer >= 1, got {}", *a.spp));
        scene.sampler.spp = *a.spp;
    }
    if (a.seed) scene.sampler.seed = *a.seed;
    if (a.resolution) {
        std::smatch m;
        static const std::regex kWxH(R"((\d{1,6})x(\d{1,6}))");
        if (!std::regex_match(*a.resolution, m, kWxH))
            bad_flag(fmt::format("--resolution: expected WIDTHxHEIGHT (e.g. 640x480), got \"{}\"", *a.resolution));
        int w = std::stoi(m[1]), h = std::stoi(m[2]);
        if (w < 1 || h < 1 || w > 32768 || h > 32768)
            bad_flag(fmt::format("--resolution: each side must be in 1..32768, got {}x{}", w, h));
        scene.camera.width = w;
        scene.camera.height = h;
    }
    if (a.integrator) {
        std::optional<IntegratorType> t = parse_integrator_type(*a.integrator);
        if (!t)
            bad_flag(fmt::format("--integrator: unknown integrator \"{}\"; expected one of: {}", *a.integrator,
                                 names_list(integrator_type_names())));
        scene.integrator.type = *t;
        // The scene loader refuses the same in a scene file (scene_lights.cpp).
        if (*t == IntegratorType::kBsdf && !scene.delta_lights.empty())
            bad_flag("--integrator bsdf: the bsdf integrator finds light only by hitting it, so it cannot see the "
                     "scene's point, spot or directional lights (they have no area); use path or whitted");
    }
    if (a.spectral && a.rgb) bad_flag("--spectral and --rgb: choose one transport mode");
    if (a.spectral) scene.integrator.spectral = true;
    if (a.rgb) scene.integrator.spectral = false;
    if (a.sampler) {
        std::optional<SamplerType> t = parse_sampler_type(*a.sampler);
        if (!t)
            bad_flag(fmt::format("--sampler: unknown sampler \"{}\"; expected one of: {}", *a.sampler,
                                 names_list(sampler_type_names())));
        scene.sampler.type = *t;
    }
    apply_sensor_overrides(a, scene.film);
    if (a.aov) scene.film.aovs = parse_aov_flag(*a.aov);
    apply_adaptive_overrides(a.adaptive, scene);
}

// Render statistics as JSON, for scripts (bench/run.sh) that should not parse the summary line.
// What an MPI job adds to the statistics (rank 0's view).
struct JobStats {
    int ranks = 1;
    uint64_t bytes_to_rank0 = 0, bytes_from_rank0 = 0;  // MPI messages' payload
};

void write_stats(const fs::path& file, const Scene& scene, const RenderStats& s, const StartupTimes& t,
                 const JobStats& job) {
    std::string json = fmt::format(
        "{{\"integrator\": \"{}\", \"width\": {}, \"height\": {}, \"spp\": {}, \"threads\": {}, \"ranks\": {},\n"
        " \"passes\": {}, \"mpi_bytes_to_rank0\": {}, \"mpi_bytes_from_rank0\": {},\n"
        " \"render_seconds\": {:.6f}, \"build_seconds\": {:.6f}, \"samples\": {}, \"dropped_samples\": {},\n"
        " \"load_seconds\": {:.6f}, \"startup_seconds\": {:.6f}, \"peak_rss_bytes\": {},\n"
        " \"rays\": {{\"camera\": {}, \"bounce\": {}, \"shadow\": {}, \"total\": {}}}}}\n",
        integrator_type_name(scene.integrator.type), scene.camera.width, scene.camera.height, scene.sampler.spp,
        s.threads, job.ranks, s.passes, job.bytes_to_rank0, job.bytes_from_rank0, s.render_seconds, s.build_seconds, s.samples, s.dropped_samples, t.load_seconds,
        t.startup_seconds, peak_rss_bytes(), s.rays.camera, s.rays.bounce, s.rays.shadow, s.rays.total());
    write_contents_atomically(file, json);
}

MemoryLimit memory_limit(const RenderArgs& a) {
    if (!a.memory_limit) return MemoryLimit::of_this_process();
    std::optional<uint64_t> bytes = parse_byte_count(*a.memory_limit);
    if (!bytes) bad_flag(fmt::format("--memory-limit: expected a size such as 512M or 8G, got \"{}\"", *a.memory_limit));
    return MemoryLimit{*bytes, "--memory-limit is"};
}

// The loader checked the scene's memory at its own resolution; --resolution may ask for more, and
// --target-error for the film's statistics.
void check_memory(const RenderArgs& a, const Scene& scene, const MemoryLimit& limit) {
    if (std::optional<std::string> refused = memory_refusal(scene, limit, a.adaptive.target_error.has_value()))
        bad_flag(a.resolution ? fmt::format("--resolution {}: {}", *a.resolution, *refused) : *refused);
}

// A positive, finite number of seconds from a flag.
double seconds_flag(const char* flag, double value) {
    if (!(value > 0) || !std::isfinite(value)) bad_flag(fmt::format("{}: expected seconds > 0, got {}", flag, value));
    return value;
}

// What a stopped render says about why; empty when it is complete.
std::string stop_reason(RenderEnd end, int signal, const RenderArgs& a) {
    if (end == RenderEnd::kStopped) return fmt::format("stopped by {}", signal == SIGTERM ? "SIGTERM" : "SIGINT");
    if (end == RenderEnd::kDeadline)
        return fmt::format("stopped at the time limit ({})", format_duration(*a.time_limit));
    return "";
}

// --shard I/N: the part, after checking the flags that go with it (one -o PART.ckpt, no --checkpoint).
std::optional<Shard> shard_flag(const RenderArgs& a) {
    if (!a.shard) {
        for (const std::string& out : a.outputs)
            if (fs::path(out).extension() == ".ckpt")
                bad_flag(fmt::format("-o {}: a part file (.ckpt) is written only with --shard I/N", out));
        return std::nullopt;
    }
    const std::optional<Shard> shard = parse_shard(*a.shard);
    if (!shard)
        bad_flag(fmt::format("--shard: expected I/N, part I of N with 1 <= I <= N <= {}, got \"{}\"", kMaxShards,
                             *a.shard));
    if (a.outputs.size() != 1 || fs::path(a.outputs.front()).extension() != ".ckpt")
        bad_flag(fmt::format("--shard {}: writes a part file, not images: give one -o PART.ckpt (candela merge writes "
                             "the images from the parts){}",
                             *a.shard, a.outputs.empty() ? "" : fmt::format(", got -o {}", a.outputs.front())));
    if (a.checkpoint) bad_flag(fmt::format("--checkpoint: with --shard the part file (-o {}) is the checkpoint",
                                           a.outputs.front()));
    return shard;
}

// A film of the scene's size has at least N tiles for --shard I/N, so that no part is empty.
void check_shard_fits(const Scene& scene, Shard shard) {
    const PixelBounds film = render_pixel_bounds(scene);
    const int tiles = shard_tile_count(film.width(), film.height());
    if (shard.count > tiles)
        bad_flag(fmt::format("--shard {}/{}: a {}x{} film has {} tile{} of {} pixels, so at most {} part{}",
                             shard.index, shard.count, film.width(), film.height(), tiles, tiles == 1 ? "" : "s",
                             kShardTileSize, tiles, tiles == 1 ? "" : "s"));
}

#if CANDELA_HAVE_MPI
// Every rank must have loaded the same scene (the same files on every host), or their tiles would
// not add up to one image: rank 0 compares the content hashes and ends the job on a difference.
void check_same_scene(const MpiSession& mpi, uint64_t content_hash) {
    const std::vector<uint64_t> hashes = mpi.gather(content_hash);
    for (size_t rank = 1; rank < hashes.size(); ++rank)
        if (hashes[rank] != hashes[0])
            bad_flag(fmt::format("rank {} loaded another scene than rank 0 (content hash {:016x}, rank 0's {:016x}): "
                                 "every rank must read the same scene file and the same files it names",
                                 rank, hashes[rank], hashes[0]));
}
#endif

// The render on this process: alone (`mpi` null), or as one rank of an MPI job, where only rank 0
// reads a checkpoint, prints and writes files, and the other ranks return the job's exit code.
int render_on_this_rank(const RenderArgs& a, const MpiSession* mpi, int rank);

}  // namespace

int run_render(const RenderArgs& a) {
    const std::optional<int> launched = mpi_launch_size();
#if CANDELA_HAVE_MPI
    if (launched && *launched != 1) {
        MpiSession mpi(nullptr, nullptr);
        if (mpi.size() == 1) return render_on_this_rank(a, nullptr, 0);
        // An error on one rank ends the whole job at once, with that rank's message.
        try {
            return render_on_this_rank(a, &mpi, mpi.rank());
        } catch (const SceneError& e) {
            fmt::print(stderr, "candela: error: rank {} of {} ({}): {}\n", mpi.rank(), mpi.size(), mpi.host(), e.what());
            mpi.abort(kExitBadInput);
        } catch (const std::exception& e) {
            fmt::print(stderr, "candela: internal error: rank {} of {} ({}): {}\n", mpi.rank(), mpi.size(), mpi.host(),
                       e.what());
            mpi.abort(kExitInternal);
        }
    }
#else
    if (launched && *launched > 1)
        bad_flag(fmt::format("this candela was built without MPI, so each of the {} processes mpirun started would "
                             "render the whole image; install libopenmpi-dev (scripts/setup.sh does) and build again",
                             *launched));
#endif
    return render_on_this_rank(a, nullptr, 0);
}

namespace {

int render_on_this_rank(const RenderArgs& a, [[maybe_unused]] const MpiSession* mpi, int rank) {
    const bool root = rank == 0;
    using Clock = std::chrono::steady_clock;
    const Clock::time_point started = Clock::now();
    const std::optional<Shard> shard = shard_flag(a);
    std::vector<fs::path> outputs;  // images; none for a shard, whose -o is its part file
    if (!shard) outputs.assign(a.outputs.begin(), a.outputs.end());
    for (const fs::path& out : outputs)
        if (!is_writable_image_extension(out))
            bad_flag(fmt::format("-o {}: unknown image format \"{}\"; expected one of: .exr, .pfm, .hdr, .png, .ppm",
                                 out.string(), out.extension().string()));
    if (a.threads && *a.threads < 0) bad_flag(fmt::format("--threads: expected an integer >= 0, got {}", *a.threads));
    if (a.tile_size && (*a.tile_size < 1 || *a.tile_size > 4096))
        bad_flag(fmt::format("--tile-size: expected an integer in 1..4096, got {}", *a.tile_size));
    if (a.time_limit) seconds_flag("--time-limit", *a.time_limit);
    if (a.checkpoint_every) seconds_flag("--checkpoint-every", *a.checkpoint_every);

    StartupTimes startup;
    const double load_start = seconds_since_start();
    const MemoryLimit limit = memory_limit(a);
    Scene scene = load_scene_file(a.scene, LoadOptions{.memory_limit = limit, .meshes = nullptr, .source_map = {}});
    startup.load_seconds = seconds_since_start() - load_start;
    // The scene's own output name (pbrt-v4's Film "filename"), else one made from the scene's.
    if (outputs.empty() && !shard) {
        fs::path named = scene.output_file.empty() ? default_output(a.scene) : fs::path(scene.output_file);
        if (!is_writable_image_extension(named))
            bad_flag(fmt::format("the scene's output file {} has an image format candela cannot write; give -o",
                                 named.string()));
        outputs.push_back(named);
    }
    const fs::path checkpoint = shard        ? fs::path(a.outputs.front())
                                : a.checkpoint ? fs::path(*a.checkpoint)
                                               : fs::path(outputs.front().string() + ".ckpt");
    if (root)
        for (const std::string& w : scene.warnings) fmt::print(stderr, "candela: warning: {}\n", w);
    apply_overrides(a, scene);
    check_memory(a, scene, limit);
    if (shard) check_shard_fits(scene, *shard);

    // Everything that must match for a checkpoint to continue this render (after the overrides).
    const RenderIdentity identity = render_identity(scene, scene_content_hash(scene));
#if CANDELA_HAVE_MPI
    if (mpi) check_same_scene(*mpi, identity.content_hash);
#endif
    RenderOptions options;
    apply_adaptive_options(a.adaptive, options);
    if (shard) check_target_error_alone(options);
    RenderState start{make_film(scene, needs_statistics(scene, options))};
    // A shard's checkpoints are its part files.
    auto save = [&, part = shard ? part_info(scene, *shard) : PartInfo{}](const RenderState& state) {
        if (shard)
            write_shard_part(checkpoint, identity, part, state);
        else
            write_checkpoint(checkpoint, identity, state);
    };
    if (a.resume && root && shard) {
        const ShardPart resumed = read_shard_part(*a.resume);
        check_part_matches(*a.resume, resumed, identity, *shard, start.film);
        put_part_values(resumed, start.film);
        start.samples_done = resumed.samples_done;
        start.dropped_samples = resumed.dropped_samples;
    } else if (a.resume && root) {
        Checkpoint resumed = read_checkpoint(*a.resume);
        check_checkpoint_matches(*a.resume, resumed.identity, identity);
        check_resumed_statistics(*a.resume, resumed.state.film, scene, options);
        start = std::move(resumed.state);
    }
    if (a.resume && root) {
        const bool nothing_left = start.samples_done >= uint32_t(scene.sampler.spp);
        fmt::print(stderr, "candela: resuming from {}: {} of {} spp done{}\n", *a.resume, start.samples_done,
                   scene.sampler.spp, nothing_left ? ", nothing left to render" : "");
    }

    options.threads = a.threads.value_or(0);
    if (a.tile_size) options.tile_size = *a.tile_size;
    // Under mpirun a rank's stderr is a pipe even on a terminal (and its stdout a pty even into a
    // file), so there the bar is drawn only when asked for.
    options.progress = root && (isatty(fileno(stderr)) != 0 || a.progress);
    options.stop = [] { return cli::stop_signal() != 0; };
    if (shard) options.shard = *shard;
    if (a.time_limit)
        options.deadline = started + std::chrono::duration_cast<Clock::duration>(
                                         std::chrono::duration<double>(*a.time_limit));
    // Checkpoints between passes, every --checkpoint-every seconds; passes short enough for it.
    Clock::time_point last_checkpoint = Clock::now();
    if (a.checkpoint_every) {
        options.pass_seconds = std::min(options.pass_seconds, *a.checkpoint_every);
        options.on_pass = [&](const RenderState& state) {
            if (std::chrono::duration<double>(Clock::now() - last_checkpoint).count() < *a.checkpoint_every) return;
            try {
                save(state);
            } catch (const SceneError& e) {  // the render goes on; the final write reports for good
                fmt::print(stderr, "candela: warning: periodic checkpoint not written: {}\n", e.what());
            }
            last_checkpoint = Clock::now();
        };
    }

    cli::install_stop_handlers();
    startup.startup_seconds = seconds_since_start();
    RenderResult result;
    int stop_signal = cli::stop_signal();
    JobStats job;
#if CANDELA_HAVE_MPI
    if (mpi) {
        MpiRenderOptions mpi_options{options, [] { return cli::stop_signal(); }, {}};
        // Saved before the other ranks are told to stop (one of them may have died: see on_stop).
        mpi_options.on_stop = [&](const RenderState& state) { save(state); };
        MpiRenderResult r = render_mpi(*mpi, scene, mpi_options, std::move(start));
        if (!root) return r.exit_code;
        result = std::move(r.result);
        stop_signal = r.stop_signal;
        job = {r.ranks, r.bytes_received, r.bytes_sent};
    } else
#endif
    {
        result = render(scene, options, std::move(start));
        stop_signal = cli::stop_signal();  // the signal that stopped it, if one did
    }
    startup.startup_seconds += result.stats.build_seconds;  // render() builds, then samples
    const std::string stopped = stop_reason(result.end, stop_signal, a);
    const int exit_code = result.end == RenderEnd::kStopped ? 128 + stop_signal : 0;
    if (result.state.samples_done == 0) {
        // An all-black image would replace a good one of an earlier run: write nothing.
        fmt::print(stderr, "candela: {} before the first pass was complete; nothing written\n", stopped);
        return exit_code;
    }
    // The checkpoint first: it is what a later run needs. Written whenever the render stopped
    // early, and at the end of a render asked for checkpoints (so that it can be taken further).
    const bool write_ckpt = !stopped.empty() || a.checkpoint || a.checkpoint_every || a.resume || shard;
    if (write_ckpt) save(result.state);
    for (const fs::path& out : outputs) write_image_with_layers(out, result.image, result.aov_layers, scene.film);
    if (a.stats) write_stats(*a.stats, scene, result.stats, startup, job);

    const RenderStats& s = result.stats;
    const uint32_t done = result.state.samples_done;
    const std::string spp = done < uint32_t(scene.sampler.spp) ? fmt::format("{} of {}", done, scene.sampler.spp)
                                                                : std::to_string(done);
    std::string outs;
    for (const fs::path& out : outputs) outs += (outs.empty() ? "" : ", ") + out.string();
    if (shard)
        outs = fmt::format("{} (part {} of {})", checkpoint.string(), shard->index, shard->count);
    else if (write_ckpt)
        outs += ", checkpoint " + checkpoint.string();
    const std::string shard_flags = shard ? fmt::format("--shard {}/{} ", shard->index, shard->count) : "";
    if (!stopped.empty())
        outs += fmt::format(" (continue with {}--resume {}{})", shard_flags, checkpoint.string(),
                            shard ? " -o " + checkpoint.string() : "");
    const uint64_t dropped = result.state.dropped_samples;
    const std::string threads =
        job.ranks > 1 ? fmt::format("{} ranks x {} threads", job.ranks, s.threads) : fmt::format("{} threads", s.threads);
    fmt::print(stderr, "candela: {}x{}, {} spp, {} in {} ({} build), {}rays ({}rays/s), {}{}{}; {}wrote {}\n",
               result.image.width, result.image.height, spp, integrator_type_name(scene.integrator.type), format_duration(s.render_seconds),
               format_duration(s.build_seconds), format_count(double(s.rays.total())),
               format_count(s.render_seconds > 0 ? double(s.rays.total()) / s.render_seconds : 0.0), threads,
               dropped ? fmt::format(", {} NaN/Inf samples dropped", dropped) : "", adaptive_summary(result, options.shard),
               stopped.empty() ? "" : stopped + "; ", outs);
    return exit_code;
}

}  // namespace

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
                           "Continue the render saved in this checkpoint up to the scene's (or --spp's) samples");
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
