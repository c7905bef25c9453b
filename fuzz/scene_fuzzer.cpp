// libFuzzer target: JSON scene text through load_scene_from_string. The scene's virtual file lies
// in tests/data/scenes/, so the mesh and image files named there (meshes/triangle.obj,
// sky_2x1.hdr, ...) load as they would from a real scene. A SceneError is the expected answer to
// bad input; anything else escaping (a nlohmann exception, std::out_of_range, bad_alloc), a crash,
// a sanitizer report or a scene that breaks the invariants below is a bug.
#include <cmath>
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/json/scene_loader.h"
#include "mesh_invariants.h"

namespace candela::fuzz {
namespace {

// What the renderer indexes without checking: every reference is in range, every mesh valid,
// the camera and sampler usable.
void require_valid_scene(const Scene& scene) {
    require(scene.material_names.size() == scene.materials.size(), "one name per material");
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (const auto& blend = scene.materials[i].blend)
            for (uint32_t part : blend->parts)
                require(part < scene.materials.size() && part != i, "blend parts defined, not the blend itself");
    for (const Shape& shape : scene.shapes) {
        require(shape.material < scene.materials.size(), "shape materials defined");
        const size_t count = shape.kind == ShapeKind::kMesh     ? scene.meshes.size()
                             : shape.kind == ShapeKind::kSphere ? scene.spheres.size()
                                                                : scene.disks.size();
        require(shape.index < count, "shape geometry defined");
        require(shape.emission.is_finite(), "finite emission");
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

}  // namespace
}  // namespace candela::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        candela::fuzz::require_valid_scene(
            candela::load_scene_from_string(text, CANDELA_FUZZ_SCENE_DIR "/fuzz.json"));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
