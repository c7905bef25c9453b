#pragma once
// What a ray hit, in world space (a hit on an instanced object too: geometry/instance.h).
#include <cstdint>

#include "candela/math/ray.h"
#include "candela/math/vec.h"

namespace candela {

struct SurfaceHit {
    float t = 0;       // ray parameter of the hit
    Vec3f p;           // the point, computed on the surface (not o + t d) so it is accurate
    Vec3f p_error;     // per-axis bound on |p - true point| (ray_offset.h uses it); never 0
                       // for a non-degenerate shape
    Vec3f ng;          // unit geometric normal on the shape's front side
    Vec3f ns;          // unit shading normal (interpolated vertex normal, or ng), same side as ng
    Vec2f b;           // barycentrics (b1, b2) of p in triangle prim_id; (0, 0) on spheres and
                       // disks. Accelerator::uv turns them into the surface's (u, v) on demand:
                       // most hits never need it, and a sphere's costs an atan2 and an acos
    uint32_t shape_id = 0;
    uint32_t prim_id = 0;  // triangle index within the mesh; 0 for spheres and disks
    uint32_t instance = 0; // for a shape of an object (geometry/instance.h), which the ray met
                           // through an instance: that instance's index; 0 for other shapes
    float time = 0;        // the ray's time: rays spawned here keep it, a moving instance is
                           // placed at it (geometry/instance_motion.h)

    // True when the ray came from the front side.
    bool front_face(const Vec3f& ray_dir) const { return dot(ray_dir, ng) < 0.0f; }
};

}  // namespace candela
