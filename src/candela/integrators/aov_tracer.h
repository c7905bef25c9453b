#pragma once
// One camera sample's AOV values (film/aov_layers.h), traced beside its radiance. Kept apart from
// the integrators so that a render without AOVs runs exactly the integrators' code, and so that
// every integrator (path, bsdf, whitted, the debug ones) gets the same layers.
//
// Open Image Denoise's convention for its auxiliary images: albedo and normal are those of the
// first vertex that is not perfectly specular. Mirrors and glass are looked through: the tracer
// follows the direction their BSDF samples (at glass, reflection or refraction with the Fresnel
// probability, as the path does) and multiplies the albedo found behind them by the chain's
// sampled weight f |cos| / pdf, the specular tint (1 for clear glass and a white mirror), as
// Cycles' denoising albedo does. Depth and position are the first hit's, through no mirror.
// Position and normal are in world space, or in the camera's (film.aov_space "camera", pbrt-v4's
// GBufferFilm default: x right, y up, z the view direction, origin at the camera).
#include "candela/camera/camera_frame.h"
#include "candela/film/film.h"
#include "candela/integrators/ray_counters.h"
#include "candela/math/ray.h"
#include "candela/sampling/sampler.h"

namespace candela {

class Accelerator;
struct Scene;

class AovTracer {
  public:
    // The arguments must outlive the tracer.
    AovTracer(const Scene& scene, const Accelerator& accel);

    // The AOV values along `camera_ray` (the sample's camera ray, unit direction, starting the
    // camera's `near` along it). Draws from `sampler` only at perfectly specular vertices, after
    // the sample's radiance took its numbers, so the radiance is the same as without AOVs. Counts
    // its rays as bounce rays. On a miss: albedo and normal 0, depth kAovMissDepth, position 0.
    AovSample trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const;

  private:
    const Scene& scene_;
    const Accelerator& accel_;
    bool camera_space_;  // film.aov_space is kCamera
    CameraFrame frame_;  // the camera's, for camera space
};

// The longest chain of perfectly specular vertices followed before giving up (albedo and
// normal then 0, as on a miss).
inline constexpr int kMaxAovSpecularChain = 16;

}  // namespace candela
