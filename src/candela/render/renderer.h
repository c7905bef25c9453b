#pragma once
// The Renderer facade: a loaded Scene in, an Image and statistics out. Builds the accelerator,
// camera and integrator, then renders in passes, each over all tiles in parallel with oneTBB.
//
// A pass takes samples [begin, end) of every pixel (sizes: pass_schedule.h). Between passes the
// render can stop, meet a deadline or write a checkpoint; a stop inside a pass abandons it at
// the next tile. Each pixel's samples are summed in index order whatever the passes, so the
// image is bit-identical however a render was split, stopped and resumed.
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>

#include "candela/geometry/alpha_cutout.h"
#include "candela/image/image.h"
#include "candela/film/film_settings.h"
#include "candela/render/ray_counters.h"
#include "candela/render/render_state.h"
#include "candela/render/shard.h"
#include "candela/render/tile.h"

namespace candela {

struct Scene;
class Accelerator;
class LightSet;

// Every member has a default, so that designated initializers may leave any out.
struct RenderOptions {
    int threads = 0;        // 0: all cores
    int tile_size = 16;     // pixels per tile side; does not change the image
    bool progress = false;  // draw a progress bar on stderr

    // Asked between passes and before each tile, from any render thread (so it must be
    // thread-safe, e.g. read an atomic flag a signal handler sets): true stops the render,
    // abandoning the pass in flight.
    std::function<bool()> stop = {};
    // Stop when reached: passes are sized to end before it, a pass still running then is abandoned.
    std::optional<std::chrono::steady_clock::time_point> deadline = {};
    // Called on the calling thread with the state after each complete pass (periodic checkpoints).
    std::function<void(const RenderState&)> on_pass = {};
    double pass_seconds = 2.0;  // about how long a grown pass lasts
    uint32_t pass_spp = 0;      // > 0: passes of exactly this many samples per pixel (tests)
    // Render only this part of the image (shard.h); the other pixels keep the start state's sums.
    // A part other than 1/1 cuts tiles of kShardTileSize, whatever tile_size says.
    Shard shard = {};
    // > 0: stop at the first decision point (adaptive_sampling.h) where the image's estimated
    // relMSE (film/pixel_statistics.h) is at most this. Needs a film with statistics.
    double target_error = 0.0;
    // Keep per-pixel statistics (film.h) without adaptive sampling or a target, e.g. for the
    // variance and spp outputs (film/pixel_statistics.h: variance_image, spp_image).
    bool statistics = false;
};

// Why render() returned.
enum class RenderEnd {
    kComplete,  // scene.sampler.spp samples per pixel (or more, from the start state)
    kStopped,   // options.stop said so
    kDeadline,  // options.deadline passed
};

struct RenderStats {
    double build_seconds = 0;   // accelerator and light tables
    double render_seconds = 0;  // sampling only
    uint64_t samples = 0;       // camera samples taken in complete passes, in this call (of the shard's pixels)
    uint64_t dropped_samples = 0;  // NaN or Inf samples among them, counted as zero and never written
    RayCounters rays;           // all rays traced, abandoned passes included
    int threads = 0;
    int passes = 0;             // complete passes, in this call
    // Films with statistics: the estimated relMSE of the final image (over the rendered tiles),
    // and whether the render ended because every pixel stopped (adaptive sampling) or the
    // estimate met options.target_error.
    std::optional<double> relmse_estimate;
    bool converged = false;
};

struct RenderResult {
    Image image;        // the mean of state's samples (black when it has none)
    std::vector<ImageLayer> aov_layers;  // the film's AOV layers, resolved like `image`
    RenderStats stats;
    RenderState state;  // the sums after the last complete pass: what a checkpoint saves
    RenderEnd end = RenderEnd::kComplete;
};

// Each shape's alpha (its material's) for the accelerator's cutouts, reading scene.textures.
AlphaCutouts alpha_cutouts(const Scene& scene);

// The scene's lights: its emitting shapes and its environment, selected as the integrator settings
// say. `accel` (built over the same scene) gives the scene's size for the environment's power.
LightSet build_light_set(const Scene& scene, const Accelerator& accel);

// Renders scene.sampler.spp samples per pixel. The image depends only on the scene (incl. its
// seed), not on threads, tile_size or passes.
RenderResult render(const Scene& scene, const RenderOptions& options);

// The pixels of the full image (camera resolution) that a render of `scene` computes and writes:
// the film's crop window.
PixelBounds render_pixel_bounds(const Scene& scene);
// The empty film a render of `scene` starts from: the crop window's size, with weight sums when
// the pixel filter's samples have weights, AOV sums for the scene's AOV layers, and statistics
// (film.h) when `statistics` is true or the scene samples adaptively.
Film make_film(const Scene& scene, bool statistics = false);

// Whether a render of `scene` with `options` needs a film with statistics: adaptive sampling, a
// target error, options.statistics, or the variance or spp AOV layer.
bool needs_statistics(const Scene& scene, const RenderOptions& options);

// The tiles a render of a width x height film with `options` renders: all of them, or those of
// options.shard. `adaptive`: sizes rounded up to a multiple of the adaptive block size.
std::vector<Tile> render_tiles(int width, int height, const RenderOptions& options, bool adaptive = false);

// Continues `start`, a state of the same scene (e.g. read from a checkpoint), up to
// scene.sampler.spp samples per pixel; when it already has as many or more, renders nothing and
// returns it. The result is bit-identical to an uninterrupted render. Throws RenderError when
// start's film is not the scene's resolution, or lacks the statistics that adaptive sampling or a
// target error needs.
RenderResult render(const Scene& scene, const RenderOptions& options, RenderState start);

}  // namespace candela
