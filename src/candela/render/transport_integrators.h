#pragma once
// The light-transport integrators. All three converge to the same image where their estimators
// overlap (path and bsdf everywhere; whitted leaves out indirect diffuse light), which the render
// tests check.
#include "candela/lights/light_set.h"
#include "candela/render/integrator.h"
#include "candela/render/render_settings.h"

namespace candela {

// Unidirectional path tracing with next-event estimation and BSDF sampling, combined by multiple
// importance sampling (power heuristic); emission counted exactly once. With mis = false it is
// the GAMES101 estimator: light only by NEE, emission found by BSDF rays ignored after the camera
// hit (except after delta bounces, which NEE cannot reach).
class PathIntegrator final : public Integrator {
  public:
    PathIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights)
        : scene_(scene), accel_(accel), lights_(lights) {}
    Rgb radiance(const Ray& ray, Rng& rng, RayCounters& counters) const override;

  private:
    const Scene& scene_;
    const Accelerator& accel_;
    const LightSet& lights_;
};

// Pure BSDF sampling: light is found only by hitting emitters (smallpt's estimator).
class BsdfIntegrator final : public Integrator {
  public:
    BsdfIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights)
        : scene_(scene), accel_(accel), lights_(lights) {}
    Rgb radiance(const Ray& ray, Rng& rng, RayCounters& counters) const override;

  private:
    const Scene& scene_;
    const Accelerator& accel_;
    const LightSet& lights_;
};

// Whitted-style ray tracing (pbrt-v3's WhittedIntegrator): emission seen directly or through
// perfect specular chains, direct light at non-delta surfaces, and recursion only through delta
// lobes (following the one the BSDF samples, which is the unbiased form of branching into both).
class WhittedIntegrator final : public Integrator {
  public:
    WhittedIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights)
        : scene_(scene), accel_(accel), lights_(lights) {}
    Rgb radiance(const Ray& ray, Rng& rng, RayCounters& counters) const override;

  private:
    const Scene& scene_;
    const Accelerator& accel_;
    const LightSet& lights_;
};

}  // namespace candela
