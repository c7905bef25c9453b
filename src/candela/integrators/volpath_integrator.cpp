#include "candela/integrators/volpath_integrator.h"

#include <bit>
#include <cmath>

#include "candela/core/mix_bits.h"
#include "candela/integrators/path_common.h"
#include "candela/materials/tabulated_bssrdf.h"
#include "candela/media/majorant_tracking.h"
#include "candela/sampling/henyey_greenstein.h"

namespace candela {

namespace {

// What one path carries through media: its channels, which of them chooses distances and events,
// and how many count in spectral MIS's average.
struct PathChannels {
    MediumChannels ch;
    int hero = 0;
    bool spectral = false;

    // pbrt-v4's SampledSpectrum::Average over the channels in use (RGB mode: three; channel 3
    // only repeats red there).
    float average(const Color& c) const { return spectral ? channel_average(c) : (c[0] + c[1] + c[2]) * (1.0f / 3.0f); }
};

// Russian roulette after a scattering (at a surface, as pbrt-v4 does, and in a medium, which
// pbrt-v4 leaves to max_depth): candela's rule (path_common.h) on the throughput divided by the
// average rescaled probability, pbrt-v4's rrBeta.
bool survive_volume_roulette(Color& beta, const Color& r_u, float eta_scale, int depth, const IntegratorSettings& s,
                             const PathChannels& pc, float u) {
    if (depth <= s.rr_depth) return true;
    const float weight = pc.average(r_u);
    if (!(weight > 0.0f)) return false;
    Color rr_beta = beta * (eta_scale / weight);
    float survive = s.rr_probability > 0.0f ? s.rr_probability : std::min(1.0f, rr_beta.max_component());
    if (survive <= 0.0f || u >= survive) return false;
    beta = beta / survive;
    return true;
}

// The most medium events (null collisions included) one path, or one shadow ray, may take: the
// work of a path in a medium far denser than its majorant is bounded (a path that reaches it ends
// there, a bias that no scene short of a pathological grid meets; docs/SCENE_FORMAT.md, "Media").
// A majorant so large that its steps fall below a float's resolution along the ray would
// otherwise never reach the ray's end.
constexpr int kMaxMediumEvents = 1 << 20;

// The medium a ray leaving a surface in direction w travels in: the shape's interior or exterior
// when it is a boundary between media, else the one the path was in (pbrt-v4's
// SurfaceInteraction::SetIntersectionProperties and GetMedium).
uint32_t medium_after(const Shape& shape, const SurfaceHit& hit, const Vec3f& w, uint32_t current) {
    if (!shape.is_medium_boundary()) return current;
    return dot(w, hit.ng) > 0.0f ? shape.exterior : shape.interior;
}

// A generator for one medium walk from two of the sampler's numbers (pbrt-v4 hashes two 1D
// samples into its RNG the same way).
Rng medium_rng(float a, float b) {
    return Rng(mix_bits(std::bit_cast<uint32_t>(a)), mix_bits(uint64_t(std::bit_cast<uint32_t>(b)) ^ 0x9e3779b97f4a7c15ull));
}

}  // namespace

VolPathIntegrator::VolPathIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights,
                                     bool next_event)
    : TransportIntegrator(scene, accel, lights), next_event_(next_event) {}

Rgb VolPathIntegrator::radiance(const Ray& ray, Sampler& sampler, RayCounters& counters) const {
    return in_mode(ray, sampler, counters, [this](auto spectral, const Ray& r, Sampler& s, RayCounters& c,
                                                  SampledWavelengths* w) { return trace<spectral()>(r, s, c, w); });
}

namespace {

// The transport of one path: the integrator's scene and lights, the path's channels, and the
// next-event estimate through media (pbrt-v4's VolPathIntegrator::SampleLd).
template <bool kSpectral>
struct VolumePath {
    const Scene& scene;
    const Accelerator& accel;
    const LightSet& lights;
    const PathChannels pc;
    RayCounters& counters;
    SpectralEmissionCache* emission_cache;
    bool mis;  // IntegratorSettings::mis

