#pragma once
// Pieces the light-transport integrators share: the surface a path stands on, MIS weights,
// Russian roulette and next-event estimation.
#include "candela/geometry/accelerator.h"
#include "candela/geometry/ray_offset.h"
#include "candela/lights/light_set.h"
#include "candela/materials/bsdf.h"
#include "candela/materials/material.h"
#include "candela/math/frame.h"
#include "candela/integrators/material_choice.h"
#include "candela/integrators/ray_counters.h"
#include "candela/scene/render_settings.h"
#include "candela/integrators/shading_frame.h"
#include "candela/integrators/spectral_bsdf_cache.h"
#include "candela/sampling/sampler.h"
#include "candela/scene/scene.h"
#include "candela/spectrum/sampled_wavelengths.h"

namespace candela {

// A hit seen from the ray that found it: its BSDF in the shading frame and the outgoing direction.
// An untextured material's BSDF is read in place; a textured one is built here from the texture
// values at the hit (materials/material.h), which needs the hit's surface coordinates. The frame
// is Frame::from_normal(ns) unless the material maps the normal or has anisotropic lobes; those
// ask the accelerator for the surface's parametrization (integrators/shading_frame.h). A blend first
// chooses the part that shades here (integrators/material_choice.h).
struct PathVertex {
    const SurfaceHit& hit;
    const Material* material;  // the material that shades here: the shape's, or a blend's part
    std::optional<Bsdf> textured_bsdf;  // engaged only for textured materials and in spectral mode
    const Bsdf& bsdf;
    Frame frame;  // z = shading normal, on the geometric normal's side
    Vec3f wo;     // towards where the path came from, local

    PathVertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray)
        : PathVertex(scene, accel, h, ray, scene.shapes[h.shape_id].material) {}
    // Spectral mode: the BSDF at the path's wavelengths, built at every hit, or for an untextured
    // material read from the path's `cache` when given (built there at its first hit); a
    // dispersive material first keeps only the hero wavelength of `w`.
    PathVertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray, SampledWavelengths& w,
               SpectralBsdfCache* cache = nullptr)
        : PathVertex(scene, accel, h, ray, resolve_blend(scene, accel, h, ray, scene.shapes[h.shape_id].material), w,
                     cache) {}

  private:
    // One flag per vertex for materials without textures, maps, anisotropy or blends (the Cornell
    // box's): Material::per_hit, tested twice, which the compiler merges on the plain path
    // (+0.07% instructions in the path loop, where testing textured and needs_shading_geometry
    // cost +0.8%: docs/decisions/0012-shading-geometry-on-request.md). A textured, mapped material asks for its uv twice. A
    // blend (per_hit too) replaces `material` by its chosen part in per_hit_bsdf, before the
    // frame is made from it (per_hit_frame takes any material).
    PathVertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray, uint32_t mi)
        : PathVertex(scene, accel, h, ray, scene.materials[mi], mi) {}
    PathVertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray, const Material& m,
               uint32_t mi)
        : hit(h),
          material(&m),
          bsdf(m.per_hit ? per_hit_bsdf(scene, accel, ray, mi) : m.bsdf),
          frame(m.per_hit ? per_hit_frame(scene, accel, *material, h) : Frame::from_normal(h.ns)),
          wo(frame.to_local(-ray.d)) {}

    // `mi`: the material that shades, blends already resolved.
    PathVertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray, uint32_t mi,
               SampledWavelengths& w, SpectralBsdfCache* cache)
        : hit(h),
          material(&scene.materials[mi]),
          bsdf(spectral_bsdf(scene, accel, *material, mi, w, cache)),
          frame(material->per_hit ? per_hit_frame(scene, accel, *material, h) : Frame::from_normal(h.ns)),
          wo(frame.to_local(-ray.d)) {}

    static uint32_t resolve_blend(const Scene& scene, const Accelerator& accel, const SurfaceHit& h, const Ray& ray,
                                  uint32_t mi) {
        return scene.materials[mi].blend ? shading_material_index(scene, accel, h, ray, mi) : mi;
    }
    const Bsdf& spectral_bsdf(const Scene& scene, const Accelerator& accel, const Material& m, uint32_t mi,
                              SampledWavelengths& w, SpectralBsdfCache* cache) {
        if (m.dispersive) w.terminate_secondary();
        if (cache && !m.textured) {
            bool cached = false;
            Bsdf& b = cache->slot(mi, cached);
            if (!cached) build_bsdf_into(b, m, scene.textures, TextureContext{Vec2f(), hit.p, &w.lambda});
            return b;
        }
        const Vec2f uv = m.textured ? accel.uv(hit) : Vec2f();
        Bsdf& b = textured_bsdf.emplace();
        build_bsdf_into(b, m, scene.textures, TextureContext{uv, hit.p, &w.lambda, hit.ng});
        return b;
    }
    const Bsdf& per_hit_bsdf(const Scene& scene, const Accelerator& accel, const Ray& ray, uint32_t mi) {
        if (material->blend) material = &scene.materials[shading_material_index(scene, accel, hit, ray, mi)];
        if (!material->textured) return material->bsdf;
        return textured_bsdf.emplace(build_bsdf(*material, scene.textures, TextureContext{accel.uv(hit), hit.p, nullptr, hit.ng}));
    }
    // Out of line, so that the maps' code stays out of the integrators' loops.
    [[gnu::noinline]] static Frame per_hit_frame(const Scene& scene, const Accelerator& accel, const Material& m,
                                                 const SurfaceHit& h) {
        if (!m.needs_shading_geometry) return Frame::from_normal(h.ns);
        return shading_frame(m, scene.textures, accel.shading(h), h);
    }
};

