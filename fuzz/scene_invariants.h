#pragma once
// What every Scene a loader returns must satisfy, whatever the file said (the scene and pbrt
// targets check it): the renderer indexes these without further checks.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "candela/scene/scene.h"
#include "mesh_invariants.h"

namespace candela::fuzz {

// How many geometries of a shape kind the scene holds. A switch without a default, so that a
// new kind is a compiler warning here rather than a false "undefined geometry" report.
inline size_t geometry_count(const Scene& scene, ShapeKind kind) {
    switch (kind) {
    case ShapeKind::kMesh: return scene.meshes.size();
    case ShapeKind::kSphere: return scene.spheres.size();
    case ShapeKind::kDisk: return scene.disks.size();
    case ShapeKind::kCurves: return scene.curves.size();
    case ShapeKind::kQuadric: return scene.quadrics.size();
    }
    return 0;
}

// What the renderer indexes without checking: every reference is in range, every mesh valid,
// the camera and sampler usable.
inline void require_valid_scene(const Scene& scene) {
    require(scene.material_names.size() == scene.materials.size(), "one name per material");
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (const auto& blend = scene.materials[i].blend)
            for (uint32_t part : blend->parts)
                require(part < scene.materials.size() && part != i, "blend parts defined, not the blend itself");
    for (const Shape& shape : scene.shapes) {
        require(shape.material < scene.materials.size(), "shape materials defined");
        require(shape.index < geometry_count(scene, shape.kind), "shape geometry defined");
        require(shape.emission.is_finite(), "finite emission");
        require(shape.kind != ShapeKind::kCurves || shape.emission.is_black(), "curves do not emit");
    }
    require(scene.object_names.size() == scene.objects.size(), "one name per object");
    for (const ObjectShapes& object : scene.objects) {
        require(size_t(object.first_shape) + object.shape_count <= scene.shapes.size(), "object shapes defined");
        for (uint32_t k = 0; k < object.shape_count; ++k)
            require(scene.shapes[object.first_shape + k].emission.is_black(), "objects do not emit");
    }
    for (const Instance& instance : scene.instances) {
        require(instance.object < scene.objects.size(), "instance objects defined");
        for (const AffineMap* map : {&instance.to_world, &instance.to_object})
            for (const auto& row : map->m)
                for (float v : row) require(std::isfinite(v), "finite instance matrices");
    }
    for (const TriangleMesh& mesh : scene.meshes) {
        require_valid_mesh(mesh);
        for (const Vec3f& p : mesh.positions) require(is_finite(p), "finite vertex positions");
    }
    for (const Sphere& sphere : scene.spheres)
        require(is_finite(sphere.center) && std::isfinite(sphere.radius) && sphere.radius > 0, "valid spheres");
    for (const Disk& disk : scene.disks)
        require(is_finite(disk.center) && is_finite(disk.axis_u) && is_finite(disk.axis_v) && is_finite(disk.normal) &&
                    disk.area() > 0 && std::isfinite(disk.area()),
                "valid disks");
    for (const Quadric& quadric : scene.quadrics) {
        require(std::isfinite(quadric.radius) && quadric.radius > 0 && quadric.phi_max > 0 &&
                    quadric.phi_max <= 2 * std::numbers::pi,
                "quadrics with a radius and a phi range");
        require(std::isfinite(quadric.object_area()) && quadric.object_area() > 0, "quadrics with area");
        for (const Transform* map : {&quadric.to_world, &quadric.to_object})
            for (const auto& row : map->matrix())
                for (double v : row) require(std::isfinite(v), "finite quadric transforms");
    }
    for (const CurveSet& curves : scene.curves) {
        for (uint32_t first : curves.segments) require(size_t(first) + 4 <= curves.points.size(), "curve segments defined");
        for (const CurvePoint& c : curves.points)
            require(is_finite(c.p) && std::isfinite(c.r) && c.r >= 0, "finite curve points and radii");
        require(curves.type != CurveType::kRibbon || curves.normals.size() == curves.points.size(),
                "a normal per ribbon control point");
    }
    require(scene.camera.width >= 1 && scene.camera.height >= 1, "a camera with pixels");
    require(scene.sampler.spp >= 1, "at least one sample per pixel");
    require(scene.integrator.max_depth >= 1, "a positive max_depth");
    if (scene.environment) {
        const Image& map = scene.environment->radiance;
        require(map.width > 0 && map.height > 0 && map.pixels.size() == size_t(map.width) * size_t(map.height),
                "an environment map with pixels");
        for (const Rgb& p : map.pixels) require(p.is_finite(), "a finite environment map");
    }
}

}  // namespace candela::fuzz
