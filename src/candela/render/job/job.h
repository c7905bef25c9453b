#pragma once
// The render job: a scene file and typed options in; the images, checkpoints or part file written,
// and what the caller prints, out. What `candela render` and the Python module (python/) do once
// they have parsed their flags or keywords:
//
//   1. checks the options (messages name the command-line flags);
//   2. reads the checkpoint or part file to resume, and takes the settings it records where the
//      options give none (render_overrides.h; a contradicting one is refused by name);
//   3. loads the scene, applies the overrides once, checks the scene's memory once (at the
//      resolution it renders) and takes its content hash;
//   4. renders, in this process or as one rank of an MPI job (`mpirun candela render`, when built
//      with MPI; CANDELA_HAVE_MPI), stopping when the caller's stop function says so, at the
//      time limit, or complete; writes checkpoints between passes when asked;
//   5. writes the checkpoint (or the part file of a shard) and the images.
//
// The library installs no signal handlers: the caller's stop function reads its own flag, and
// on_start tells the caller when its handlers should take over from the default ones.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "candela/formats/json/scene_loader.h"
#include "candela/render/job/render_overrides.h"
#include "candela/render/render_options.h"
#include "candela/render/shard.h"
#include "candela/scene/memory_budget.h"

namespace candela {

class MpiSession;

// What the job tells its caller while it runs, besides its result.
enum class JobMessage {
    kInfo,     // "resuming from ck.ckpt: 4 of 16 spp done"
    kWarning,  // the scene's warnings, a periodic checkpoint that could not be written
    kError,    // an error on one rank of an MPI job, just before the job ends with it
};

struct RenderJobOptions {
    std::filesystem::path scene = {};
    // Loads the scene in place of reading the file `scene`, with the job's memory limit and film
    // charge (the Python module: a scene document in memory); `scene` still names it. Empty: the
    // file, by its extension (formats/scene_file.h).
    std::function<Scene(const LoadOptions&)> load = {};
    RenderOverrides overrides = {};
    std::optional<MemoryLimit> memory_limit = {};  // default: what this process may have
    // Images, format by extension. None: the scene's own output file (pbrt-v4's Film "filename"),
    // else <scene name>.png in the current folder. With a shard: exactly one, the part file (.ckpt).
    std::vector<std::filesystem::path> outputs = {};
    // False: the job writes no image and no checkpoint, whatever `outputs` and `checkpoint` say;
    // the caller takes the image and its layers from the result (the Python module).
    bool write_files = true;
    int threads = 0;                    // 0: all cores (under MPI: per rank, the host's shared)
    std::optional<int> tile_size = {};  // pixels per tile side, 1..4096; does not change the image
    bool progress = false;              // draw the progress bar on stderr (rank 0 only)
    std::optional<double> time_limit = {};  // seconds from `started`; stops at a pass boundary
    std::optional<std::filesystem::path> checkpoint = {};  // default: the first output + ".ckpt"
    std::optional<double> checkpoint_every = {};  // seconds between checkpoints after passes
    std::optional<std::filesystem::path> resume = {};  // a checkpoint, or with `shard` a part file
    std::optional<Shard> shard = {};  // render part I of N to the part file outputs[0]
    // Nonzero stops the render at once (a pass in flight is abandoned) and is reported back as
    // RenderJobResult::stop_signal; the CLI passes its signal flag (SIGINT, SIGTERM). Called from
    // any render thread: it must be thread-safe.
    std::function<int()> stop = [] { return 0; };
    // Called after each complete pass with the render's state (rank 0's, under MPI), after the
    // periodic checkpoint if one was due: a preview, or a test's hook.
    std::function<void(const RenderState&)> on_pass = [](const RenderState&) {};
    // Called once the scene is loaded and checked, just before the render starts (the CLI installs
    // its signal handlers here, so that a signal while loading still ends the program at once).
    std::function<void()> on_start = [] {};
    std::function<void(JobMessage, const std::string&)> message = [](JobMessage, const std::string&) {};
    // When the job began: the time limit and the startup time count from here.
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};

struct RenderJobResult {
    // False on the other ranks of an MPI job: they write and print nothing; only exit_code counts.
    bool root = true;
    // 128 + stop_signal when the stop function stopped it, else 0.
    int exit_code = 0;
    int stop_signal = 0;  // what the stop function returned (under MPI: of whichever rank), 0 if none
    RenderResult render;  // image, AOV layers, statistics, final state, end (RenderEnd)
    // The scene as rendered (after the overrides and the checkpoint's settings).
    std::string integrator;
    int width = 0, height = 0;  // the camera's resolution (the image is the crop window's part)
    int spp = 0;                // the samples per pixel asked for
    std::optional<Shard> shard = {};
    std::vector<std::filesystem::path> images = {};  // written; none when no pass was complete
    std::optional<std::filesystem::path> checkpoint = {};  // the checkpoint (or part) written, if any
    std::filesystem::path checkpoint_file = {};  // where this render's checkpoints go (to resume)
    double load_seconds = 0;     // reading the scene file and what it names
    double startup_seconds = 0;  // from `started` to the first sample, the frame's build included
    int ranks = 1;
    uint64_t bytes_to_rank0 = 0, bytes_from_rank0 = 0;  // MPI messages' payload, rank 0's view
};

// Where jobs run: this process alone, or, when an MPI launcher (mpirun, srun) started it as one of
// several processes, one rank of an MPI job, with MPI initialised for the object's lifetime. Keep
// it until the result is reported: MPI_Finalize ends what a rank's launcher forwards of its output.
class JobRanks {
  public:
    // Throws SceneError when launched as several processes by a candela built without MPI (each
    // would render the whole image).
    JobRanks();
    ~JobRanks();
    JobRanks(const JobRanks&) = delete;
    JobRanks& operator=(const JobRanks&) = delete;

    // The MPI session of a job of more than one rank, else null.
    const MpiSession* session() const;

  private:
    // Owned; a plain pointer, as the type is complete only with MPI. A launcher's job of one
    // process has a session too (MPI initialised), but renders alone.
    MpiSession* session_ = nullptr;
};

// Runs the job as one rank of `session`'s MPI job, or in this process alone when `session` is
// null. Bad input (scene, flags, checkpoint) throws SceneError; under MPI, an error on a rank is
// reported as a kError message and ends every rank at once (exit code 2 for a SceneError, 1 for
// any other exception).
RenderJobResult run_render_job(const RenderJobOptions& options, const MpiSession* session = nullptr);

}  // namespace candela
