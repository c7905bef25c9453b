#pragma once
// A point light (pbrt-v4's PointLight): radiant intensity I (W/sr) the same in every direction
// from one position, so a point at distance r receives irradiance I / r^2 on a surface facing it.
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/lights/delta_light_type.h"
#include "candela/math/color.h"
#include "candela/math/constants.h"

namespace candela {

struct PointLight {
    Vec3f position;
    Color intensity;  // W/sr, scale and power applied

    // Power per unit intensity: the full sphere of directions, 4 pi sr (pbrt-v4's PointLight::Phi
    // and its `power` normalization, k_e = 4 pi).
    CANDELA_HD static float power_per_intensity() { return 4.0f * kPi; }

    CANDELA_HD std::optional<DeltaLightSample> sample(const Vec3f& ref) const {
        std::optional<DeltaLightSample> s;
        Vec3f d = position - ref;
        float dist2 = dot(d, d);
        if (!(dist2 > 0.0f)) return s;
        s.emplace(DeltaLightSample{position, d * (1.0f / std::sqrt(dist2)), intensity / dist2, 1.0f / dist2, false});
        return s;
    }
    CANDELA_HD float power(float /*scene_radius*/) const { return power_per_intensity() * to_rgb(intensity).luminance(); }
};
static_assert(DeltaLightType<PointLight>);

}  // namespace candela
