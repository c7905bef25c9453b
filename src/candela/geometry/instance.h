#pragma once
// Object instancing (pbrt-v4's ObjectBegin / ObjectEnd / ObjectInstance): an object is a run of the
// scene's shapes kept in object space, built once into its own Embree scene; an instance places it
// in the world by a transform, as one Embree instance geometry. A forest of 10,000 instanced trees
// then holds one tree's triangles and BVH plus a matrix (and Embree's small instance record) per
// tree, instead of 10,000 trees.
//
// A hit on an instance names the object's shape by its scene shape id (so its material is found as
// any shape's) and the instance by its index; the accelerator computes the hit in object space and
// moves it to the world: points and tangents by the transform, normals by its inverse transpose.
// A mirroring transform needs no winding swap: the front normal carried by the inverse transpose
// stays on the side it was on, which is what transform_mesh's swap achieves for a mesh placed
// directly (pbrt-v4's Transform of a SurfaceInteraction does the same).
#include <array>
#include <cstdint>
#include <span>

#include "candela/geometry/shading_geometry.h"
#include "candela/geometry/surface_hit.h"
#include "candela/math/transform.h"

namespace candela {

// An object's shapes: ids first_shape .. first_shape + shape_count - 1 of the scene's shapes, which
// are in object space and are not in the world themselves (only through instances).
struct ObjectShapes {
    uint32_t first_shape = 0;
    uint32_t shape_count = 0;
};

// An affine map as Embree holds an instance's transform: a row-major 3x4 matrix of floats (the
// points that Embree's traversal meets are those of this matrix), applied in double.
struct AffineMap {
    float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    Vec3d apply_point(const Vec3d& p) const {
        return apply_vector(p) + Vec3d(double(m[0][3]), double(m[1][3]), double(m[2][3]));
    }
    Vec3d apply_vector(const Vec3d& v) const {
        Vec3d r;
        for (int i = 0; i < 3; ++i) r[i] = double(m[i][0]) * v.x + double(m[i][1]) * v.y + double(m[i][2]) * v.z;
        return r;
    }
    // The transpose of the linear part times v: with the inverse map, how a normal transforms.
    Vec3d apply_transposed(const Vec3d& v) const {
        Vec3d r;
        for (int i = 0; i < 3; ++i) r[i] = double(m[0][i]) * v.x + double(m[1][i]) * v.y + double(m[2][i]) * v.z;
        return r;
    }
};

// Instance::motion of an instance that stands still.
inline constexpr uint32_t kNoMotion = 0xffffffffu;

// One placement of an object: 104 bytes, a matrix and its inverse in float. (A Transform, in
// double with its inverse, is 256: 10,000 instances of it would cost more than Embree's own
// instance records.)
struct Instance {
    uint32_t object = 0;  // into the scene's objects
    AffineMap to_world;   // object space to world space (a moving instance: at the shutter's opening)
    AffineMap to_object;  // its inverse: normals transform by its transpose
    uint32_t motion = kNoMotion;  // into the scene's instance motions (instance_motion.h), or none
};

// An instance of `object` placed by `to_world`, which must be affine and invertible, with both
// matrices within float range (the scene loader checks).
Instance make_instance(uint32_t object, const Transform& to_world);

struct InstanceMotion;  // instance_motion.h

// What the accelerator needs to build instances; empty for a scene without them. Moving instances
// index `motions`, which the shutter [open, close] maps to Embree's ray times [0, 1].
struct Instancing {
    std::span<const ObjectShapes> objects;
    std::span<const Instance> instances;
    std::span<const InstanceMotion> motions = {};
    std::array<double, 2> shutter{0.0, 1.0};
};

// Moves a hit computed in object space (point, error bound, normals) to world space. The error
// bound covers the object-space bound carried through the matrix and the rounding of the
// transformed point to float.
void hit_to_world(const Instance& instance, SurfaceHit& hit);

// Moves shading geometry computed in object space, where the unit shading normal is `ns`, to world
// space: dpdu and dpdv as vectors; dndu and dndv as the derivatives of the world's unit normal
// normalize(M^-T ns), which is (I - n n^T) M^-T dndu / |M^-T ns| (pbrt-v4 applies M^-T alone,
// which scales them wrongly under a scale).
ShadingGeometry shading_to_world(const Instance& instance, const ShadingGeometry& g, const Vec3f& ns);

}  // namespace candela
