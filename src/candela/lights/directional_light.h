#pragma once
// A directional light (pbrt-v4's DistantLight; the sun): parallel light travelling along one
// direction from infinitely far away, giving irradiance E (W/m^2) to a surface facing it, and
// E cos theta to one tilted by theta. Its power is what crosses the scene: E times the area of
// the disk of the scene's bounding sphere, pi r^2 (pbrt-v4's DistantLight::Phi).
#include <optional>

#include "candela/core/platform.h"
#include "candela/lights/delta_light_type.h"
#include "candela/math/color.h"
#include "candela/math/constants.h"

namespace candela {

struct DirectionalLight {
    Vec3f direction;   // unit, the way the light travels
    Color irradiance;  // W/m^2 on a surface facing the light, scale and power applied

    // Power per unit irradiance in a scene of bounding-sphere radius r: pi r^2.
    CANDELA_HD static float power_per_irradiance(float scene_radius) { return kPi * scene_radius * scene_radius; }

    CANDELA_HD std::optional<DeltaLightSample> sample(const Vec3f& ref) const {
        std::optional<DeltaLightSample> s;
        s.emplace(DeltaLightSample{ref - direction, -direction, irradiance, 1.0f, true});
        return s;
    }
    CANDELA_HD float power(float scene_radius) const {
        return power_per_irradiance(scene_radius) * to_rgb(irradiance).luminance();
    }
};
static_assert(DeltaLightType<DirectionalLight>);

}  // namespace candela
