#include "candela/integrators/aov_tracer.h"

#include <cmath>

#include "candela/integrators/path_common.h"

namespace candela {

AovTracer::AovTracer(const Scene& scene, const Accelerator& accel)
    : scene_(scene), accel_(accel), camera_space_(scene.film.aov_space == AovSpace::kCamera), frame_(scene.camera) {}

namespace {

// Camera-space coordinates of a world-space vector: its components along the frame's axes (unit
// and perpendicular, so the dot products invert to_world).
Vec3f to_camera(const CameraFrame& f, const Vec3f& v) {
    return Vec3f(dot(v, f.right), dot(v, f.up), dot(v, f.forward));
}

}  // namespace

AovSample AovTracer::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const {
    AovSample aov{Rgb(0.0f), Vec3f(0.0f), kAovMissDepth, Vec3f(0.0f)};
    Ray ray = camera_ray;
    Rgb tint(1.0f);  // the specular chain's f |cos| / pdf so far
    for (int vertex = 0; vertex < kMaxAovSpecularChain; ++vertex) {
        ++counters.bounce;
        const std::optional<SurfaceHit> hit = accel_.intersect(ray);
        if (!hit) break;
        if (vertex == 0) {
            aov.depth = scene_.camera.near + hit->t;
            aov.position = hit->p;
        }
        // RGB mode whatever the integrator's: the albedo layer is an RGB reflectance.
        const PathVertex v(scene_, accel_, *hit, ray);
        if (!v.bsdf.is_delta_only()) {
            aov.albedo = tint * to_rgb(v.bsdf.albedo());
            aov.normal = face_forward(v.frame.n, -ray.d);
            break;
        }
        const float uc = sampler.next_float();
        const Vec2f u = sampler.next_vec2f();
        const std::optional<BsdfSample> bs = v.bsdf.sample(v.wo, uc, u, TransportMode::kRadiance);
        if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) break;
        tint = tint * to_rgb(bs->f * (std::abs(bs->wi.z) / bs->pdf));
        ray = spawn_ray(v.hit, v.frame.to_world(bs->wi));
    }
    if (camera_space_) {
        // A miss keeps its zeros (pbrt-v4 writes 0 where no surface was seen).
        if (aov.depth != kAovMissDepth) aov.position = to_camera(frame_, aov.position - frame_.position);
        aov.normal = to_camera(frame_, aov.normal);
    }
    return aov;
}

}  // namespace candela