    const Color* lambda() const { return pc.ch.lambda; }

    // `p_n`: the surface normal at p, zero in a medium (for LightSelection::kBvh).
    std::optional<LightSample> sample_light(const Vec3f& p, const Vec3f& p_n, const LightNumbers& n) const {
        if constexpr (kSpectral)
            return lights.sample(p, p_n, n.uc, n.u, *pc.ch.lambda, emission_cache);
        else
            return lights.sample(p, p_n, n.uc, n.u);
    }

    // The transmittance from the ray's origin to its end (ray.tmax, or infinity), through media and
    // `interface` surfaces, by ratio tracking; black when an opaque surface is in the way. `r_l` and
    // `r_u` gain the tracking's rescaled probabilities. `target`: the light's point, or nullopt
    // for a light at infinity in direction ray.d.
    Color transmittance(Ray ray, uint32_t medium, const std::optional<Vec3f>& target, Rng& rng, Color& r_l,
                        Color& r_u) const {
        Color T_ray(1.0f);
        int events = 0;
        for (;;) {
            ++counters.shadow;
            std::optional<SurfaceHit> hit = accel.intersect(ray);
            if (hit && !scene.materials[scene.shapes[hit->shape_id].material].interface) return Color(0.0f);
            if (medium != kNoMedium) {
                const float t_max = hit ? hit->t : ray.tmax;
                const Color T_maj = visit(
                    [&](const auto& m) {
                        return sample_majorant_transmittance(
                            m, ray, t_max, rng.next_float(), rng, pc.ch, pc.hero,
                            [&](const Vec3f&, const MediumPoint& mp, const Color& sigma_maj, const Color& T) {
                                // Ratio tracking: each null collision keeps sigma_n / sigma_maj.
                                if (++events > kMaxMediumEvents) {
                                    T_ray = Color(0.0f);
                                    return false;
                                }
                                const Color sigma_n = clamp_channels(sigma_maj - mp.sigma_a - mp.sigma_s, 0.0f, kInfinity);
                                const float pdf = T[pc.hero] * sigma_maj[pc.hero];
                                T_ray *= T * sigma_n / pdf;
                                r_l *= T * sigma_maj / pdf;
                                r_u *= T * sigma_n / pdf;
                                // Russian roulette once the estimate is small (pbrt-v4's 0.05, 0.75).
                                const Color Tr = T_ray / pc.average(r_l + r_u);
                                if (Tr.max_component() < 0.05f) {
                                    if (rng.next_float() < 0.75f)
                                        T_ray = Color(0.0f);
                                    else
                                        T_ray /= 0.25f;
                                }
                                return !T_ray.is_black();
                            });
                    },
                    scene.media[medium]);
                T_ray *= T_maj / T_maj[pc.hero];
                r_l *= T_maj / T_maj[pc.hero];
                r_u *= T_maj / T_maj[pc.hero];
            }
            if (T_ray.is_black() || !T_ray.is_finite()) return Color(0.0f);
            if (!hit) return T_ray;
            // Through the interface, on towards the light.
            medium = medium_after(scene.shapes[hit->shape_id], *hit, ray.d, medium);
            ray = target ? spawn_ray_to(*hit, *target) : spawn_ray(*hit, ray.d);
        }
    }

