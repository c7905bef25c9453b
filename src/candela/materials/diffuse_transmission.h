#pragma once
// Lambertian reflection and Lambertian transmission (pbrt-v4's DiffuseTransmissionBxDF): a thin
// sheet that scatters diffusely to both sides, f = R / pi on wo's side and T / pi on the other.
// Leaves, paper, lamp shades. The directional albedo is R + T whatever wo, so R + T = 1 conserves
// energy exactly.
//
// Sampling (as pbrt-v4's): a side is chosen by uc with probabilities in the proportion of the
// largest channel of R and of T, then a cosine-distributed direction on that side. The weight
// f |cos| / pdf is then R (or T) over that side's probability.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/sampling/warps.h"

namespace candela {

struct DiffuseTransmissionLobe {
    Color reflectance{0.25f};    // R: the fraction reflected, per channel
    Color transmittance{0.25f};  // T: the fraction transmitted, per channel

    // R / pi when wo and wi share a hemisphere, T / pi when they do not.
    CANDELA_HD Color eval(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
        if (wo.z == 0.0f || wi.z == 0.0f) return Color(0.0f);
        return (same_hemisphere(wo, wi) ? reflectance : transmittance) * kInvPi;
    }
    // The chosen side's probability times |cos(theta_i)| / pi.
    CANDELA_HD float pdf(const Vec3f& wo, const Vec3f& wi) const {
        const float pr = reflection_probability();
        if (wo.z == 0.0f || wi.z == 0.0f || pr < 0.0f) return 0.0f;
        return (same_hemisphere(wo, wi) ? pr : 1.0f - pr) * abs_cos_theta(wi) * kInvPi;
    }
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f& u, TransportMode) const {
        std::optional<BsdfSample> result;
        const float pr = reflection_probability();
        if (wo.z == 0.0f || pr < 0.0f) return result;  // pr < 0: neither side scatters
        Vec3f wi = sample_cosine_hemisphere(u);
        if (wi.z == 0.0f) return result;  // on the disk's rim: in the surface's plane
        const bool reflect = uc < pr;
        // wi on wo's side to reflect, on the other to transmit.
        if ((wo.z < 0.0f) == reflect) wi.z = -wi.z;
        BsdfSample& s = result.emplace();
        s.f = (reflect ? reflectance : transmittance) * kInvPi;
        s.wi = wi;
        s.pdf = (reflect ? pr : 1.0f - pr) * abs_cos_theta(wi) * kInvPi;
        s.is_transmission = !reflect;
        return result;
    }
    static constexpr bool kUsesChoice = true;
    CANDELA_HD bool is_delta() const { return false; }
    CANDELA_HD Color albedo() const { return reflectance + transmittance; }

    // The probability of sampling the reflected side: max(R) / (max(R) + max(T)) (pbrt-v4's
    // pr / (pr + pt)); -1 when both are black.
    CANDELA_HD float reflection_probability() const {
        const float pr = reflectance.max_component(), pt = transmittance.max_component();
        return pr + pt > 0.0f ? pr / (pr + pt) : -1.0f;
    }
};
static_assert(BsdfLobeType<DiffuseTransmissionLobe>);

}  // namespace candela
