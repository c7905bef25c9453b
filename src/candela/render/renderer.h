#pragma once
// The Renderer facade: a loaded Scene in, an Image and statistics out. Builds the accelerator,
// camera and integrator, then renders tiles in parallel with oneTBB.
#include <cstdint>

#include "candela/image/image.h"
#include "candela/render/ray_counters.h"

namespace candela {

struct Scene;
class Accelerator;
class LightSet;

struct RenderOptions {
    int threads = 0;        // 0: all cores
    int tile_size = 16;     // pixels per tile side; does not change the image
    bool progress = false;  // draw a progress bar on stderr
};

struct RenderStats {
    double build_seconds = 0;   // accelerator and light tables
    double render_seconds = 0;  // sampling only
    uint64_t samples = 0;       // camera samples taken
    uint64_t dropped_samples = 0;  // NaN or Inf samples, counted as zero and never written
    RayCounters rays;
    int threads = 0;
};

struct RenderResult {
    Image image;
    RenderStats stats;
};

// The scene's lights: its emitting shapes and its environment, selected as the integrator settings
// say. `accel` (built over the same scene) gives the scene's size for the environment's power.
LightSet build_light_set(const Scene& scene, const Accelerator& accel);

// Renders scene.sampler.spp samples per pixel. The image depends only on the scene (incl. its
// seed), not on threads or tile_size.
RenderResult render(const Scene& scene, const RenderOptions& options);

}  // namespace candela
