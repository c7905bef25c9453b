#include "candela/render/job/job.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "candela/core/error.h"
#include "candela/core/seconds_since.h"
#include "candela/distributed/mpi_launch.h"
#include "candela/formats/scene_file.h"
#include "candela/image/image_io.h"
#include "candela/image/image_layers.h"
#include "candela/render/frame_setup.h"
#include "candela/render/job/checkpoint.h"
#include "candela/render/job/job_files.h"
#include "candela/render/job/shard_part.h"
#include "candela/render/pass_engine.h"
#include "candela/render/renderer.h"
#include "candela/scene/content_hash.h"
#include "candela/scene/enum_names.h"

#if CANDELA_HAVE_MPI
#include "candela/distributed/mpi_renderer.h"
#include "candela/distributed/mpi_session.h"
#endif

namespace candela {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A positive, finite number of seconds.
void check_seconds(const char* flag, const std::optional<double>& value) {
    if (value && (!(*value > 0) || !std::isfinite(*value)))
        bad_flag(fmt::format("{}: expected seconds > 0, got {}", flag, *value));
}

// The options that do not need the scene: outputs, the shard's part file, threads, tiles, times.
void check_options(const RenderJobOptions& o) {
    if (!o.shard) {
        for (const fs::path& out : o.outputs) {
            if (out.extension() == ".ckpt")
                bad_flag(fmt::format("-o {}: a part file (.ckpt) is written only with --shard I/N", out.string()));
            if (!is_writable_image_extension(out))
                bad_flag(fmt::format("-o {}: unknown image format \"{}\"; expected one of: .exr, .pfm, .hdr, .png, .ppm",
                                     out.string(), out.extension().string()));
        }
    } else {
        const Shard s = *o.shard;
        if (s.count < 1 || s.count > kMaxShards || s.index < 1 || s.index > s.count)
            bad_flag(fmt::format("--shard: expected I/N, part I of N with 1 <= I <= N <= {}, got \"{}/{}\"",
                                 kMaxShards, s.index, s.count));
        if (o.outputs.size() != 1 || o.outputs.front().extension() != ".ckpt")
            bad_flag(fmt::format("--shard {}/{}: writes a part file, not images: give one -o PART.ckpt (candela merge "
                                 "writes the images from the parts){}",
                                 s.index, s.count,
                                 o.outputs.empty() ? "" : fmt::format(", got -o {}", o.outputs.front().string())));
        if (o.checkpoint)
            bad_flag(fmt::format("--checkpoint: with --shard the part file (-o {}) is the checkpoint",
                                 o.outputs.front().string()));
    }
    if (o.threads < 0) bad_flag(fmt::format("--threads: expected an integer >= 0, got {}", o.threads));
    if (o.tile_size && (*o.tile_size < 1 || *o.tile_size > 4096))
        bad_flag(fmt::format("--tile-size: expected an integer in 1..4096, got {}", *o.tile_size));
    check_seconds("--time-limit", o.time_limit);
    check_seconds("--checkpoint-every", o.checkpoint_every);
}

// The images to write: the options', else the scene's own output name (pbrt-v4's Film
// "filename"), else <scene name>.png in the current folder, where the scene name is the file's
// stem, or its folder's name for the conventional scenes/<name>/scene.json. None for a shard.
std::vector<fs::path> image_outputs(const RenderJobOptions& o, const Scene& scene) {
    if (o.shard || !o.write_files) return {};
    if (!o.outputs.empty()) return o.outputs;
    fs::path named = scene.output_file;
    if (named.empty()) {
        std::string stem = o.scene.stem().string();
        if (stem == "scene" && o.scene.has_parent_path()) stem = fs::absolute(o.scene).parent_path().filename().string();
        named = stem + ".png";
    }
    if (!is_writable_image_extension(named))
        bad_flag(fmt::format("the scene's output file {} has an image format candela cannot write; give -o",
                             named.string()));
    return {named};
}

// The scene as it renders: overrides (with the resumed file's settings) applied once, then its
// memory checked once, at its final resolution and with what --target-error adds.
void apply_and_check(const RenderJobOptions& o, const RenderOverrides& overrides, const MemoryLimit& limit,
                     Scene& scene) {
    apply_overrides(overrides, scene);
    if (std::optional<std::string> refused = memory_refusal(scene, limit, overrides.target_error.has_value())) {
        if (o.overrides.resolution)
            bad_flag(fmt::format("--resolution {}x{}: {}", o.overrides.resolution->width,
                                 o.overrides.resolution->height, *refused));
        bad_flag(o.resume ? fmt::format("--resume {}: {}", o.resume->string(), *refused) : *refused);
    }
    if (o.shard) {
        const PixelBounds film = render_pixel_bounds(scene);
        const int tiles = shard_tile_count(film.width(), film.height());
        const Shard s = *o.shard;
        if (s.count > tiles)
            bad_flag(fmt::format("--shard {}/{}: a {}x{} film has {} tile{} of {} pixels, so at most {} part{}",
                                 s.index, s.count, film.width(), film.height(), tiles, tiles == 1 ? "" : "s",
                                 kShardTileSize, tiles, tiles == 1 ? "" : "s"));
    }
}

// The render options but for the stop function and the checkpoints.
RenderOptions render_options(const RenderJobOptions& o, bool root) {
    RenderOptions options;
    options.threads = o.threads;
    if (o.tile_size) options.tile_size = *o.tile_size;
    options.progress = root && o.progress;
    if (o.shard) options.shard = *o.shard;
    if (o.time_limit)
        options.deadline =
            o.started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*o.time_limit));
    if (o.overrides.target_error) {
        if (o.shard)
            bad_flag("--target-error does not run with --shard: each part would stop on its own pixels' estimate, "
                     "and the merged image would not meet the target; use --noise-threshold (adaptive sampling, "
                     "which shards and merges bit for bit), or render --target-error in one process or under mpirun");
        options.target_error = *o.overrides.target_error;
    }
    return options;
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

