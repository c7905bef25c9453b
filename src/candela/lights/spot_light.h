#pragma once
// A spot light (pbrt-v4's SpotLight): a point light whose intensity fades from I on its axis to 0
// at the cone's half-angle. Inside cos_falloff_start (the angle cone_angle - cone_delta) the
// intensity is I; between that and cos_falloff_end (cone_angle) it falls off as the smoothstep of
// cos theta, s(t) = t^2 (3 - 2t) with t = (cos theta - cos_end) / (cos_start - cos_end); beyond,
// nothing. With cone_delta 0 the edge is hard.
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/lights/delta_light_type.h"
#include "candela/math/color.h"
#include "candela/math/constants.h"

namespace candela {

// pbrt-v4's SmoothStep(x, a, b): 0 below a, 1 above b, t^2 (3 - 2t) between; a step at a when
// a == b.
CANDELA_HD inline float smooth_step(float x, float a, float b) {
    if (a == b) return x < a ? 0.0f : 1.0f;
    float t = clamp((x - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct SpotLight {
    Vec3f position;
    Vec3f axis;        // unit, the direction the cone points to
    Color intensity;   // W/sr on the axis, scale and power applied
    float cos_falloff_start = 1.0f;  // cos(cone_angle - cone_delta): full intensity inside
    float cos_falloff_end = 0.0f;    // cos(cone_angle): no light outside

    // Power per unit axial intensity: 2 pi ((1 - cos_start) + (cos_start - cos_end) / 2), the
    // full cone plus the smoothstep's integral over the falloff, which is exactly half its width
    // in cos theta (pbrt-v4's SpotLight::Phi and its `power` normalization k_e).
    CANDELA_HD static float power_per_intensity(float cos_start, float cos_end) {
        return 2.0f * kPi * ((1.0f - cos_start) + (cos_start - cos_end) * 0.5f);
    }
    // The fraction of the axial intensity sent at angle theta from the axis.
    CANDELA_HD float falloff(float cos_theta) const {
        return smooth_step(cos_theta, cos_falloff_end, cos_falloff_start);
    }

    CANDELA_HD std::optional<DeltaLightSample> sample(const Vec3f& ref) const {
        std::optional<DeltaLightSample> s;
        Vec3f d = position - ref;
        float dist2 = dot(d, d);
        if (!(dist2 > 0.0f)) return s;
        Vec3f wi = d * (1.0f / std::sqrt(dist2));
        float f = falloff(dot(-wi, axis));
        if (f == 0.0f) return s;  // outside the cone (pbrt-v4 returns no sample there either)
        s.emplace(DeltaLightSample{position, wi, intensity * (f / dist2), f / dist2, false});
        return s;
    }
    CANDELA_HD float power(float /*scene_radius*/) const {
        return power_per_intensity(cos_falloff_start, cos_falloff_end) * to_rgb(intensity).luminance();
    }
};
static_assert(DeltaLightType<SpotLight>);

}  // namespace candela
