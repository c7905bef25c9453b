#pragma once
// What every camera sample of a render reads, built once from the scene (accelerator, lights,
// camera, integrator, pixel filter), and the one operation all ways of rendering share: take a
// tile's samples [begin, end). The renderer (renderer.h) runs it over tiles on threads; the MPI
// renderer over tiles handed out to ranks. Since a tile's result depends only on its pixels'
// sums before and the sample range, every way gives the same bits.
#include <cstdint>
#include <memory>
#include <optional>

#include "candela/film/aov_layers.h"
#include "candela/film/film_settings.h"
#include "candela/integrators/ray_counters.h"
#include "candela/render/tile.h"

namespace candela {

struct Scene;
class Film;

// What one thread counts while rendering tiles.
struct TileTally {
    RayCounters rays;
    uint64_t dropped = 0;  // NaN or Inf samples, counted as zero and never written
};

class FrameRenderer {
  public:
    // Builds the accelerator and light tables (the build time is build_seconds()). Throws
    // RenderError when the film's crop window covers no pixel.
    explicit FrameRenderer(const Scene& scene);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    // The film's pixels within the full image (the crop window), its size, and whether it keeps
    // weight sums (the pixel filter's samples have weights).
    PixelBounds bounds() const { return bounds_; }
    int width() const { return bounds_.width(); }
    int height() const { return bounds_.height(); }
    bool weighted() const;
    // The AOV layers the scene asks for (FilmSettings::aovs): films rendered into must keep them.
    AovLayers aovs() const;
    double build_seconds() const { return build_seconds_; }

    // Samples [begin, end) of the tile's pixels: each pixel's sum (and weight sum) is read from
    // `from`, the samples are added in index order, and the result is written to `to`, which may
    // be `from`. Thread-safe for tiles that do not overlap. For films with statistics (film.h)
    // also the sums of squares and counts; with adaptive sampling (adaptive_sampling.h) only the
    // tile's active blocks take samples, the others are copied: then the tile must be aligned to
    // the block size, and no decision point may lie inside (begin, end). Adaptive
    // sampling needs films with statistics. `target_scale`: with --target-error, its allocation's
    // scale at the last decision point (error_allocation.h; blocks decide as with adaptive
    // sampling, and the same conditions hold).
    void render_tile(const Tile& tile, uint32_t begin, uint32_t end, const Film& from, Film& to, TileTally& tally,
                     std::optional<double> target_scale = {}) const;

  private:
    struct Parts;
    std::unique_ptr<Parts> parts_;
    PixelBounds bounds_;
    double build_seconds_ = 0;
};

}  // namespace candela
