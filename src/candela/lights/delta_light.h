#pragma once
// The closed set of delta lights (delta_light_type.h): point, spot and directional.
#include <optional>

#include "candela/core/platform.h"
#include "candela/core/variant.h"
#include "candela/lights/directional_light.h"
#include "candela/lights/point_light.h"
#include "candela/lights/spot_light.h"

namespace candela {

using DeltaLight = Variant<PointLight, SpotLight, DirectionalLight>;

CANDELA_HD inline std::optional<DeltaLightSample> sample_delta_light(const DeltaLight& light, const Vec3f& ref) {
    return visit([&](const auto& l) { return l.sample(ref); }, light);
}

// The light's colour: a point or spot light's intensity, a directional light's irradiance.
CANDELA_HD inline Color delta_light_color(const DeltaLight& light) {
    if (const PointLight* p = get_if<PointLight>(&light)) return p->intensity;
    if (const SpotLight* s = get_if<SpotLight>(&light)) return s->intensity;
    return get_if<DirectionalLight>(&light)->irradiance;
}

// Emitted power as luminance (W); scene_radius is the scene's bounding-sphere radius.
CANDELA_HD inline float delta_light_power(const DeltaLight& light, float scene_radius) {
    return visit([&](const auto& l) { return l.power(scene_radius); }, light);
}

}  // namespace candela
