#pragma once
// Integrators that show one property of the first hit; kept as debugging and AOV tools.
// Rays that escape give black (0) in all of them.
#include "candela/integrators/integrator.h"

namespace candela {

// The shading normal on the shape's front side, mapped from [-1, 1] to [0, 1] per axis so that a
// PNG shows it (0.5 * n + 0.5).
class NormalsIntegrator final : public Integrator {
  public:
    explicit NormalsIntegrator(const Accelerator& accel) : accel_(accel) {}
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    const Accelerator& accel_;
};

// Distance from the camera position to the first hit, in scene units (grey).
class DepthIntegrator final : public Integrator {
  public:
    DepthIntegrator(const Accelerator& accel, float near) : accel_(accel), near_(near) {}
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    const Accelerator& accel_;
    float near_;  // camera rays start this far from the camera
};

// The first hit's material colour (material_albedo; a textured material's at the hit).
class AlbedoIntegrator final : public Integrator {
  public:
    AlbedoIntegrator(const Scene& scene, const Accelerator& accel) : scene_(scene), accel_(accel) {}
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    const Scene& scene_;
    const Accelerator& accel_;
};

// Ambient occlusion: the cosine-weighted fraction of the hemisphere on the viewer's side that is
// open up to max_distance, estimated with one cosine-sampled occlusion ray per sample (so the
// estimate is 1 or 0 and its mean is (1/pi) * integral of visibility * cos).
class AoIntegrator final : public Integrator {
  public:
    AoIntegrator(const Accelerator& accel, float max_distance) : accel_(accel), max_distance_(max_distance) {}
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    const Accelerator& accel_;
    float max_distance_;
};

}  // namespace candela