// The job on this process: alone (`mpi` null), or as one rank of an MPI job, where only rank 0
// reads the file to resume, writes files and reports.
RenderJobResult run_on_this_rank(const RenderJobOptions& o, [[maybe_unused]] const MpiSession* mpi, int rank) {
    const bool root = rank == 0;
    check_options(o);
    const MemoryLimit limit = o.memory_limit ? *o.memory_limit : MemoryLimit::of_this_process();
    RenderJobResult out;
    out.root = root;
    const double load_start = seconds_since(o.started);
    // The film is charged once its resolution is final (apply_and_check), when an override or a
    // checkpoint may change it; the loader still guards what it allocates itself.
    const bool resolution_final = !o.overrides.resolution && !o.resume;
    const LoadOptions load_options{
        .memory_limit = limit, .meshes = nullptr, .source_map = {}, .charge_film = resolution_final};
    Scene scene = o.load ? o.load(load_options) : load_scene_file(o.scene, load_options);
    out.load_seconds = seconds_since(o.started) - load_start;
    const std::vector<fs::path> outputs = image_outputs(o, scene);
    out.checkpoint_file = o.shard           ? o.outputs.front()
                          : o.checkpoint    ? *o.checkpoint
                          : outputs.empty() ? fs::path()  // write_files false: no checkpoint
                                            : fs::path(outputs.front().string() + ".ckpt");

    RenderOverrides overrides = o.overrides;
    std::optional<ResumedFile> resumed;
    if (o.resume) {
        if (root) resumed = read_resumed_file(*o.resume, o.shard.has_value());
#if CANDELA_HAVE_MPI
        if (mpi) share_resumed_settings(*mpi, resumed);
#endif
        take_checkpoint_settings(*o.resume, resumed->identity, resumed->target_spp, scene, overrides);
    }
    apply_and_check(o, overrides, limit, scene);
    // The loader's warnings and the overrides' (an --integrator that ignores the scene's media),
    // once the overrides are applied: an --integrator may withdraw the loader's media warning.
    if (root)
        for (const std::string& w : scene.warnings) o.message(JobMessage::kWarning, w);
    // Everything that must match for a checkpoint to continue this render.
    const RenderIdentity identity = render_identity(scene, scene_content_hash(scene));
#if CANDELA_HAVE_MPI
    if (mpi) check_same_scene(*mpi, identity.content_hash);
#endif
    RenderOptions options = render_options(o, root);
    RenderState start = root && resumed ? resumed_state(*o.resume, std::move(*resumed), identity, o.shard, scene, options)
                                        : RenderState{make_film(scene, needs_statistics(scene, options))};
    if (root && o.resume) {
        const bool nothing_left = start.samples_done >= uint32_t(scene.sampler.spp);
        o.message(JobMessage::kInfo, fmt::format("resuming from {}: {} of {} spp done{}", o.resume->string(),
                                                 start.samples_done, scene.sampler.spp,
                                                 nothing_left ? ", nothing left to render" : ""));
    }
    const JobSaver save(out.checkpoint_file, identity, scene, o.shard);
    options.stop = [&o] { return o.stop() != 0; };
    // Checkpoints between passes, every checkpoint_every seconds; passes short enough for it.
    Clock::time_point last_checkpoint = Clock::now();
    if (o.checkpoint_every) options.pass_seconds = std::min(options.pass_seconds, *o.checkpoint_every);
    options.on_pass = [&](const RenderState& state) {
        if (o.write_files && o.checkpoint_every && seconds_since(last_checkpoint) >= *o.checkpoint_every) {
            try {
                save(state);
            } catch (const SceneError& e) {  // the render goes on; the final write reports for good
                o.message(JobMessage::kWarning, fmt::format("periodic checkpoint not written: {}", e.what()));
            }
            last_checkpoint = Clock::now();
        }
        o.on_pass(state);
    };

    o.on_start();
    out.startup_seconds = seconds_since(o.started);
#if CANDELA_HAVE_MPI
    if (mpi) {
        MpiRenderOptions mpi_options{options, o.stop, {}};
        // Saved before the other ranks are told to stop (one of them may have died: see on_stop).
        mpi_options.on_stop = [&](const RenderState& state) { save(state); };
        MpiRenderResult r = render_mpi(*mpi, scene, mpi_options, std::move(start));
        out.exit_code = r.exit_code;
        if (!root) return out;
        out.render = std::move(r.result);
        out.stop_signal = r.stop_signal;
        out.ranks = r.ranks;
        out.bytes_to_rank0 = r.bytes_received;
        out.bytes_from_rank0 = r.bytes_sent;
    } else
#endif
    {
        out.render = render(scene, options, std::move(start));
        out.stop_signal = o.stop();  // what stopped it, if anything did
    }
    out.startup_seconds += out.render.stats.build_seconds;  // render() builds, then samples
    out.exit_code = out.render.end == RenderEnd::kStopped ? 128 + out.stop_signal : 0;
    out.integrator = std::string(integrator_type_name(scene.integrator.type));
    out.width = scene.camera.width;
    out.height = scene.camera.height;
    out.spp = scene.sampler.spp;
    out.shard = o.shard;
    const RenderState& state = out.render.state;
    // An all-black image would replace a good one of an earlier run: nothing is written.
    if (state.samples_done == 0) return out;
    // The checkpoint first: it is what a later run needs. Written whenever the render stopped
    // early, and at the end of a render asked for checkpoints (so that it can be taken further).
    if (o.write_files &&
        (out.render.end != RenderEnd::kComplete || o.checkpoint || o.checkpoint_every || o.resume || o.shard)) {
        save(state);
        out.checkpoint = out.checkpoint_file;
    }
    for (const fs::path& file : outputs) {
        write_image_with_layers(file, out.render.image, out.render.aov_layers, scene.film);
        out.images.push_back(file);
    }
    return out;
}

}  // namespace

