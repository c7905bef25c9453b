#pragma once
// Volumetric path tracing as pbrt-v4's VolPathIntegrator: the null-scattering path integral of
// Miller, Georgiev and Jarosz (2019). Along each ray inside a medium, distances are drawn by
// delta tracking against the medium's majorant (media/majorant_tracking.h); each drawn point is
// an absorption (the path ends; the medium's emission is counted there), a real scattering (next-
// event estimation, then a new direction from the phase function) or a null collision (the path
// goes on), chosen by the hero channel's probabilities. Shadow rays pass through media and
// `interface` surfaces and are weighted by ratio tracking. Every estimate carries the rescaled
// path probabilities r_u (unidirectional) and r_l (light sampling) of all channels, so the
// channels that did not choose the distances are weighted by spectral MIS (their average), and
// light found by scattering and by NEE is combined by the balance heuristic, as pbrt-v4 does.
//
// The hero channel is spectral mode's hero wavelength (channel 0), and in RGB mode a channel drawn
// per path (each of the three with probability 1/3): fixing it to red would never sample the
// scattering of a medium whose red coefficient is 0.
//
// Subsurface materials (materials/subsurface.h): a path that refracts into one by the tabulated
// method leaves at an exit point found by probe rays (pbrt-v4's BSSRDF sampling, in
// cross_subsurface); by the random walk it enters the material's medium, whose scatterings do not
// count toward max_depth.
//
// A scene without media, `interface` surfaces and tabulated subsurface materials renders with
// the path integrator (make_integrator): the same bits, the same speed. Without next-event estimation (next_event
// false: the `bsdf` integrator on a scene with media) light is found only by scattering into it,
// the estimator that checks volpath's light sampling and shadow rays (tests/integrators/).
#include "candela/integrators/transport_integrators.h"
#include "candela/media/medium.h"

namespace candela {

class VolPathIntegrator final : public TransportIntegrator {
  public:
    VolPathIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights, bool next_event = true);
    Rgb radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const override;

  private:
    template <bool kSpectral>
    Color trace(const Ray& ray, Sampler& sampler, RayCounters& counters, SampledWavelengths* w) const;

    bool next_event_ = true;
};

}  // namespace candela
