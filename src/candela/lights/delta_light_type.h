#pragma once
// What every delta light provides (point, spot, directional; lights/delta_light.h holds the closed
// set), checked at each light's definition (STYLE.md). A delta light occupies no area or solid
// angle: no ray can hit it, so only next-event estimation finds it, with a light sample that is
// certain (a "pdf" of 1 given the light). Its sample carries the irradiance it would give a
// surface facing it, and integrators weight it 1 in multiple importance sampling (pbrt-v4's
// LightType::DeltaPosition and DeltaDirection).
#include <concepts>
#include <optional>

#include "candela/math/color.h"
#include "candela/math/vec.h"

namespace candela {

// The light a delta light sends to a reference point.
struct DeltaLightSample {
    Vec3f p;        // the light's position; for a directional light, ref + wi (it is infinitely far)
    Vec3f wi;       // unit, from the reference point towards the light
    Color Li;       // irradiance at ref on a surface facing the light (W/m^2): I / r^2, or E
    float factor;   // Li over the light's colour (1 / r^2 times a spot's falloff; 1): spectral
                    // mode multiplies the colour's spectrum by it
    bool infinite;  // a directional light: a shadow ray towards it runs to infinity
};

template <class T>
concept DeltaLightType = requires(const T& light, Vec3f ref, float scene_radius) {
    // The light arriving at ref; nullopt where none does (outside a spot's cone, or ref at the
    // light's position).
    { light.sample(ref) } -> std::same_as<std::optional<DeltaLightSample>>;
    // Emitted power as luminance (W), for light selection by power; a directional light's
    // depends on the scene's bounding-sphere radius.
    { light.power(scene_radius) } -> std::same_as<float>;
};

}  // namespace candela