RenderJobResult run_render_job(const RenderJobOptions& options, const MpiSession* session) {
#if CANDELA_HAVE_MPI
    if (session) {
        // An error on one rank ends the whole job at once, with that rank's message.
        auto fail = [&](const char* kind, const std::exception& e, int exit_code) {
            options.message(JobMessage::kError, fmt::format("{}: rank {} of {} ({}): {}", kind, session->rank(),
                                                            session->size(), session->host(), e.what()));
            session->abort(exit_code);
        };
        try {
            return run_on_this_rank(options, session, session->rank());
        } catch (const SceneError& e) {
            fail("error", e, 2);
        } catch (const std::exception& e) {
            fail("internal error", e, 1);
        }
    }
#endif
    return run_on_this_rank(options, nullptr, 0);
}

JobRanks::JobRanks() {
    const std::optional<int> launched = mpi_launch_size();
#if CANDELA_HAVE_MPI
    if (launched && *launched != 1) session_ = new MpiSession(nullptr, nullptr);
#else
    if (launched && *launched > 1)
        bad_flag(fmt::format("this candela was built without MPI, so each of the {} processes mpirun started would "
                             "render the whole image; install libopenmpi-dev (scripts/setup.sh does) and build again",
                             *launched));
#endif
}

JobRanks::~JobRanks() {
#if CANDELA_HAVE_MPI
    delete session_;
#endif
}

const MpiSession* JobRanks::session() const {
#if CANDELA_HAVE_MPI
    if (session_ && session_->size() > 1) return session_;
#endif
    return nullptr;
}

}  // namespace candela
