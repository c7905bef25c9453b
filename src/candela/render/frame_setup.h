#pragma once
// Frame setup: what a render builds from a loaded Scene before its first sample, shared by the
// frame renderer (frame_renderer.h), the pass engine and the render job's files: the accelerator's
// alpha cutouts, the light set, the film's pixels and the empty film.
#include "candela/film/film.h"
#include "candela/film/film_settings.h"
#include "candela/geometry/alpha_cutout.h"

namespace candela {

struct Scene;
class Accelerator;
class LightSet;

// Each shape's alpha (its material's) for the accelerator's cutouts, reading scene.textures.
AlphaCutouts alpha_cutouts(const Scene& scene);

// The scene's lights: its emitting shapes and its environment, selected as the integrator settings
// say. `accel` (built over the same scene) gives the scene's size for the environment's power.
LightSet build_light_set(const Scene& scene, const Accelerator& accel);

// The pixels of the full image (camera resolution) that a render of `scene` computes and writes:
// the film's crop window.
PixelBounds render_pixel_bounds(const Scene& scene);
// The empty film a render of `scene` starts from: the crop window's size, with weight sums when
// the pixel filter's samples have weights, AOV sums for the scene's AOV layers, and statistics
// (film.h) when `statistics` is true or the scene samples adaptively.
Film make_film(const Scene& scene, bool statistics = false);

}  // namespace candela
