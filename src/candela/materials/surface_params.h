#pragma once
// What a material does to the surface rather than to the light it scatters, on any material
// type: a normal map or a bump map (the shading normal, integrators/shading_frame.h) and alpha (how
// much of the surface is there at all; the accelerator's cutouts, geometry/alpha_cutout.h).
#include <cstdint>
#include <optional>

#include "candela/textures/texture_param.h"

namespace candela {

// Which way a normal map's green channel points: OpenGL's +v (Blender, pbrt, glTF) or DirectX's
// -v (Unreal, 3ds Max).
enum class NormalMapConvention : uint8_t { kOpenGl, kDirectX };

struct SurfaceParams {
    // A tangent-space normal: the colour (r, g, b) is (x, y, z) / 2 + 1/2 in the frame whose x
    // runs along dpdu, y towards +v (kOpenGl) and z along the shading normal.
    std::optional<ColorParam> normal_map;
    NormalMapConvention normal_map_convention = NormalMapConvention::kOpenGl;
    // A height along the shading normal, in scene units (pbrt's displacement).
    std::optional<FloatParam> bump_map;
    // The surface's coverage: rays pass through with probability 1 - alpha.
    FloatParam alpha{1.0f};

    // Whether the shading normal depends on the maps.
    CANDELA_HD bool perturbs_normal() const { return normal_map.has_value() || bump_map.has_value(); }
    // Whether some rays pass through.
    CANDELA_HD bool cuts_out() const { return alpha.is_textured() || alpha.value < 1.0f; }
};

}  // namespace candela
