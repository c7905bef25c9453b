#pragma once
// Small scenes built in code, for tests that must not depend on the scene loader.
#include <cmath>

#include "candela/geometry/triangle_mesh.h"
#include "candela/media/medium_spectrum.h"
#include "candela/scene/scene.h"

namespace candela::test {

// A pixel filter of `type` with its default radius (film/film_settings.h).
inline FilterSettings filter_of(FilterType type) {
    FilterSettings f;
    f.type = type;
    const float r = default_filter_radius(type);
    f.radius = {r, r};
    return f;
}

// Points the scene's camera (up +y) from `position` at `look_at` and sets the image size.
inline void set_camera(Scene& scene, Vec3f position, Vec3f look_at, float fov_degrees, int width, int height) {
    scene.camera.position = position;
    scene.camera.look_at = look_at;
    scene.camera.fov_degrees = fov_degrees;
    scene.camera.width = width;
    scene.camera.height = height;
}

// Adds a quad shape with the given material index; returns its shape id.
inline uint32_t add_quad(Scene& scene, Vec3f corner, Vec3f e1, Vec3f e2, uint32_t material = 0) {
    scene.meshes.push_back(make_quad(corner, e1, e2));
    scene.shapes.push_back({ShapeKind::kMesh, uint32_t(scene.meshes.size() - 1), material, {}, false});
    return uint32_t(scene.shapes.size() - 1);
}

// Adds a sphere; reverse_orientation makes its inside the front side.
inline uint32_t add_sphere(Scene& scene, Vec3d center, double radius, uint32_t material = 0,
                           bool reverse_orientation = false) {
    scene.spheres.push_back({center, radius, reverse_orientation});
    scene.shapes.push_back({ShapeKind::kSphere, uint32_t(scene.spheres.size() - 1), material, {}, false});
    return uint32_t(scene.shapes.size() - 1);
}

// A tiny open box with a sphere inside, seen from the front: enough variety (edges, curvature,
// occlusion) that scheduling bugs would show in the pixels.
inline Scene small_box_scene(int width, int height, int spp) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.8f, 0.7f, 0.6f)), make_diffuse(Rgb(0.2f, 0.5f, 0.9f))};
    s.material_names = {"wall", "ball"};
    add_quad(s, {-1, -1, -1}, {2, 0, 0}, {0, 0, 2});  // floor
    add_quad(s, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0});   // back
    add_quad(s, {-1, -1, -1}, {0, 0, 2}, {0, 2, 0});  // left
    add_sphere(s, {0.3, -0.5, 0.2}, 0.5, 1);
    set_camera(s, Vec3f{0, 0, -4}, Vec3f{0, 0, 0}, 45, width, height);
    s.sampler.spp = spp;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 42;
    s.integrator.max_distance = 1.0f;
    return s;
}

// Makes shape `shape` a diffuse area light of radiance `emission`.
inline void set_emission(Scene& scene, uint32_t shape, Rgb emission, bool two_sided = false) {
    scene.shapes[shape].emission = emission;
    scene.shapes[shape].two_sided = two_sided;
}

// Adds a box standing on its bottom face (which is left out: it would lie on the floor), rotated
// by `degrees` about the vertical axis through `center`; faces point outwards.
inline void add_box(Scene& scene, Vec3f center, Vec3f half, float degrees, uint32_t material) {
    const float c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    auto rotate = [&](Vec3f v) { return Vec3f(v.x * c + v.z * s, v.y, -v.x * s + v.z * c); };
    auto face = [&](Vec3f corner, Vec3f e1, Vec3f e2) {
        add_quad(scene, center + rotate(corner * half), rotate(e1 * half), rotate(e2 * half), material);
    };
    // Corners and edges on the unit cube [-1, 1]^3, scaled by `half`; cross(e1, e2) points out.
    face({-1, 1, -1}, {0, 0, 2}, {2, 0, 0});    // top, +y
    face({-1, -1, -1}, {0, 2, 0}, {2, 0, 0});   // front, -z
    face({-1, -1, 1}, {2, 0, 0}, {0, 2, 0});    // back, +z
    face({-1, -1, -1}, {0, 0, 2}, {0, 2, 0});   // left, -x
    face({1, -1, -1}, {0, 2, 0}, {0, 0, 2});    // right, +x
}

// Material indices of cornell_box_scene.
inline constexpr uint32_t kCornellWhite = 0, kCornellRed = 1, kCornellGreen = 2, kCornellBlack = 3,
                          kCornellMirror = 4, kCornellGlass = 5;

