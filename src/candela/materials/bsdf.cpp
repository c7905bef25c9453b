// Bsdf: uniform choice among the lobes, with pdfs and values combined as pbrt-v3's BSDF::Sample_f,
// BSDF::Pdf and BSDF::f do, so that a direction sampled from one lobe is weighted by the density
// of the whole mixture (the one-sample "balance" combination of the lobes' strategies).
#include "candela/materials/bsdf.h"

#include <type_traits>

#include "candela/math/constants.h"

namespace candela {

CANDELA_HD Color Bsdf::eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode) const {
    Color f(0.0f);
    for (uint32_t k = 0; k < lobe_count; ++k)
        f += visit([&](const auto& lobe) { return lobe.eval(wo, wi, mode); }, lobes[k]);
    return f;
}

CANDELA_HD float Bsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (lobe_count == 0) return 0.0f;
    float sum = 0.0f;
    for (uint32_t k = 0; k < lobe_count; ++k)
        sum += visit([&](const auto& lobe) { return lobe.pdf(wo, wi); }, lobes[k]);
    return sum / static_cast<float>(lobe_count);
}

CANDELA_HD std::optional<BsdfSample> Bsdf::sample(const Vec3f& wo, float uc, const Vec2f& u,
                                                  TransportMode mode) const {
    // uc picks lobe k and is then stretched back over [0, 1) for the lobe's own discrete choice
    // (pbrt-v3's uRemapped), so one number serves both without correlating them. With one lobe
    // (most materials) there is no choice and uc goes to the lobe as it is.
    auto n = static_cast<float>(lobe_count);
    uint32_t k = 0;
    float uc_lobe = uc;
    if (lobe_count > 1) {
        k = static_cast<uint32_t>(uc * n);
        if (k >= lobe_count) k = lobe_count - 1;
        uc_lobe = clamp(uc * n - static_cast<float>(k), 0.0f, kOneMinusEpsilon);
    }
    // One object, initialised by the lobe and returned on every path, so that it is built where
    // the caller receives it (a copy of a just-written struct stalls on store forwarding).
    std::optional<BsdfSample> s =
        lobe_count == 0 ? std::nullopt
                        : visit([&](const auto& lobe) { return lobe.sample(wo, uc_lobe, u, mode); }, lobes[k]);
    if (!s || !(s->pdf > 0.0f)) {
        s.reset();
    } else if (s->is_delta) {
        // Only this lobe can have produced wi: the others' densities there are 0 (or, for other
        // delta lobes, meet it with probability 0). The lobe choice divides the probability.
        if (lobe_count > 1) s->pdf /= n;
    } else if (lobe_count > 1) {
        if (!has_estimated_lobe()) {
            s->f = eval(wo, s->wi, mode);
            s->pdf = pdf(wo, s->wi);
        } else {
            // A coated lobe's pdf() is no density of its sampling, so the balance above would
            // be biased. Each lobe's sample counts alone instead, its weight f / pdf divided by
            // the probability 1/n of choosing it (unbiased, as the lobes' integrals add); the
            // sample reports the mixture's pdf() for MIS with light sampling, which stays
            // unbiased because pdf() is a fixed function of the directions.
            float p = pdf(wo, s->wi);
            s->f = s->f * (n * p / s->pdf);
            s->pdf = p;
        }
    }
    return s;
}

CANDELA_HD bool Bsdf::has_estimated_lobe() const {
    for (uint32_t k = 0; k < lobe_count; ++k)
        if (visit([](const auto& lobe) { return kIsLayeredLobe<std::decay_t<decltype(lobe)>>; }, lobes[k]))
            return true;
    return false;
}

CANDELA_HD bool Bsdf::is_delta_only() const {
    for (uint32_t k = 0; k < lobe_count; ++k)
        if (!visit([](const auto& lobe) { return lobe.is_delta(); }, lobes[k])) return false;
    return true;
}

CANDELA_HD bool Bsdf::uses_choice() const {
    if (lobe_count != 1) return lobe_count > 1;
    return visit([](const auto& lobe) { return bool(std::decay_t<decltype(lobe)>::kUsesChoice); }, lobes[0]);
}

CANDELA_HD Color Bsdf::albedo() const {
    Color sum(0.0f);
    for (uint32_t k = 0; k < lobe_count; ++k)
        sum += visit([](const auto& lobe) { return lobe.albedo(); }, lobes[k]);
    return sum;
}

}  // namespace candela