    // Next-event estimation from a point with scattering function `f(wi)` and its pdf `pdf(wi)`
    // (a BSDF's times |cos|, or the phase function), the shadow ray spawned by `spawn(ls)`, in
    // `medium`: beta f T Le / (average of the rescaled probabilities), pbrt-v4's SampleLd.
    // `medium_of(wi)`: the medium the shadow ray starts in.
    template <class F, class Pdf, class Spawn, class MediumOf>
    Color direct_light(const Vec3f& p, const Vec3f& p_n, const LightNumbers& n, const Color& beta, const Color& r_p, F&& f, Pdf&& pdf,
                       Spawn&& spawn, MediumOf&& medium_of, Rng& rng) const {
        std::optional<LightSample> ls = sample_light(p, p_n, n);
        if (!ls || ls->pdf <= 0.0f || ls->Le.is_black()) return Color(0.0f);
        const Color f_hat = f(ls->wi);
        if (f_hat.is_black()) return Color(0.0f);
        const Ray shadow = spawn(*ls);
        Color r_l(1.0f), r_u(1.0f);
        const Color T = transmittance(shadow, medium_of(ls->wi), ls->infinite ? std::nullopt : std::optional<Vec3f>(ls->p), rng,
                                      r_l, r_u);
        if (T.is_black()) return Color(0.0f);
        r_l *= r_p * ls->pdf;
        // A delta light, which nothing else can find; or NEE alone (mis false), which then counts
        // all light that reaches a scattering point (trace ignores what scattering finds).
        if (ls->is_delta || !mis) return beta * f_hat * T * ls->Le / pc.average(r_l);
        r_u *= r_p * pdf(ls->wi);
        return beta * f_hat * T * ls->Le / pc.average(r_l + r_u);
    }

    // pbrt-v4's tabulated BSSRDF (VolPathIntegrator::Li), where the path has just refracted into
    // subsurface material `ss` at `entry` (shading normal `ns`) of a shape of material `material`:
    // a probe segment from the profile (TabulatedBssrdf::sample_sp), one of its hits on shapes of
    // the same material kept by weighted reservoir sampling (weight 1: each with probability 1/n),
    // beta *= Sp / (pdf[hero] / n) and r_u *= pdf / pdf[hero] (spectral MIS over the channels'
    // radius sampling); then at the exit point next-event estimation and the next direction by
    // the NormalizedFresnel lobe, in the medium `outside` (the path's before it entered). Depth
    // does not grow (as in pbrt-v4). Its numbers are drawn from the sampler first, in a fixed
    // order: probe axis and radius (3), the reservoir's seed, the light's (3), the exit direction
    // (2). Returns false when the path ends.
    bool cross_subsurface(const Subsurface& ss, uint32_t material, const SurfaceHit& entry, const Vec3f& ns,
                          uint32_t outside, Sampler& sampler, bool next_event, Color& L, Color& beta, Color& r_u,
                          Color& r_l, Ray& ray, uint32_t& medium, Vec3f& prev_p, Vec3f& prev_n, Rng& rng) const {
        const float u_axis = sampler.next_float();
        const Vec2f u_radius = sampler.next_vec2f();
        const float u_pick = sampler.next_float();
        const LightNumbers light_numbers = draw_light_numbers(sampler, lights);
        const Vec2f u_exit = sampler.next_vec2f();

        Color sigma_a, sigma_s;
        const Vec2f uv = ss.is_textured() ? accel.uv(entry) : Vec2f();
        ss.coefficients(scene.textures, TextureContext{uv, entry.p, pc.ch.lambda, entry.ng}, sigma_a, sigma_s);
        const TabulatedBssrdf bssrdf(entry.p, ns, ss.eta, sigma_a, sigma_s, &ss.table, pc.hero);
        const std::optional<BssrdfProbeSegment> probe = bssrdf.sample_sp(u_axis, u_radius.x, u_radius.y);
        if (!probe) return false;

        // Every surface along the segment; those of the material are the candidates (at most
        // kMaxMediumEvents surfaces, a bound no geometry short of a pathological one meets).
        Rng pick(mix_bits(uint64_t(std::bit_cast<uint32_t>(u_pick))), 0x2545f4914f6cdd1dull);
        std::optional<SurfaceHit> exit;
        int candidates = 0;
        Ray r{probe->p0, probe->p1 - probe->p0, 0.0f, 1.0f, entry.time};  // at the path's time (motion blur)
        for (int hits = 0; hits < kMaxMediumEvents; ++hits) {
            ++counters.bounce;
            std::optional<SurfaceHit> h = accel.intersect(r);
            if (!h) break;
            if (scene.shapes[h->shape_id].material == material && pick.next_float() * float(++candidates) < 1.0f)
                exit = h;
            r = spawn_ray_to(*h, probe->p1);
        }
        if (!exit) return false;
        const Color Sp = bssrdf.sp(exit->p);
        const Color pdf = bssrdf.pdf_sp(exit->p, exit->ng);
        const float pdf_hero = pdf[pc.hero] / float(candidates);
        if (!(pdf_hero > 0.0f) || Sp.is_black()) return false;
        beta *= Sp / pdf_hero;
        r_u *= pdf / pdf[pc.hero];
        if (!beta.is_finite()) return false;

        // The exit: pbrt-v4's NormalizedFresnelBxDF in the frame of the hit's shading normal,
        // with wo that normal.
        const Shape& shape = scene.shapes[exit->shape_id];
        const NormalizedFresnel lobe{ss.eta};
        const Frame frame = Frame::from_normal(exit->ns);
        const Vec3f wo(0.0f, 0.0f, 1.0f);
        if (next_event && !lights.empty()) {
            auto f = [&](const Vec3f& wi_world) {
                const Vec3f wi = frame.to_local(normalize(wi_world));
                return lobe.eval(wo, wi, TransportMode::kRadiance) * std::abs(wi.z);
            };
            auto pdf_of = [&](const Vec3f& wi_world) { return lobe.pdf(wo, frame.to_local(normalize(wi_world))); };
            auto spawn = [&](const LightSample& ls) {
                return ls.infinite ? spawn_ray(*exit, ls.wi) : spawn_ray_to(*exit, ls.p);
            };
            auto medium_of = [&](const Vec3f& wi) { return medium_after(shape, *exit, wi, outside); };
            L += direct_light(exit->p, exit->ns, light_numbers, beta, r_u, f, pdf_of, spawn, medium_of, rng);
        }
        const std::optional<BsdfSample> bs = lobe.sample(wo, 0.0f, u_exit, TransportMode::kRadiance);
        if (!bs || !(bs->pdf > 0.0f)) return false;
        beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        r_l = r_u / bs->pdf;
        const Vec3f wi = frame.to_world(bs->wi);
        ray = spawn_ray(*exit, wi);
        medium = medium_after(shape, *exit, wi, outside);
        prev_p = exit->p;
        prev_n = exit->ns;
        return true;
    }
};

}  // namespace

