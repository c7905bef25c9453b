#include "candela/render/path_common.h"
#include "candela/render/transport_integrators.h"

namespace candela {

Rgb WhittedIntegrator::radiance(const Ray& camera_ray, Rng& rng, RayCounters& counters) const {
    Rgb L(0.0f), beta(1.0f);
    Ray ray = camera_ray;
    for (int bounces = 0;; ++bounces) {
        ++(bounces == 0 ? counters.camera : counters.bounce);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) break;
        // Seen directly or through delta bounces only (the loop ends at any other bounce).
        L += beta * lights_.emitted(hit->shape_id, hit->ng, -ray.d);
        if (bounces == scene_.integrator.max_depth) break;

        PathVertex v(scene_, *hit, ray);
        L += beta * sample_direct_light(v, lights_, accel_, /*mis=*/false, rng, counters);

        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        std::optional<BsdfSample> bs = v.bsdf.sample(v.wo, uc, u, TransportMode::kRadiance);
        if (!bs || !bs->is_delta || bs->pdf <= 0.0f || bs->f.is_black()) break;
        beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        ray = spawn_ray(*hit, v.frame.to_world(bs->wi));
    }
    return L;
}

}  // namespace candela
