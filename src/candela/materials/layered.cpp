// LayeredLobe: the random walks of pbrt-v4's LayeredBxDF (bxdfs.h) for a coat entered from
// above (twoSided), PBR 4th ed. 14.3.2 (f), 14.3.3 (sampling and PDF). The walk's state is a
// direction w (the way light travels between the layers), a depth z in [0, thickness] (the coat
// at thickness, the base at 0) and a throughput; the medium has sigma_t = 1, so thickness is in
// mean free paths.
#include "candela/materials/layered.h"

#include <bit>
#include <cfloat>

#include "candela/sampling/henyey_greenstein.h"
#include "candela/sampling/rng.h"

namespace candela {

namespace {

// A hash of a direction's bits (the seed of the generators below).
CANDELA_HD uint64_t hash_direction(const Vec3f& w) {
    uint64_t xy = (uint64_t(std::bit_cast<uint32_t>(w.x)) << 32) | std::bit_cast<uint32_t>(w.y);
    return mix_bits(mix_bits(xy) ^ std::bit_cast<uint32_t>(w.z));
}

// The generator of one eval() or pdf() call: seeded by the two directions, and by which of the
// two functions asks (pbrt-v4 hashes them in the opposite order for the PDF).
CANDELA_HD Rng direction_rng(const Vec3f& a, const Vec3f& b, uint64_t salt) {
    return Rng(mix_bits(hash_direction(a) ^ salt), hash_direction(b));
}

// The power heuristic (beta = 2) for one sample of each strategy; 1 where the first density is
// so large that its square overflows (pbrt-v4's PowerHeuristic).
CANDELA_HD float power_heuristic_layered(float pdf_f, float pdf_g) {
    float f2 = pdf_f * pdf_f;
    if (std::isinf(f2)) return 1.0f;
    return f2 / (f2 + pdf_g * pdf_g);
}

// Transmittance exp(-|dz / cos|) along w over a depth difference dz (sigma_t = 1); 1 for dz = 0.
CANDELA_HD float transmittance(float dz, const Vec3f& w) {
    if (std::abs(dz) <= FLT_MIN) return 1.0f;
    return std::exp(-std::abs(dz / w.z));
}

// A sample of the exponential distribution of rate a: -ln(1 - u) / a.
CANDELA_HD float sample_exponential(float u, float a) { return -std::log(1.0f - u) / a; }

// A sample that the walk may use: it exists, carries light and has a density, and leaves the
// interface's plane (pbrt-v4's `!bs || !bs->f || bs->pdf == 0 || bs->wi.z == 0`).
CANDELA_HD bool usable(const std::optional<BsdfSample>& s) {
    return s && !s->f.is_black() && s->pdf > 0.0f && s->wi.z != 0.0f;
}

constexpr uint64_t kEvalSalt = 0x6576616c5f666e00ull;    // "eval_fn"
constexpr uint64_t kPdfSalt = 0x7064665f666e0000ull;     // "pdf_fn"
constexpr uint64_t kSampleSalt = 0x73616d706c650000ull;  // "sample"

}  // namespace

template <class Base>
CANDELA_HD Color LayeredLobe<Base>::eval(const Vec3f& wo_in, const Vec3f& wi_in, TransportMode mode) const {
    Vec3f wo = wo_in, wi = wi_in;
    if (wo.z < 0.0f) {
        wo = -wo;
        wi = -wi;
    }
    // The base transmits nothing: light that enters through the coat leaves through it, on wo's
    // side (pbrt-v4's walk towards the base as exit interface finds no transmission there).
    if (!same_hemisphere(wo, wi)) return Color(0.0f);
    const float thick = thickness > FLT_MIN ? thickness : FLT_MIN;
    const float exit_z = thick;  // light enters and leaves through the coat
    const bool coat_specular = coat.is_specular(), base_specular = base.is_delta();
    const bool scattering = !medium_albedo.is_black();
    const auto n = static_cast<float>(n_samples);

    // Reflection at the coat, counted once per walk as each walk's estimate includes it.
    Color f = coat.f(wo, wi, mode) * n;

    // The density with which the next-event strategy (wis, drawn from wi through the coat)
    // produces the inside direction `up` (travelling up to the coat): the coat's density of
    // wi -> -up, in the solid angle of the inside direction, the measure in which the other
    // strategy (a base or phase sample) draws `up`. pbrt-v4 weights with the reverse density
    // coat.pdf(-up, wi), in wi's measure, so its two weights do not add to 1 and its f is too
    // bright behind rough coats (by 3 to 11 % in layered_stat_test.cpp's cases).
    auto next_event_pdf = [&](const Vec3f& up) {
        return pbrt_v4_weights ? coat.pdf(-up, wi, ReflTrans::kAll) : coat.pdf(wi, -up, ReflTrans::kTransmission);
    };

    Rng rng = direction_rng(wo, wi, kEvalSalt);
    auto r = [&rng]() { return rng.next_float(); };
    for (int s = 0; s < n_samples; ++s) {
        // Into the layers along wo, and (for next-event estimation, with the adjoint transport
        // mode) from wi: every path that leaves towards wi ends with a refraction that wis
        // samples in reverse.
        float uc = r();
        Vec2f u(r(), r());
        std::optional<BsdfSample> wos = coat.sample(wo, uc, u, mode, ReflTrans::kTransmission);
        if (!usable(wos)) continue;
        uc = r();
        u = Vec2f(r(), r());
        std::optional<BsdfSample> wis = coat.sample(wi, uc, u, reversed(mode), ReflTrans::kTransmission);
        if (!usable(wis)) continue;

        Color beta = wos->f * (abs_cos_theta(wos->wi) / wos->pdf);
        float z = thick;
        Vec3f w = wos->wi;
        for (int depth = 0; depth < max_depth; ++depth) {
            if (depth > 3 && beta.max_component() < 0.25f) {
                float q = 1.0f - beta.max_component();
                q = q > 0.0f ? q : 0.0f;
                if (r() < q) break;
                beta = beta / (1.0f - q);
            }

            if (!scattering) {
                z = z == thick ? 0.0f : thick;
                beta *= transmittance(thick, w);
            } else {
                // A free flight through the medium: a scattering event inside the slab, or the
                // next interface (the transmittance is sampled, so it leaves beta).
                float dz = sample_exponential(r(), 1.0f / abs_cos_theta(w));
                float zp = w.z > 0.0f ? z + dz : z - dz;
                if (zp == z) continue;
                if (0.0f < zp && zp < thick) {
                    // Next-event estimation through the coat along wis, MIS-weighted against the
                    // phase function's own sample below when the coat is rough.
                    float phase = henyey_greenstein(dot(-w, -wis->wi), g);
                    float wt = coat_specular ? 1.0f : power_heuristic_layered(wis->pdf, phase);
                    f += beta * medium_albedo * (phase * wt * transmittance(zp - exit_z, wis->wi) / wis->pdf) *
                         wis->f;
                    PhaseSample ps = sample_henyey_greenstein(-w, g, Vec2f(r(), r()));
                    if (ps.p == 0.0f || ps.wi.z == 0.0f) continue;
                    beta *= medium_albedo;  // times p / pdf = 1
                    w = ps.wi;
                    z = zp;
                    // The phase sample heading for the coat, weighted against wis.
                    if (((z < exit_z && w.z > 0.0f) || (z > exit_z && w.z < 0.0f)) && !coat_specular) {
                        Color f_exit = coat.f(-w, wi, mode);
                        if (!f_exit.is_black()) {
                            float wt_exit = power_heuristic_layered(ps.p, next_event_pdf(w));
                            f += beta * f_exit * (transmittance(zp - exit_z, ps.wi) * wt_exit);
                        }
                    }
                    continue;
                }
                z = clamp(zp, 0.0f, thick);
            }

            if (z == exit_z) {
                // At the coat from below: only reflection keeps the walk inside (transmission
                // towards wi is what the next-event estimates count).
                uc = r();
                u = Vec2f(r(), r());
                std::optional<BsdfSample> bs = coat.sample(-w, uc, u, mode, ReflTrans::kReflection);
                if (!usable(bs)) break;
                beta *= bs->f * (abs_cos_theta(bs->wi) / bs->pdf);
                w = bs->wi;
                continue;
            }
            // At the base: next-event estimation along wis (unless the base is specular), then a
            // sample of the base for the walk's next direction.
            if (!base_specular) {
                float wt = coat_specular ? 1.0f : power_heuristic_layered(wis->pdf, base.pdf(-w, -wis->wi));
                f += beta * base.eval(-w, -wis->wi, mode) * wis->f *
                     (abs_cos_theta(wis->wi) * wt * transmittance(thick, wis->wi) / wis->pdf);
            }
            uc = r();
            u = Vec2f(r(), r());
            std::optional<BsdfSample> bs = base.sample(-w, uc, u, mode);
            if (!usable(bs)) break;
            beta *= bs->f * (abs_cos_theta(bs->wi) / bs->pdf);
            w = bs->wi;
            if (!coat_specular) {
                // The base's sample continued through the coat towards wi, weighted against wis.
                Color f_exit = coat.f(-w, wi, mode);
                if (!f_exit.is_black()) {
                    float wt = 1.0f;
                    if (!base_specular) wt = power_heuristic_layered(bs->pdf, next_event_pdf(w));
                    f += beta * f_exit * (transmittance(thick, bs->wi) * wt);
                }
            }
        }
    }
    return f / n;
}

template <class Base>
CANDELA_HD float LayeredLobe<Base>::pdf(const Vec3f& wo, const Vec3f& wi) const {
    // A delta-only lobe has no density (and pbrt-v4's uniform share would claim one for it).
    if (is_delta()) return 0.0f;
    if (wo.z < 0.0f) return pdf_upper(-wo, -wi);
    return pdf_upper(wo, wi);
}

template <class Base>
CANDELA_HD float LayeredLobe<Base>::pdf_upper(const Vec3f& wo, const Vec3f& wi) const {
    // Mixed with the uniform density so that every direction has some (pbrt-v4: Lerp(0.9, ...)).
    constexpr float kUniformShare = 0.1f;
    // wi across the surface: no transmission-transmission path exists, only the uniform share.
    if (!same_hemisphere(wo, wi)) return kUniformShare * kInv4Pi;

    const auto n = static_cast<float>(n_samples);
    float pdf_sum = n * coat.pdf(wo, wi, ReflTrans::kReflection);
    Rng rng = direction_rng(wi, wo, kPdfSalt);
    auto r = [&rng]() { return rng.next_float(); };
    for (int s = 0; s < n_samples; ++s) {
        // The transmission-reflection-transmission path: into the coat from wo and from wi, and
        // the base's density between the two refracted directions (PBR 4th ed., eq. 14.38). The
        // transport mode changes no density, only f.
        float uc = r();
        Vec2f u(r(), r());
        std::optional<BsdfSample> wos = coat.sample(wo, uc, u, TransportMode::kRadiance, ReflTrans::kTransmission);
        uc = r();
        u = Vec2f(r(), r());
        std::optional<BsdfSample> wis = coat.sample(wi, uc, u, TransportMode::kImportance, ReflTrans::kTransmission);
        if (!(wos && !wos->f.is_black() && wos->pdf > 0.0f && wis && !wis->f.is_black() && wis->pdf > 0.0f))
            continue;
        if (coat.is_specular()) {
            pdf_sum += base.pdf(-wos->wi, -wis->wi);
            continue;
        }
        // A rough coat: the product of the base's and the exit's densities estimated by MIS of
        // the two ways of closing the path (eq. 14.39).
        uc = r();
        u = Vec2f(r(), r());
        std::optional<BsdfSample> rs = base.sample(-wos->wi, uc, u, TransportMode::kRadiance);
        if (!(rs && !rs->f.is_black() && rs->pdf > 0.0f)) continue;
        if (base.is_delta()) {
            pdf_sum += coat.pdf(-rs->wi, wi);
            continue;
        }
        float r_pdf = base.pdf(-wos->wi, -wis->wi);
        pdf_sum += power_heuristic_layered(wis->pdf, r_pdf) * r_pdf;
        float t_pdf = coat.pdf(-rs->wi, wi);
        pdf_sum += power_heuristic_layered(rs->pdf, t_pdf) * t_pdf;
    }
    return lerp(1.0f - kUniformShare, kInv4Pi, pdf_sum / n);
}

template <class Base>
CANDELA_HD std::optional<BsdfSample> LayeredLobe<Base>::sample(const Vec3f& wo_in, float uc, const Vec2f& u,
                                                              TransportMode mode) const {
    const bool flip = wo_in.z < 0.0f;
    const Vec3f wo = flip ? -wo_in : wo_in;
    std::optional<BsdfSample> result;

    // The coat first: reflection there is the sample; transmission starts the walk.
    std::optional<BsdfSample> bs = coat.sample(wo, uc, u, mode);
    if (!usable(bs)) return result;
    if (!bs->is_transmission) {
        result = bs;
        if (!result->is_delta) {
            float p = pdf_upper(wo, result->wi);
            result->f = result->f * (p / result->pdf);
            result->pdf = p;
        }
        if (flip) result->wi = -result->wi;
        return result;
    }

    const float thick = thickness > FLT_MIN ? thickness : FLT_MIN;
    const bool scattering = !medium_albedo.is_black();
    Vec3f w = bs->wi;
    bool specular_path = bs->is_delta;
    Rng rng(mix_bits(hash_direction(wo) ^ kSampleSalt),
            mix_bits(std::bit_cast<uint32_t>(uc)) ^
                ((uint64_t(std::bit_cast<uint32_t>(u.x)) << 32) | std::bit_cast<uint32_t>(u.y)));
    auto r = [&rng]() { return rng.next_float(); };
    // The walk's f (with the cosines of the interfaces passed) and its density.
    Color f = bs->f * abs_cos_theta(bs->wi);
    float pdf = bs->pdf;
    float z = thick;

    // One event more than eval()'s walks: the exit through the coat is an event of the walk here,
    // so max_depth + 1 events count the paths of at most max_depth events between the layers,
    // the paths eval() counts (pbrt-v4 stops one event earlier, so that its Sample_f and f
    // truncate differently wherever the medium scatters or max_depth is odd).
    const int events = pbrt_v4_weights ? max_depth - 1 : max_depth;
    for (int depth = 0; depth <= events; ++depth) {
        // Roulette on the walk's weight f / pdf; the survival probability joins the density.
        float rr_beta = f.max_component() / pdf;
        if (depth > 3 && rr_beta < 0.25f) {
            float q = 1.0f - rr_beta;
            q = q > 0.0f ? q : 0.0f;
            if (r() < q) return result;
            pdf *= 1.0f - q;
        }
        if (w.z == 0.0f) return result;

        if (scattering) {
            float dz = sample_exponential(r(), 1.0f / abs_cos_theta(w));
            float zp = w.z > 0.0f ? z + dz : z - dz;
            if (zp == z) return result;
            if (0.0f < zp && zp < thick) {
                // Scattered in the medium: the distance's density and the transmittance cancel.
                PhaseSample ps = sample_henyey_greenstein(-w, g, Vec2f(r(), r()));
                if (ps.p == 0.0f || ps.wi.z == 0.0f) return result;
                f *= medium_albedo * ps.p;
                pdf *= ps.p;
                specular_path = false;
                w = ps.wi;
                z = zp;
                continue;
            }
            z = clamp(zp, 0.0f, thick);
        } else {
            z = z == thick ? 0.0f : thick;
            f *= transmittance(thick, w);
        }

        float uc_next = r();
        Vec2f u_next(r(), r());
        bs = z == 0.0f ? base.sample(-w, uc_next, u_next, mode) : coat.sample(-w, uc_next, u_next, mode);
        if (!usable(bs)) return result;
        f *= bs->f;
        pdf *= bs->pdf;
        specular_path = specular_path && bs->is_delta;
        w = bs->wi;

        if (bs->is_transmission) {
            // Out through the coat (the base transmits nothing), on wo's side. A long walk's f
            // and density can both fall below float's normal range (a hundred scattering
            // events of density 0.01): the weight is their quotient, formed first, and a walk
            // whose weight is lost to underflow is dropped.
            Color weight = f / pdf;
            if (!(pdf > 0.0f) || !weight.is_finite()) return result;
            BsdfSample& out = result.emplace();
            out.wi = w;
            out.is_delta = specular_path;
            if (specular_path) {
                out.f = f;
                out.pdf = pdf;
            } else {
                float p = pdf_upper(wo, w);
                out.f = weight * p;
                out.pdf = p;
            }
            if (flip) out.wi = -out.wi;
            return result;
        }
        f *= abs_cos_theta(bs->wi);
    }
    return result;
}

template struct LayeredLobe<LambertianLobe>;
template struct LayeredLobe<ConductorLobe>;

}  // namespace candela