// pbrt-v4's VolPathIntegrator::Li, with candela's path vertex, light set and Russian roulette.
template <bool kSpectral>
Color VolPathIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters,
                               SampledWavelengths* w) const {
    SpectralBsdfCache bsdf_cache_storage;
    SpectralEmissionCache emission_cache_storage;
    SpectralBsdfCache* bsdf_cache = kSpectral ? &bsdf_cache_storage : nullptr;
    SpectralEmissionCache* emission_cache = kSpectral ? &emission_cache_storage : nullptr;
    PathChannels pc{MediumChannels{kSpectral ? &w->lambda : nullptr}, 0, kSpectral};
    if constexpr (!kSpectral) pc.hero = std::min(2, int(sampler.next_float() * 3.0f));
    const IntegratorSettings& settings = scene_.integrator;
    const VolumePath<kSpectral> path{scene_, accel_, lights_, pc, counters, emission_cache, settings.mis};

    Color L(0.0f), beta(1.0f), r_u(1.0f), r_l(1.0f);
    bool specular_bounce = false;
    int depth = 0;
    float eta_scale = 1.0f;
    Vec3f prev_p;  // the last scattering point, where light sampling would have started
    Vec3f prev_n;  // its shading normal; zero in a medium (LightSelection::kBvh reads it)
    Ray ray = camera_ray;
    uint32_t medium = scene_.camera_medium;
    int medium_events = 0;
    for (int segment = 0;; ++segment) {
        ++(segment == 0 ? counters.camera : counters.bounce);
        // This segment's numbers: NEE and the next direction at whatever scatters (a surface or
        // the medium), Russian roulette, and the medium walk's first distance and generator.
        const LightNumbers light_numbers = draw_light_numbers(sampler, lights_);
        const BsdfNumbers bsdf_numbers = draw_bsdf_numbers(sampler, any_material_uses_choice_);
        const float roulette_number = draw_roulette_number(sampler, depth + 1, settings);
        const float u_distance = sampler.next_float();
        Rng rng = medium_rng(sampler.next_float(), u_distance);
        std::optional<SurfaceHit> hit = accel_.intersect(ray);

        if (medium != kNoMedium) {
            bool scattered = false, terminated = false;
            const float t_max = hit ? hit->t : kInfinity;
            const Medium& m = scene_.media[medium];
            const float g = medium_g(m);
            const bool counts_bounces = medium_counts_bounces(m);
            const Color T_maj = visit(
                [&](const auto& med) {
                    return sample_majorant_transmittance(
                        med, ray, t_max, u_distance, rng, pc.ch, pc.hero,
                        [&](const Vec3f& p, const MediumPoint& mp, const Color& sigma_maj, const Color& T) {
                            const int h = pc.hero;
                            if (beta.is_black() || ++medium_events > kMaxMediumEvents) {
                                terminated = true;
                                return false;
                            }
                            // Emission at the point, as absorption would count it (pbrt-v4).
                            if (depth < settings.max_depth && !mp.Le.is_black()) {
                                const float pdf = sigma_maj[h] * T[h];
                                const Color r_e = r_u * sigma_maj * T / pdf;
                                if (!r_e.is_black()) L += beta * T / pdf * mp.sigma_a * mp.Le / pc.average(r_e);
                            }
                            const float p_absorb = mp.sigma_a[h] / sigma_maj[h];
                            const float p_scatter = mp.sigma_s[h] / sigma_maj[h];
                            const float um = rng.next_float();
                            if (um < p_absorb) {
                                terminated = true;
                                return false;
                            }
                            if (um < p_absorb + p_scatter) {
                                // A real scattering: NEE, then the phase function's direction.
                                // A subsurface random walk's steps are not the path's bounces.
                                if (counts_bounces && depth++ >= settings.max_depth) {
                                    terminated = true;
                                    return false;
                                }
                                const float pdf = T[h] * mp.sigma_s[h];
                                beta *= T * mp.sigma_s / pdf;
                                r_u *= T * mp.sigma_s / pdf;
                                if (beta.is_black() || r_u.is_black()) return false;
                                const Vec3f wo = -normalize(ray.d);
                                auto phase = [&](const Vec3f& wi) { return Color(henyey_greenstein(dot(wo, normalize(wi)), g)); };
                                auto phase_pdf = [&](const Vec3f& wi) { return henyey_greenstein(dot(wo, normalize(wi)), g); };
                                auto spawn = [&](const LightSample& ls) {
                                    return ls.infinite ? Ray{p, ls.wi, 0.0f, kInfinity, ray.time}
                                                       : Ray{p, ls.p - p, 0.0f, 1.0f - kShadowEpsilon, ray.time};
                                };
                                if (next_event_ && !lights_.empty())
                                    L += path.direct_light(p, Vec3f{}, light_numbers, beta, r_u, phase, phase_pdf, spawn,
                                                           [&](const Vec3f&) { return medium; }, rng);
                                const PhaseSample ps = sample_henyey_greenstein(wo, g, bsdf_numbers.u);
                                if (!(ps.p > 0.0f)) {
                                    terminated = true;
                                    return false;
                                }
                                // beta *= p / pdf, which is 1 for a phase function sampled exactly.
                                r_l = r_u / ps.p;
                                prev_p = p;
                                prev_n = Vec3f{};
                                scattered = true;
                                ray = Ray{p, ps.wi, 0.0f, kInfinity, ray.time};
                                specular_bounce = false;
                                return false;
                            }
                            // A null collision: the path goes on.
                            const Color sigma_n = clamp_channels(sigma_maj - mp.sigma_a - mp.sigma_s, 0.0f, kInfinity);
                            const float pdf = T[h] * sigma_n[h];
                            if (pdf == 0.0f) {
                                beta = Color(0.0f);
                            } else {
                                beta *= T * sigma_n / pdf;
                                r_u *= T * sigma_n / pdf;
                                r_l *= T * sigma_maj / pdf;
                            }
                            return !beta.is_black() && !r_u.is_black();
                        });
                },
                m);
            if (terminated || beta.is_black() || r_u.is_black() || !beta.is_finite()) break;
            if (scattered) {
                if (!survive_volume_roulette(beta, r_u, eta_scale, depth, settings, pc, roulette_number)) break;
                continue;
            }
            beta *= T_maj / T_maj[pc.hero];
            r_u *= T_maj / T_maj[pc.hero];
            r_l *= T_maj / T_maj[pc.hero];
            if (!beta.is_finite()) break;
        }

        if (!hit) {
            const Color Le = environment_radiance<kSpectral>(ray.d, pc.ch.lambda);
            if (!Le.is_black()) {
                if (depth == 0 || specular_bounce || !next_event_)
                    L += beta * Le / pc.average(r_u);
                else if (settings.mis)
                    L += beta * Le / pc.average(r_u + r_l * lights_.environment_pdf(normalize(ray.d)));
            }
            break;
        }
        const Color Le = emitted<kSpectral>(hit->shape_id, hit->ng, -ray.d, pc.ch.lambda, emission_cache);
        if (!Le.is_black()) {
            if (depth == 0 || specular_bounce || !next_event_)
                L += beta * Le / pc.average(r_u);
            else if (settings.mis)
                L += beta * Le / pc.average(r_u + r_l * lights_.pdf(prev_p, prev_n, hit->shape_id, hit->p, hit->ng));
        }

        const Shape& shape = scene_.shapes[hit->shape_id];
        if (scene_.materials[shape.material].interface) {
            // Only a boundary between media: through it, without counting a bounce.
            medium = medium_after(shape, *hit, ray.d, medium);
            ray = spawn_ray(*hit, ray.d);
            continue;
        }
        if (depth++ >= settings.max_depth) break;

        PathVertex v = make_vertex<kSpectral>(scene_, accel_, *hit, ray, w, bsdf_cache);
        if (next_event_ && !v.bsdf.is_delta_only() && !lights_.empty()) {
            auto f = [&](const Vec3f& wi_world) {
                const Vec3f wi = v.frame.to_local(wi_world);
                return v.bsdf.eval(v.wo, wi, TransportMode::kRadiance) * std::abs(wi.z);
            };
            auto pdf = [&](const Vec3f& wi_world) { return v.bsdf.pdf(v.wo, v.frame.to_local(wi_world)); };
            auto spawn = [&](const LightSample& ls) { return ls.infinite ? spawn_ray(*hit, ls.wi) : spawn_ray_to(*hit, ls.p); };
            // The shadow ray's medium: that of the side of the surface it leaves by.
            auto medium_of = [&](const Vec3f& wi) { return medium_after(shape, *hit, wi, medium); };
            L += path.direct_light(hit->p, v.frame.n, light_numbers, beta, r_u, f, pdf, spawn, medium_of, rng);
        }
        std::optional<BsdfSample> bs = continue_path(v, bsdf_numbers, beta, ray);
        if (!bs) break;
        r_l = r_u / bs->pdf;
        specular_bounce = bs->is_delta;
        if (bs->is_transmission) eta_scale *= sqr(bs->eta);
        prev_p = hit->p;
        prev_n = v.frame.n;
        // Into a subsurface material by the tabulated BSSRDF: out again at the probe's exit.
        if (v.material->subsurface != kNoSubsurface && bs->is_transmission &&
            scene_.subsurfaces[v.material->subsurface].method == SubsurfaceMethod::kTabulated) {
            if (!path.cross_subsurface(scene_.subsurfaces[v.material->subsurface], shape.material, *hit, v.frame.n,
                                       medium, sampler, next_event_, L, beta, r_u, r_l, ray, medium, prev_p, prev_n,
                                       rng))
                break;
            specular_bounce = false;
        } else {
            medium = medium_after(shape, *hit, ray.d, medium);
        }
        if (!survive_volume_roulette(beta, r_u, eta_scale, depth, settings, pc, roulette_number)) break;
    }
    return L;
}

}  // namespace candela
