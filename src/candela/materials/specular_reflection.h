#pragma once
// The perfect mirror: all light leaves in the mirrored direction (-wo.x, -wo.y, wo.z), scaled by
// a reflectance. A delta lobe: eval and pdf are 0, sample returns f = reflectance / |cos wi| with
// pdf 1, so its weight f |cos wi| / pdf is the reflectance (pbrt-v3 SpecularReflection with a
// constant Fresnel term).
#include <optional>

#include "candela/materials/bsdf_lobe.h"

namespace candela {

struct SpecularReflectionLobe {
    Color reflectance{1.0f};

    // 0: no two directions chosen independently are mirror images.
    CANDELA_HD Color eval(const Vec3f&, const Vec3f&, TransportMode) const { return Color(0.0f); }
    // 0, as eval.
    CANDELA_HD float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }
    // The mirrored direction, on wo's side (uc and u unused); nullopt for wo in the plane.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float, const Vec2f&,
                                                TransportMode) const {
        if (wo.z == 0.0f) return std::nullopt;
        BsdfSample s;
        s.wi = {-wo.x, -wo.y, wo.z};
        s.f = reflectance / abs_cos_theta(s.wi);
        s.pdf = 1.0f;
        s.is_delta = true;
        return s;
    }
    static constexpr bool kUsesChoice = false;
    CANDELA_HD bool is_delta() const { return true; }
    CANDELA_HD Color albedo() const { return reflectance; }
};
static_assert(BsdfLobeType<SpecularReflectionLobe>);

}  // namespace candela
