#include "candela/integrators/path_common.h"
#include "candela/integrators/transport_integrators.h"

namespace candela {

// smallpt's radiance(): follow BSDF samples and add emission wherever the path lands.
template <>
template <bool kSpectral>
Color BsdfIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters, SampledWavelengths* w) const {
    const Color* lambda = kSpectral ? &w->lambda : nullptr;
    Color L(0.0f), beta(1.0f);
    float eta_scale = 1.0f;
    Ray ray = camera_ray;
    for (int bounces = 0;; ++bounces) {
        ++(bounces == 0 ? counters.camera : counters.bounce);
        // This vertex's random numbers, drawn while the ray is traced (path_common.h).
        const BsdfNumbers bsdf_numbers = draw_bsdf_numbers(sampler, any_material_uses_choice_);
        const float roulette_number = draw_roulette_number(sampler, bounces + 1, scene_.integrator);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) {
            L += beta * environment_radiance<kSpectral>(ray.d, lambda);
            break;
        }
        L += beta * emitted<kSpectral>(hit->shape_id, hit->ng, -ray.d, lambda);
        if (bounces == scene_.integrator.max_depth) break;

        PathVertex v = make_vertex<kSpectral>(scene_, accel_, *hit, ray, w);
        std::optional<BsdfSample> bs = continue_path(v, bsdf_numbers, beta, ray);
        if (!bs) break;
        if (bs->is_transmission) eta_scale *= sqr(bs->eta);
        if (!survive_russian_roulette(beta, eta_scale, bounces + 1, scene_.integrator, roulette_number)) break;
    }
    return L;
}

template class EstimatorIntegrator<Estimator::kBsdf>;

}  // namespace candela
