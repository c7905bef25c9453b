#pragma once
// The light-transport integrators. All three converge to the same image where their estimators
// overlap (path and bsdf everywhere; whitted leaves out indirect diffuse light), which the render
// tests check.
#include "candela/lights/light_set.h"
#include "candela/render/integrator.h"
#include "candela/render/render_settings.h"

namespace candela {

// What the light-transport integrators share: the scene, its accelerator and its lights.
// (Abstract: radiance() stays pure. The constructor is public because derived classes inherit it.)
class TransportIntegrator : public Integrator {
  public:
    TransportIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights);

  protected:
    const Scene& scene_;
    const Accelerator& accel_;
    const LightSet& lights_;
    bool any_material_uses_choice_ = false;  // some material reads the lobe-choice number
};

// Unidirectional path tracing with next-event estimation and BSDF sampling, combined by multiple
// importance sampling (power heuristic); emission counted exactly once. With mis = false it is
// the GAMES101 estimator: light only by NEE, emission found by BSDF rays ignored after the camera
// hit (except after delta bounces, which NEE cannot reach).
class PathIntegrator final : public TransportIntegrator {
  public:
    using TransportIntegrator::TransportIntegrator;
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;
};

// Pure BSDF sampling: light is found only by hitting emitters (smallpt's estimator).
class BsdfIntegrator final : public TransportIntegrator {
  public:
    using TransportIntegrator::TransportIntegrator;
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;
};

// Whitted-style ray tracing (pbrt-v3's WhittedIntegrator): emission seen directly or through
// perfect specular chains, direct light at non-delta surfaces, and recursion only through delta
// lobes (following the one the BSDF samples, which is the unbiased form of branching into both).
class WhittedIntegrator final : public TransportIntegrator {
  public:
    using TransportIntegrator::TransportIntegrator;
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;
};

}  // namespace candela
