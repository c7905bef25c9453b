#pragma once
// A thin pane of glass: two parallel smooth interfaces so close that the ray leaves where it
// entered (pbrt-v4's ThinDielectricBxDF). Light bounces between the two faces; summing the
// geometric series of internal reflections, a single face's R and T = 1 - R become
//   R' = R + T^2 R / (1 - R^2),   T' = 1 - R'
// (pbrt-v4), with R the Fresnel reflectance at the incidence angle of either face
// (the inner angle sees the same R, by reciprocity). Transmitted light continues straight along
// -wo: the refractions in and out cancel, so no index ratio is crossed and radiance is not
// scaled. A delta lobe, choosing reflection with probability R'; both sides are alike.
#include <optional>

#include "candela/materials/bsdf_lobe.h"
#include "candela/materials/fresnel.h"

namespace candela {

struct ThinDielectricLobe {
    float eta = 1.5f;  // the pane's index over the surrounding medium's

    // R' for light arriving along wo (either side).
    CANDELA_HD float reflectance(const Vec3f& wo) const {
        float r = fresnel_dielectric(abs_cos_theta(wo), eta);
        if (!(r < 1.0f)) return r;
        float t = 1.0f - r;
        return r + t * t * r / (1.0f - r * r);
    }

    // 0: a delta lobe.
    CANDELA_HD Color eval(const Vec3f&, const Vec3f&, TransportMode) const { return Color(0.0f); }
    // 0: a delta lobe.
    CANDELA_HD float pdf(const Vec3f&, const Vec3f&) const { return 0.0f; }
    // The mirror direction when uc < R', else -wo (u unused); nullopt for wo in the plane.
    CANDELA_HD std::optional<BsdfSample> sample(const Vec3f& wo, float uc, const Vec2f&,
                                                TransportMode) const {
        std::optional<BsdfSample> result;
        if (wo.z == 0.0f) return result;
        float r = reflectance(wo);
        BsdfSample& s = result.emplace();
        s.is_delta = true;
        if (uc < r) {
            s.wi = {-wo.x, -wo.y, wo.z};
            s.f = Color(r / abs_cos_theta(s.wi));
            s.pdf = r;
            return result;
        }
        s.wi = -wo;
        s.f = Color((1.0f - r) / abs_cos_theta(s.wi));
        s.pdf = 1.0f - r;
        s.is_transmission = true;
        return result;
    }
    static constexpr bool kUsesChoice = true;
    CANDELA_HD bool is_delta() const { return true; }
    CANDELA_HD Color albedo() const { return Color(1.0f); }
};
static_assert(BsdfLobeType<ThinDielectricLobe>);

}  // namespace candela
