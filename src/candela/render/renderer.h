#pragma once
// The Renderer facade: a loaded Scene in, an Image and statistics out, in one process. Builds
// the frame (frame_renderer.h: accelerator, camera, integrator) and runs the pass engine
// (pass_engine.h) with each pass's tiles on a oneTBB thread pool.
//
// A pass takes samples [begin, end) of every pixel (sizes: pass_schedule.h). Between passes the
// render can stop, meet a deadline or write a checkpoint; a stop inside a pass abandons it at
// the next tile. Each pixel's samples are summed in index order whatever the passes, so the
// image is bit-identical however a render was split, stopped and resumed.
#include "candela/render/frame_setup.h"
#include "candela/render/render_options.h"

namespace candela {

struct Scene;

// Renders scene.sampler.spp samples per pixel. The image depends only on the scene (incl. its
// seed), not on threads, tile_size or passes.
RenderResult render(const Scene& scene, const RenderOptions& options);

// Continues `start`, a state of the same scene (e.g. read from a checkpoint), up to
// scene.sampler.spp samples per pixel; when it already has as many or more, renders nothing and
// returns it. The result is bit-identical to an uninterrupted render. Throws RenderError when
// start's film is not the scene's resolution, or lacks the statistics that adaptive sampling or a
// target error needs.
RenderResult render(const Scene& scene, const RenderOptions& options, RenderState start);

}  // namespace candela
