#pragma once
// The light-transport integrators. All three converge to the same image where their estimators
// overlap (path and bsdf everywhere; whitted leaves out indirect diffuse light), which the render
// tests check.
#include "candela/film/sensor.h"
#include "candela/lights/light_set.h"
#include "candela/integrators/integrator.h"
#include "candela/scene/render_settings.h"
#include "candela/spectrum/sampled_wavelengths.h"

namespace candela {

// What the light-transport integrators share: the scene, its accelerator and its lights.
// (Abstract: radiance() stays pure. The constructor is public because derived classes inherit it.)
class TransportIntegrator : public Integrator {
  public:
    TransportIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights);

  protected:
    // One camera sample in the scene's mode: RGB, or (IntegratorSettings::spectral) four
    // wavelengths drawn from the sampler's next number, traced and turned into RGB by the sensor.
    // `trace` is the derived integrator's trace<kSpectral>(ray, sampler, counters, wavelengths).
    template <class Trace>
    Rgb in_mode(const Ray& ray, Sampler& sampler, RayCounters& counters, Trace&& trace) const {
        if (!spectral_) return sensor_.rgb_to_rgb(to_rgb(trace(std::false_type{}, ray, sampler, counters, nullptr)));
        SampledWavelengths w = SampledWavelengths::sample_visible(sampler.next_float());
        const Color L = trace(std::true_type{}, ray, sampler, counters, &w);
        return sensor_.spectral_to_rgb(L, w);
    }

    // The lights' emission in the mode (lambda: the path's wavelengths when kSpectral).
    template <bool kSpectral>
    Color environment_radiance(const Vec3f& w, const Color* lambda) const {
        if constexpr (kSpectral)
            return lights_.environment_radiance(w, *lambda);
        else
            return lights_.environment_radiance(w);
    }
    // `cache`: the path's emission cache in spectral mode, when the integrator keeps one.
    template <bool kSpectral>
    Color emitted(uint32_t shape_id, const Vec3f& n, const Vec3f& w, const Color* lambda,
                  SpectralEmissionCache* cache = nullptr) const {
        if constexpr (kSpectral)
            return lights_.emitted(shape_id, n, w, *lambda, cache);
        else
            return lights_.emitted(shape_id, n, w);
    }

    const Scene& scene_;
    const Accelerator& accel_;
    const LightSet& lights_;
    bool any_material_uses_choice_ = false;  // some material reads the lobe-choice number
    bool any_interface_ = false;             // some material is `interface` (path passes through it)
    bool spectral_ = false;                  // IntegratorSettings::spectral
    Sensor sensor_;                          // the film's (iso, exposure_time, white_balance)
};

// The estimators of the light-transport integrator (IntegratorType path, bsdf and whitted).
enum class Estimator {
    // Unidirectional path tracing with next-event estimation and BSDF sampling, combined by
    // multiple importance sampling (power heuristic); emission counted exactly once. With
    // mis = false it is the GAMES101 estimator: light only by NEE, emission found by BSDF rays
    // ignored after the camera hit (except after delta bounces, which NEE cannot reach).
    kPath,
    // Pure BSDF sampling: light is found only by hitting emitters (smallpt's estimator).
    kBsdf,
    // Whitted-style ray tracing (pbrt-v3's WhittedIntegrator): emission seen directly or through
    // perfect specular chains, direct light at non-delta surfaces, and recursion only through
    // delta lobes (following the one the BSDF samples, which is the unbiased form of branching
    // into both).
    kWhitted,
};

// A light-transport integrator running one estimator. Its trace() is the estimator, written
// once for both modes and defined in the estimator's own file (path_integrator.cpp,
// bsdf_integrator.cpp, whitted_integrator.cpp), which also compiles the class.
template <Estimator kEstimator>
class EstimatorIntegrator final : public TransportIntegrator {
  public:
    using TransportIntegrator::TransportIntegrator;
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    // The radiance along ray: RGB-mode colour, or the values at the wavelengths w (spectral).
    template <bool kSpectral>
    Color trace(const Ray& ray, Sampler& sampler, RayCounters& counters, SampledWavelengths* w) const;
};

template <Estimator kEstimator>
Rgb EstimatorIntegrator<kEstimator>::radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const {
    return in_mode(ray, sampler, counters, [this](auto spectral, const Ray& r, Sampler& s, RayCounters& c,
                                                  SampledWavelengths* w) { return trace<spectral()>(r, s, c, w); });
}

using PathIntegrator = EstimatorIntegrator<Estimator::kPath>;
using BsdfIntegrator = EstimatorIntegrator<Estimator::kBsdf>;
using WhittedIntegrator = EstimatorIntegrator<Estimator::kWhitted>;
extern template class EstimatorIntegrator<Estimator::kPath>;
extern template class EstimatorIntegrator<Estimator::kBsdf>;
extern template class EstimatorIntegrator<Estimator::kWhitted>;

}  // namespace candela
