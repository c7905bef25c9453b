#pragma once
// The material that shades a hit: the shape's own, or where that is a blend (pbrt-v4's `mix`,
// materials/material_blend.h) the part chosen there, chosen again while the part is itself a
// blend (pbrt-v4's loop in SurfaceInteraction::GetBSDF). Blends cannot form a cycle (the scene
// loader refuses one), so the loop ends.
#include <cstdint>
#include <optional>

#include "candela/geometry/accelerator.h"
#include "candela/geometry/surface_hit.h"
#include "candela/materials/material.h"
#include "candela/math/ray.h"
#include "candela/scene/scene.h"

namespace candela {

// The index of the material that shades `hit`, found from the ray that met it, starting at
// material `index`. The surface's uv is asked for only when some amount on the way is a texture.
// Out of line: scenes without blends never call it (PathVertex tests Material::per_hit first).
[[gnu::noinline]] inline uint32_t shading_material_index(const Scene& scene, const Accelerator& accel,
                                                         const SurfaceHit& hit, const Ray& ray, uint32_t index) {
    const Vec3f wo = -ray.d;
    std::optional<Vec2f> uv;
    while (const std::optional<MaterialBlend>& blend = scene.materials[index].blend) {
        TextureContext ctx{Vec2f(), hit.p, nullptr, hit.ng};
        if (blend->amount.is_textured()) {
            if (!uv) uv = accel.uv(hit);
            ctx.uv = *uv;
        }
        index = choose_blend_part(*blend, index, scene.textures, ctx, wo);
    }
    return index;
}

}  // namespace candela
