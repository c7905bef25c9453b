#include "candela/render/path_common.h"
#include "candela/render/transport_integrators.h"

namespace candela {

Rgb WhittedIntegrator::radiance(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const {
    Rgb L(0.0f), beta(1.0f);
    Ray ray = camera_ray;
    for (int bounces = 0;; ++bounces) {
        ++(bounces == 0 ? counters.camera : counters.bounce);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) {
            L += beta * lights_.environment_radiance(ray.d);
            break;
        }
        // Seen directly or through delta bounces only (the loop ends at any other bounce).
        L += beta * lights_.emitted(hit->shape_id, hit->ng, -ray.d);
        if (bounces == scene_.integrator.max_depth) break;

        PathVertex v(scene_, *hit, ray);
        L += beta * sample_direct_light(v, lights_, accel_, /*mis=*/false, sampler, counters);

        // Only delta lobes continue the path; a non-delta choice ends it (its light is counted).
        std::optional<BsdfSample> bs = continue_path(v, sampler, beta, ray);
        if (!bs || !bs->is_delta) break;
    }
    return L;
}

}  // namespace candela
