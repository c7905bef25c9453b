#include "candela/integrators/debug_integrators.h"

#include "candela/geometry/accelerator.h"
#include "candela/geometry/ray_offset.h"
#include "candela/math/frame.h"
#include "candela/integrators/material_choice.h"
#include "candela/sampling/warps.h"
#include "candela/scene/scene.h"

namespace candela {

Rgb NormalsIntegrator::radiance(const Ray& ray, Sampler&, RayCounters& counters) const {
    ++counters.camera;
    auto hit = accel_.intersect(ray);
    if (!hit) return Rgb(0.0f);
    Vec3f n = hit->ns * 0.5f + Vec3f(0.5f);
    return {n.x, n.y, n.z};
}

Rgb DepthIntegrator::radiance(const Ray& ray, Sampler&, RayCounters& counters) const {
    ++counters.camera;
    auto hit = accel_.intersect(ray);
    return hit ? Rgb(near_ + hit->t) : Rgb(0.0f);
}

Rgb AlbedoIntegrator::radiance(const Ray& ray, Sampler&, RayCounters& counters) const {
    ++counters.camera;
    auto hit = accel_.intersect(ray);
    if (!hit) return Rgb(0.0f);
    uint32_t mi = scene_.shapes[hit->shape_id].material;
    // A blend shows the part that shades at the hit.
    if (scene_.materials[mi].blend) mi = shading_material_index(scene_, accel_, *hit, ray, mi);
    const Material& m = scene_.materials[mi];
    // A textured material shows its textures at the hit, as it shades there.
    if (m.textured) return to_rgb(build_bsdf(m, scene_.textures, TextureContext{accel_.uv(*hit), hit->p, nullptr, hit->ng}).albedo());
    return to_rgb(material_albedo(m));
}

Rgb AoIntegrator::radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const {
    ++counters.camera;
    auto hit = accel_.intersect(ray);
    if (!hit) return Rgb(0.0f);
    // Occlusion is measured on the side the camera sees, whichever side of the shape that is.
    Vec3f ns = face_forward(hit->ns, -ray.d);
    Vec3f ng = face_forward(hit->ng, ns);
    Vec3f w = Frame::from_normal(ns).to_world(sample_cosine_hemisphere(sampler.next_vec2f()));
    // Directions below the geometric surface (possible where shading normals bend away from it)
    // are blocked by the surface itself.
    if (dot(w, ng) <= 0.0f) return Rgb(0.0f);
    Ray probe = spawn_ray(*hit, w);
    probe.tmax = max_distance_;
    ++counters.shadow;
    return Rgb(accel_.occluded(probe) ? 0.0f : 1.0f);
}

}  // namespace candela
