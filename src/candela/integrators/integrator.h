#pragma once
// Integrators turn a camera ray into a value: radiance for light transport, or a per-pixel
// quantity (normal, depth, albedo, occlusion) for the debug integrators. An open, cold set (one
// virtual call per camera sample), so a virtual interface.
#include <memory>

#include "candela/math/ray.h"
#include "candela/math/color.h"
#include "candela/integrators/ray_counters.h"
#include "candela/sampling/sampler.h"

namespace candela {

class Accelerator;
class LightSet;
struct Scene;

class Integrator {
  public:
    virtual ~Integrator() = default;
    // The value carried back along camera_ray (unit direction). Uses only `sampler` for randomness,
    // so a sample is a pure function of its random stream.
    virtual Rgb radiance(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const = 0;
};

// The integrator the scene asks for. The arguments must outlive it.
std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Accelerator& accel, const LightSet& lights);

}  // namespace candela
