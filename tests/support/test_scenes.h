#pragma once
// Small scenes built in code, for tests that must not depend on the scene loader.
#include "candela/geometry/triangle_mesh.h"
#include "candela/scene/scene.h"

namespace candela::test {

// Adds a quad shape with the given material index; returns its shape id.
inline uint32_t add_quad(Scene& scene, Vec3f corner, Vec3f e1, Vec3f e2, uint32_t material = 0) {
    scene.meshes.push_back(make_quad(corner, e1, e2));
    scene.shapes.push_back({ShapeKind::kMesh, uint32_t(scene.meshes.size() - 1), material, {}, false});
    return uint32_t(scene.shapes.size() - 1);
}

inline uint32_t add_sphere(Scene& scene, Vec3d center, double radius, uint32_t material = 0) {
    scene.spheres.push_back({center, radius, false});
    scene.shapes.push_back({ShapeKind::kSphere, uint32_t(scene.spheres.size() - 1), material, {}, false});
    return uint32_t(scene.shapes.size() - 1);
}

// A tiny open box with a sphere inside, seen from the front: enough variety (edges, curvature,
// occlusion) that scheduling bugs would show in the pixels.
inline Scene small_box_scene(int width, int height, int spp) {
    Scene s;
    s.materials = {DiffuseMaterial{Rgb(0.8f, 0.7f, 0.6f)}, DiffuseMaterial{Rgb(0.2f, 0.5f, 0.9f)}};
    s.material_names = {"wall", "ball"};
    add_quad(s, {-1, -1, -1}, {2, 0, 0}, {0, 0, 2});  // floor
    add_quad(s, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0});   // back
    add_quad(s, {-1, -1, -1}, {0, 0, 2}, {0, 2, 0});  // left
    add_sphere(s, {0.3, -0.5, 0.2}, 0.5, 1);
    s.camera.position = {0, 0, -4};
    s.camera.look_at = {0, 0, 0};
    s.camera.fov_degrees = 45;
    s.camera.width = width;
    s.camera.height = height;
    s.sampler.spp = spp;
    s.sampler.seed = 42;
    s.integrator.max_distance = 1.0f;
    return s;
}

}  // namespace candela::test
