// The `objects` part of a scene file and the `instance` shapes that place them (pbrt-v4's
// ObjectBegin / ObjectEnd / ObjectInstance; geometry/instance.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "candela/formats/json/scene_sections.h"
#include "candela/scene/memory_budget.h"
#include "candela/scene/enum_names.h"

namespace candela {

namespace {

uint32_t object_index(const JsonCursor& c, const Scene& scene) {
    const std::string name = c.string();
    for (size_t i = 0; i < scene.object_names.size(); ++i)
        if (scene.object_names[i] == name) return static_cast<uint32_t>(i);
    if (scene.object_names.empty())
        c.fail(fmt::format("unknown object {}; no objects are defined (\"objects\" defines them)", json_quoted(name)));
    const std::vector<std::string_view> names(scene.object_names.begin(), scene.object_names.end());
    if (auto hint = closest_name(name, names))
        c.fail(fmt::format("unknown object {} (did you mean {}?)", json_quoted(name), json_quoted(*hint)));
    c.fail(fmt::format("unknown object {}; defined objects: {}", json_quoted(name), names_list(names)));
}

}  // namespace

void ObjectBounds::add(const Vec3d& p) {
    lo = min(lo, p);
    hi = max(hi, p);
}

void ObjectBounds::add(const TriangleMesh& mesh) {
    for (const Vec3f& p : mesh.positions) add(Vec3d(p));
}

void ObjectBounds::add(const Sphere& sphere) {
    add(sphere.center - Vec3d(sphere.radius));
    add(sphere.center + Vec3d(sphere.radius));
}

void ObjectBounds::add(const Disk& disk) {
    const Vec3d half(std::hypot(disk.axis_u.x, disk.axis_v.x), std::hypot(disk.axis_u.y, disk.axis_v.y),
                     std::hypot(disk.axis_u.z, disk.axis_v.z));
    add(disk.center - half);
    add(disk.center + half);
}

void ObjectBounds::add(const Quadric& quadric) {
    Vec3d a, b;
    quadric_world_bounds(quadric, a, b);
    add(a);
    add(b);
}

std::vector<ObjectBounds> read_objects(JsonCursor objects, const std::filesystem::path& folder, Scene& scene,
                                       MemoryBudget& budget, const MeshStore* meshes, const CurveStore* curves) {
    std::vector<ObjectBounds> bounds;
    for (auto& [name, c] : objects.members()) {
        ObjectBounds& b = bounds.emplace_back();
        ShapeSection section{folder, name, &b, {}, meshes, curves};
        ObjectShapes object{static_cast<uint32_t>(scene.shapes.size()), 0};
        read_shapes(c.require("shapes"), section, scene, budget);
        c.reject_unknown_keys();
        object.shape_count = static_cast<uint32_t>(scene.shapes.size()) - object.first_shape;
        scene.objects.push_back(object);
        scene.object_names.push_back(name);
    }
    return bounds;
}

void read_instance(JsonCursor& c, const ShapeSection& section, Scene& scene, MemoryBudget& budget) {
    const uint32_t object = object_index(c.require("object"), scene);
    std::optional<JsonCursor> transform = c.get("transform");
    Transform to_world;
    if (transform) to_world = read_transform(*transform);
    std::optional<JsonCursor> motion = c.get("motion");
    c.reject_unknown_keys();
    Instance instance = make_instance(object, to_world);
    const std::string what = fmt::format("object {}", json_quoted(scene.object_names[object]));
    const ObjectBounds& b = section.objects[object];
    if (transform) check_instance_range(instance, to_world, b, *transform, what);
    if (motion) {
        const AnimatedTransform path = read_motion(*motion, to_world);
        if (path.animated()) {
            check_instance_range(make_instance(object, path.end()), path.end(), b, *motion, what);
            instance = make_instance(object, path.at(scene.camera.shutter[0]));
            instance.motion = static_cast<uint32_t>(scene.instance_motions.size());
            scene.instance_motions.push_back(InstanceMotion{path, Transform()});
        }
    }
    if (auto refused = budget.charge(instance_memory_bytes(), "an instance")) c.fail(*refused);
    scene.instances.push_back(instance);
}

}  // namespace candela
