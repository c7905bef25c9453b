#pragma once
// The ideal diffuse lobe: f = albedo / pi in the hemisphere of wo, importance sampled by the
// cosine. It reflects on whichever side wo lies (a two-sided surface), because a shading normal
// may face either way; the integrator decides which side is lit.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/sampling/warps.h"

namespace candela {

struct LambertianLobe {
    Color reflectance{0.5f};  // directional albedo: the fraction of light reflected, per channel

    // albedo / pi when wo and wi share a hemisphere, else 0.
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
        return same_hemisphere(wo, wi) ? reflectance * kInvPi : Color(0.0f);
    }
    // |cos(theta_i)| / pi in wo's hemisphere, else 0.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const {
        return same_hemisphere(wo, wi) ? abs_cos_theta(wi) * kInvPi : 0.0f;
    }
    // A cosine-distributed wi on wo's side (uc unused). Since f |cos| / pdf = albedo for every
    // sample, the estimator of the directional albedo has no variance (Nori's diffuse.cpp).
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float, const Vec2f& u, TransportMode) const {
        // Built where the caller receives it (one object, returned on every path): a copy of a
        // just-written struct costs a store-forwarding stall per sample.
        std::optional<BsdfSample> result;
        Vec3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
        // wo in the surface's plane, or wi drawn on the disk's rim: no hemisphere holds both.
        if (!same_hemisphere(wo, wi)) return result;
        BsdfSample& s = result.emplace();  // eval() and pdf() for a wi known to be in wo's hemisphere
        s.f = reflectance * kInvPi;
        s.wi = wi;
        s.pdf = abs_cos_theta(wi) * kInvPi;
        return result;
    }
    static constexpr bool kUsesChoice = false;
    CANDELA_HD bool is_delta() const { return false; }
    CANDELA_HD Color albedo() const { return reflectance; }
};
static_assert(BsdfLobeType<LambertianLobe>);

}  // namespace candela
