#include "candela/integrators/path_common.h"
#include "candela/integrators/transport_integrators.h"

namespace candela {

// pbrt-v4's PathIntegrator::Li. At each vertex: emission found
// by the BSDF-sampled ray (MIS-weighted against having sampled the light), then one light sample
// (MIS-weighted against having sampled the BSDF), then the next direction by BSDF sampling.
// An `interface` surface (a boundary between media, which path ignores as pbrt-v4's path does)
// has no BSDF: the ray goes straight through without counting a bounce, and the next emitter it
// finds counts in full, as after a delta bounce (pbrt-v4's SkipIntersection with specularBounce).
template <>
template <bool kSpectral>
Color PathIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters, SampledWavelengths* w) const {
    const Color* lambda = kSpectral ? &w->lambda : nullptr;
    Color L(0.0f), beta(1.0f);
    float eta_scale = 1.0f;  // product of eta^2 over refractions, to undo them for roulette
    Ray ray = camera_ray;
    bool after_delta = false;  // the last bounce was a delta lobe: NEE could not have found the light
    float prev_bsdf_pdf = 0.0f;
    Vec3f prev_p;
    // Spectral mode: the untextured materials' BSDFs and the lights' emission at this path's
    // wavelengths, which do not change along it (spectral_bsdf_cache.h, spectral_emission_cache.h).
    // Plain locals (RGB mode never reads them, and the compiler drops them there), not
    // std::optional, whose default constructor zeroes its whole storage: 1.7 kB per path.
    SpectralBsdfCache bsdf_cache_storage;
    SpectralEmissionCache emission_cache_storage;
    SpectralBsdfCache* bsdf_cache = kSpectral ? &bsdf_cache_storage : nullptr;
    SpectralEmissionCache* emission_cache = kSpectral ? &emission_cache_storage : nullptr;
    int bounces = 0;  // vertices with a BSDF so far; an `interface` crossing is none
    for (int segment = 0;; ++segment) {
        ++(segment == 0 ? counters.camera : counters.bounce);
        // This vertex's random numbers, drawn while the ray is traced (path_common.h).
        const LightNumbers light_numbers = draw_light_numbers(sampler, lights_);
        const BsdfNumbers bsdf_numbers = draw_bsdf_numbers(sampler, any_material_uses_choice_);
        const float roulette_number = draw_roulette_number(sampler, bounces + 1, scene_.integrator);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) {
            // The ray escapes to the environment: the same MIS rule as for hitting an emitter.
            Color Le = environment_radiance<kSpectral>(ray.d, lambda);
            if (bounces == 0 || after_delta)
                L += beta * Le;
            else if (scene_.integrator.mis)
                L += beta * Le * power_heuristic(prev_bsdf_pdf, lights_.environment_pdf(ray.d));
            break;
        }

        Color Le = emitted<kSpectral>(hit->shape_id, hit->ng, -ray.d, lambda, emission_cache);
        if (!Le.is_black()) {
            if (bounces == 0 || after_delta) {
                L += beta * Le;
            } else if (scene_.integrator.mis) {
                float light_pdf = lights_.pdf(prev_p, hit->shape_id, hit->p, hit->ng);
                L += beta * Le * power_heuristic(prev_bsdf_pdf, light_pdf);
            }
            // Without MIS, NEE alone accounts for light reached after a non-delta bounce.
        }
        if (any_interface_ && scene_.materials[scene_.shapes[hit->shape_id].material].interface) {
            ray = spawn_ray(*hit, ray.d);
            after_delta = true;
            continue;
        }
        if (bounces == scene_.integrator.max_depth) break;

        PathVertex v = make_vertex<kSpectral>(scene_, accel_, *hit, ray, w, bsdf_cache);
        L += beta * sample_direct_light<kSpectral>(v, lights_, accel_, scene_.integrator.mis, light_numbers, counters, lambda,
                                                   emission_cache);

        std::optional<BsdfSample> bs = continue_path(v, bsdf_numbers, beta, ray);
        if (!bs) break;
        if (bs->is_transmission) eta_scale *= sqr(bs->eta);
        after_delta = bs->is_delta;
        prev_bsdf_pdf = bs->pdf;
        prev_p = hit->p;
        if (!survive_russian_roulette(beta, eta_scale, bounces + 1, scene_.integrator, roulette_number)) break;
        ++bounces;
    }
    return L;
}

template class EstimatorIntegrator<Estimator::kPath>;

}  // namespace candela
