#pragma once
// Ray traversal: one Embree 3 scene over all shapes. Triangle meshes are native Embree triangles;
// spheres and disks are user geometry with candela's precise intersection (sphere_intersection.h,
// disk_intersection.h), and so are the clipped quadrics (quadric_intersection.h); curves are Embree's Bezier curves (curves.h, curve_hit.h). Shape i
// of the scene is Embree geometry i, so hits name the shape directly. Objects (instance.h) are
// Embree scenes of their own, built once, and instance j is the top-level Embree instance geometry
// shapes.size() + j; a hit through it names the object's shape and the instance. Embree stays out
// of this header so that only accelerator.cpp compiles against it.
#include <memory>
#include <optional>
#include <span>
#include <utility>

#include "candela/geometry/alpha_cutout.h"
#include "candela/geometry/curves.h"
#include "candela/geometry/disk.h"
#include "candela/geometry/instance.h"
#include "candela/geometry/quadric.h"
#include "candela/geometry/shading_geometry.h"
#include "candela/geometry/shape.h"
#include "candela/geometry/sphere.h"
#include "candela/geometry/surface_hit.h"
#include "candela/geometry/triangle_mesh.h"
#include "candela/math/bounds.h"
#include "candela/math/ray.h"

struct RTCSceneTy;  // Embree's scene handle (RTCScene), for benchmarks that trace it directly

namespace candela {

// Sees every query the accelerator answers, after answering it: bench/record_rays.cpp records
// the renderer's own rays this way. Called from every render thread, so it must be thread-safe.
class RayObserver {
  public:
    // `occlusion`: an occluded() query (else intersect()); `hit`: it found something.
    virtual void observe(const Ray& ray, bool occlusion, bool hit) = 0;

  protected:
    ~RayObserver() = default;
};

// Installs `observer` for all accelerators and threads (null: off, the default; off costs one
// relaxed atomic load and a branch per query). Not for use while a render is running.
void set_ray_observer(RayObserver* observer);

// Meshes of up to this many triangles keep a table of their winding normals (12 B a triangle),
// which hits read instead of normalizing a cross product: a shorter chain from Embree's answer to
// the next ray while the table sits in cache (1.7% of a Cornell box render), and no gain on the
// 870k-triangle dragon, whose table would miss the cache as often as its vertices do
// (bench/RESULTS.md).
inline constexpr size_t kMaxTrianglesWithNormalTable = size_t(1) << 16;

class Accelerator {
  public:
    // The spans must outlive the accelerator: hits read vertex data from them. Shapes that
    // `cutouts` cuts out let rays through where their alpha says (alpha_cutout.h). The shapes of
    // `instancing`'s objects are in object space and in the world only through its instances.
    Accelerator(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres,
                std::span<const Disk> disks, std::span<const Shape> shapes, AlphaCutouts cutouts = {},
                Instancing instancing = {}, std::span<const CurveSet> curves = {},
                std::span<const Quadric> quadrics = {});
    // A scene without disks.
    Accelerator(std::span<const TriangleMesh> meshes, std::span<const Sphere> spheres,
                std::span<const Shape> shapes, AlphaCutouts cutouts = {})
        : Accelerator(meshes, spheres, {}, shapes, std::move(cutouts)) {}
    ~Accelerator();
    Accelerator(const Accelerator&) = delete;
    Accelerator& operator=(const Accelerator&) = delete;

    // The closest hit with ray.tmin <= t <= ray.tmax. Thread-safe.
    std::optional<SurfaceHit> intersect(const Ray& ray) const;
    // The surface parameterisation (u, v) at a hit this accelerator returned: the mesh's vertex
    // uvs interpolated (a quad's (s, t)), or the barycentrics (b1, b2) for meshes without uvs; on
    // spheres pbrt's, u = phi / 2pi, v = 1 - theta / pi about +y (shading_geometry.h); on disks
    // pbrt's, u = phi / 2pi, v = 1 - r / radius (disk.h); on cylinders, partial spheres and partial
    // disks pbrt-v4's (quadric_intersection.h); on curves pbrt's, u along the segment
    // and v across it (curves.h).
    Vec2f uv(const SurfaceHit& hit) const;
    // The uv and the derivatives of point and shading normal at a hit (shading_geometry.h):
    // for materials with a tangent frame, normal map or bump map only, so computed on request.
    ShadingGeometry shading(const SurfaceHit& hit) const;
    // Whether anything lies on the ray within [tmin, tmax] (shadow rays). Thread-safe.
    bool occluded(const Ray& ray) const;
    // World bounds of all shapes.
    Bounds3f bounds() const;
    // The Embree scene, built with the flags above, for benchmarks of Embree alone.
    RTCSceneTy* embree_scene() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Call once in every thread that traces rays: Embree is faster, and its results are the same,
// with denormals flushed to zero (Embree's documentation asks for FTZ and DAZ).
void enable_flush_denormals();

}  // namespace candela