// The Cornell box walls in [-1, 1]^3, open towards the camera at -z, lit by a one-sided square
// light facing down just below the ceiling (black, so it reflects nothing); no objects inside.
// The integrator settings are the defaults (max_depth 64, throughput roulette after 3 bounces).
inline Scene cornell_walls_scene(int width, int height, int spp) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.75f, 0.73f, 0.70f)), make_diffuse(Rgb(0.63f, 0.07f, 0.05f)),
                   make_diffuse(Rgb(0.14f, 0.45f, 0.09f)), make_diffuse(Rgb(0.0f)),
                   make_mirror(Rgb(0.95f)),                 make_dielectric(1.5f)};
    s.material_names = {"white", "red", "green", "black", "mirror", "glass"};
    add_quad(s, {-1, -1, -1}, {0, 0, 2}, {2, 0, 0}, kCornellWhite);  // floor, +y
    add_quad(s, {-1, 1, -1}, {2, 0, 0}, {0, 0, 2}, kCornellWhite);   // ceiling, -y
    add_quad(s, {-1, -1, 1}, {0, 2, 0}, {2, 0, 0}, kCornellWhite);   // back, -z
    add_quad(s, {-1, -1, -1}, {0, 2, 0}, {0, 0, 2}, kCornellRed);    // left, +x
    add_quad(s, {1, -1, -1}, {0, 0, 2}, {0, 2, 0}, kCornellGreen);   // right, -x
    // A quarter of the ceiling: large, so that BSDF sampling alone finds it often enough for the
    // agreement tests to reach their precision in seconds.
    uint32_t light = add_quad(s, {-0.5f, 0.98f, -0.5f}, {1, 0, 0}, {0, 0, 1}, kCornellBlack);  // -y
    set_emission(s, light, Rgb(4.0f, 3.2f, 2.4f));
    set_camera(s, Vec3f{0, 0, -3.6f}, Vec3f{0, 0, 0}, 38, width, height);
    s.sampler.spp = spp;
    s.sampler.type = SamplerType::kIndependent;  // the z-tests need independent samples
    s.sampler.seed = 7;
    return s;
}

// The Cornell box with its two diffuse boxes (short and tall), all surfaces diffuse.
inline Scene cornell_box_scene(int width, int height, int spp) {
    Scene s = cornell_walls_scene(width, height, spp);
    add_box(s, {0.35f, -0.7f, -0.3f}, {0.3f, 0.3f, 0.3f}, -17.0f, kCornellWhite);
    add_box(s, {-0.35f, -0.4f, 0.35f}, {0.3f, 0.6f, 0.3f}, 20.0f, kCornellWhite);
    return s;
}

// The Cornell box with a mirror sphere and a glass sphere (index 1.5) on the floor.
inline Scene cornell_glass_scene(int width, int height, int spp) {
    Scene s = cornell_walls_scene(width, height, spp);
    add_sphere(s, {-0.45, -0.6, 0.35}, 0.4, kCornellMirror);
    add_sphere(s, {0.45, -0.6, -0.2}, 0.4, kCornellGlass);
    return s;
}

// small_box_scene with a one-sided square light over the box and a mirror ball: every light
// transport integrator has direct light, indirect light and a delta bounce to compute.
inline Scene lit_small_box_scene(int width, int height, int spp) {
    Scene s = small_box_scene(width, height, spp);
    s.materials.push_back(make_mirror(Rgb(0.9f)));
    s.materials.push_back(make_diffuse(Rgb(0.0f)));
    s.material_names.push_back("mirror");
    s.material_names.push_back("black");
    add_sphere(s, {-0.5, -0.7, -0.4}, 0.3, 2);
    uint32_t light = add_quad(s, {-0.4f, 0.9f, -0.4f}, {0.8f, 0, 0}, {0, 0, 0.8f}, 3);  // faces -y
    set_emission(s, light, Rgb(6.0f, 5.0f, 4.0f));
    return s;
}

// lit_small_box_scene filled with fog (the camera in it), with a sphere of chromatic, emitting
// smoke behind an interface, rendered by volpath: every branch of its loop runs (null collisions,
// scattering, absorption, emission, interfaces, shadow rays through media).
inline Scene media_small_box_scene(int width, int height, int spp) {
    Scene s = lit_small_box_scene(width, height, spp);
    HomogeneousMedium fog;
    fog.sigma_a = medium_coefficient(Rgb(0.05f));
    fog.sigma_s = medium_coefficient(Rgb(0.4f));
    fog.g = 0.3f;
    HomogeneousMedium smoke;
    smoke.sigma_a = medium_coefficient(Rgb(0.5f, 1.0f, 2.0f));
    smoke.sigma_s = medium_coefficient(Rgb(3.0f, 2.0f, 1.0f));
    smoke.Le = medium_emission(Rgb(0.5f, 0.2f, 0.1f));
    smoke.emissive = true;
    smoke.g = -0.2f;
    s.media = {fog, smoke};
    s.medium_names = {"fog", "smoke"};
    s.camera_medium = 0;
    Material boundary = make_material(TransmissionParams{1.0f, ColorParam{Rgb(1.0f)}});
    boundary.interface = true;
    s.materials.push_back(boundary);
    s.material_names.push_back("boundary");
    const uint32_t sphere = add_sphere(s, {0.4, -0.5, 0.2}, 0.45, uint32_t(s.materials.size() - 1));
    s.shapes[sphere].interior = 1;
    s.shapes[sphere].exterior = 0;
    s.integrator.type = IntegratorType::kVolPath;
    return s;
}

}  // namespace candela::test
