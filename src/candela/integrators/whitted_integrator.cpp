#include "candela/integrators/path_common.h"
#include "candela/integrators/transport_integrators.h"

namespace candela {

template <>
template <bool kSpectral>
Color WhittedIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters, SampledWavelengths* w) const {
    const Color* lambda = kSpectral ? &w->lambda : nullptr;
    Color L(0.0f), beta(1.0f);
    Ray ray = camera_ray;
    for (int bounces = 0;; ++bounces) {
        ++(bounces == 0 ? counters.camera : counters.bounce);
        // This vertex's random numbers, drawn while the ray is traced (path_common.h).
        const LightNumbers light_numbers = draw_light_numbers(sampler, lights_);
        const BsdfNumbers bsdf_numbers = draw_bsdf_numbers(sampler, any_material_uses_choice_);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) {
            L += beta * environment_radiance<kSpectral>(ray.d, lambda);
            break;
        }
        // Seen directly or through delta bounces only (the loop ends at any other bounce).
        L += beta * emitted<kSpectral>(hit->shape_id, hit->ng, -ray.d, lambda);
        if (bounces == scene_.integrator.max_depth) break;

        PathVertex v = make_vertex<kSpectral>(scene_, accel_, *hit, ray, w);
        L += beta * sample_direct_light<kSpectral>(v, lights_, accel_, /*mis=*/false, light_numbers, counters, lambda);

        // Only delta lobes continue the path; a non-delta choice ends it (its light is counted).
        std::optional<BsdfSample> bs = continue_path(v, bsdf_numbers, beta, ray);
        if (!bs || !bs->is_delta) break;
    }
    return L;
}

template class EstimatorIntegrator<Estimator::kWhitted>;

}  // namespace candela