// Veach's power heuristic with beta = 2 (one sample from each strategy).
inline float power_heuristic(float pdf_a, float pdf_b) {
    float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// The random numbers of a vertex, drawn before its ray is traced. They do not depend on the hit,
// and a Sobol request is a chain of dependent multiplies (sampler.h): drawn first, the CPU works
// them out while Embree traverses, instead of stalling on them after the hit (6% of a Cornell
// box render, bench/RESULTS.md). The requests keep the sampler's fixed order; one a decision cannot need is skipped.

// Next-event estimation: the light choice (skipped with one light), then the point on the light.
struct LightNumbers {
    float uc = 0.0f;
    Vec2f u;
};
inline LightNumbers draw_light_numbers(Sampler& sampler, const LightSet& lights) {
    LightNumbers n;
    if (lights.empty()) {
        sampler.skip_float();
        sampler.skip_vec2f();
        return n;
    }
    if (lights.uses_choice())
        n.uc = sampler.next_float();
    else
        sampler.skip_float();
    n.u = sampler.next_vec2f();
    return n;
}

// BSDF sampling: the lobe choice (skipped when no material of the scene reads it,
// Bsdf::uses_choice), then the direction.
struct BsdfNumbers {
    float uc = 0.0f;
    Vec2f u;
};
inline BsdfNumbers draw_bsdf_numbers(Sampler& sampler, bool any_material_uses_choice) {
    BsdfNumbers n;
    if (any_material_uses_choice)
        n.uc = sampler.next_float();
    else
        sampler.skip_float();
    n.u = sampler.next_vec2f();
    return n;
}

// Russian roulette after bounce number `bounces` (1 = first scattering): skipped for the first
// rr_depth bounces, which are never cut.
inline float draw_roulette_number(Sampler& sampler, int bounces, const IntegratorSettings& s) {
    if (bounces <= s.rr_depth) {
        sampler.skip_float();
        return 0.0f;
    }
    return sampler.next_float();
}

// Russian roulette after the path's bounce number `bounces` (1 = first scattering) with the
// number `u` drawn for it: the first rr_depth bounces are never cut. Returns false when the path
// ends, otherwise divides beta by the survival probability. By default the survival probability
// is the throughput's largest component (with refraction's eta^2 radiance scaling taken out, as
// pbrt-v4 does, so a path inside glass is not killed for being compressed); a fixed probability
// when the settings give one (GAMES101's 0.8).
inline bool survive_russian_roulette(Color& beta, float eta_scale, int bounces, const IntegratorSettings& s, float u) {
    if (bounces <= s.rr_depth) return true;
    float survive = s.rr_probability > 0.0f ? s.rr_probability : std::min(1.0f, (beta * eta_scale).max_component());
    if (survive <= 0.0f || u >= survive) return false;
    beta = beta / survive;
    return true;
}

// One light sample for the vertex, from `n`: f |cos| Le / pdf, weighted by the power heuristic
// against BSDF sampling when `mis`, except for a delta light (point, spot, directional), which BSDF
// sampling cannot find: its weight is 1 (pbrt-v4's PathIntegrator::SampleLd). Counts its shadow
// ray. Black for delta-only BSDFs.
// `lambda`: the path's wavelengths in spectral mode (kSpectral), else unused; `cache`: the path's
// emission cache in spectral mode, when the integrator keeps one.
template <bool kSpectral = false>
inline Color sample_direct_light(const PathVertex& v, const LightSet& lights, const Accelerator& accel, bool mis,
                                 const LightNumbers& n, RayCounters& counters, const Color* lambda = nullptr,
                                 SpectralEmissionCache* cache = nullptr) {
    if (v.bsdf.is_delta_only() || lights.empty()) return Color(0.0f);
    std::optional<LightSample> ls;
    if constexpr (kSpectral)
        ls = lights.sample(v.hit.p, v.frame.n, n.uc, n.u, *lambda, cache);
    else
        ls = lights.sample(v.hit.p, v.frame.n, n.uc, n.u);
    if (!ls || ls->pdf <= 0.0f || ls->Le.is_black()) return Color(0.0f);
    Vec3f wi = v.frame.to_local(ls->wi);
    Color f = v.bsdf.eval(v.wo, wi, TransportMode::kRadiance) * std::abs(wi.z);
    if (f.is_black()) return Color(0.0f);
    ++counters.shadow;
    // Towards the environment or a directional light the shadow ray runs to infinity; towards a
    // surface or a point light it stops short.
    Ray shadow = ls->infinite ? spawn_ray(v.hit, ls->wi) : spawn_ray_to(v.hit, ls->p);
    if (accel.occluded(shadow)) return Color(0.0f);
    float w = mis && !ls->is_delta ? power_heuristic(ls->pdf, v.bsdf.pdf(v.wo, wi)) : 1.0f;
    return f * ls->Le * (w / ls->pdf);
}

// Samples the BSDF with `n` for the path's next direction and moves the path there:
// beta *= f |cos| / pdf and `ray` becomes the spawned ray. Returns the sample, or nullopt when the
// path ends here.
inline std::optional<BsdfSample> continue_path(const PathVertex& v, const BsdfNumbers& n, Color& beta, Ray& ray) {
    std::optional<BsdfSample> bs = v.bsdf.sample(v.wo, n.uc, n.u, TransportMode::kRadiance);
    if (!bs || bs->pdf <= 0.0f || bs->f.is_black()) return std::nullopt;
    beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
    ray = spawn_ray(v.hit, v.frame.to_world(bs->wi));
    return bs;
}

// The vertex at `hit` in the integrator's mode: RGB (w and cache unused) or spectral at the
// wavelengths w, with the path's BSDF cache when the integrator keeps one.
template <bool kSpectral>
PathVertex make_vertex(const Scene& scene, const Accelerator& accel, const SurfaceHit& hit, const Ray& ray,
                       SampledWavelengths* w, SpectralBsdfCache* cache = nullptr) {
    if constexpr (kSpectral)
        return PathVertex(scene, accel, hit, ray, *w, cache);
    else
        return PathVertex(scene, accel, hit, ray);
}

}  // namespace candela
