// The `materials` and `shapes` parts of a scene file.
#include <fmt/format.h>

#include <array>

#include "candela/scene/enum_names.h"
#include "candela/scene/mesh_loader.h"
#include "candela/scene/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 3> kMaterialTypes = {"diffuse", "mirror", "dielectric"};
constexpr std::array<std::string_view, 3> kShapeTypes = {"mesh", "sphere", "quad"};
// Reflectances above 1 would create energy; negative ones are meaningless.
constexpr Bounds kReflectance = Bounds::closed(0, 1);
// |sin| of the angle between a quad's edges below which it has no usable area or normal.
constexpr double kParallelSine = 1e-6;

std::string format_vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

Material read_material(JsonCursor c) {
    std::string_view type = c.require("type").choice("material type", kMaterialTypes);
    Material material;
    if (type == "diffuse") {
        DiffuseMaterial d;
        if (auto v = c.get("albedo")) d.albedo = v->colour(kReflectance);
        material = d;
    } else if (type == "mirror") {
        MirrorMaterial m;
        if (auto v = c.get("albedo")) m.albedo = v->colour(kReflectance);
        material = m;
    } else {
        DielectricMaterial d;
        if (auto v = c.get("ior")) d.ior = v->number_f(Bounds::above(0));
        if (auto v = c.get("tint")) d.tint = v->colour(kReflectance);
        material = d;
    }
    c.reject_unknown_keys();
    return material;
}

uint32_t material_index(const JsonCursor& c, const Scene& scene) {
    std::string name = c.string();
    for (size_t i = 0; i < scene.material_names.size(); ++i)
        if (scene.material_names[i] == name) return static_cast<uint32_t>(i);
    if (scene.material_names.empty())
        c.fail(fmt::format("unknown material {}; no materials are defined", json_quoted(name)));
    std::vector<std::string_view> names(scene.material_names.begin(), scene.material_names.end());
    c.fail(fmt::format("unknown material {}; defined materials: {}", json_quoted(name),
                       names_list(names)));
}

Sphere read_sphere(JsonCursor& c, bool reverse_orientation) {
    Sphere s;
    s.center = c.require("center").vec3();
    s.radius = c.require("radius").number(Bounds::above(0));
    s.reverse_orientation = reverse_orientation;
    return s;
}

TriangleMesh read_quad(JsonCursor& c) {
    JsonCursor corner = c.require("corner"), edge1 = c.require("edge1"), edge2 = c.require("edge2");
    Vec3f p = corner.vec3f(), e1 = edge1.vec3f(), e2 = edge2.vec3f();
    if (e1 == Vec3f(0.0f)) edge1.fail_expected("a nonzero edge");
    if (e2 == Vec3f(0.0f)) edge2.fail_expected("a nonzero edge");
    Vec3d d1(e1), d2(e2);
    if (!(length(cross(d1, d2)) > kParallelSine * length(d1) * length(d2)))
        edge2.fail(fmt::format("edge2 {} is parallel to edge1 {}; the quad has no area",
                               format_vec(e2), format_vec(e1)));
    return make_quad(p, e1, e2);
}

void read_shape(JsonCursor c, const std::filesystem::path& folder, Scene& scene) {
    std::string_view type = c.require("type").choice("shape type", kShapeTypes);
    Shape shape;
    shape.material = material_index(c.require("material"), scene);
    if (auto v = c.get("emission")) shape.emission = v->colour(Bounds::at_least(0));
    if (auto v = c.get("two_sided")) shape.two_sided = v->boolean();
    bool reverse_orientation = false;
    if (auto v = c.get("reverse_orientation")) reverse_orientation = v->boolean();

    if (type == "sphere") {
        // Spheres take no transform: Sphere stores the world-space centre and radius exactly.
        Sphere sphere = read_sphere(c, reverse_orientation);
        c.reject_unknown_keys();
        shape.kind = ShapeKind::kSphere;
        shape.index = static_cast<uint32_t>(scene.spheres.size());
        scene.spheres.push_back(sphere);
        scene.shapes.push_back(shape);
        return;
    }

    Transform to_world;
    if (auto v = c.get("transform")) to_world = read_transform(*v);
    TriangleMesh mesh;
    if (type == "quad") {
        mesh = read_quad(c);
        c.reject_unknown_keys();
    } else {
        JsonCursor file = c.require("file");
        std::filesystem::path path = referenced_file(file, folder, "mesh");
        // Every key is checked before the (possibly slow) load.
        c.reject_unknown_keys();
        mesh = load_referenced(file, [&] { return load_mesh(path); });
        if (mesh.triangle_count() == 0)
            file.fail(fmt::format("mesh file {} has no triangles", json_quoted(file.string())));
    }
    transform_mesh(mesh, to_world, reverse_orientation);
    shape.kind = ShapeKind::kMesh;
    shape.index = static_cast<uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.shapes.push_back(shape);
}

}  // namespace

void read_materials(JsonCursor materials, Scene& scene) {
    for (auto& [name, c] : materials.members()) {
        scene.materials.push_back(read_material(c));
        scene.material_names.push_back(name);
    }
}

void read_shapes(const JsonCursor& shapes, const std::filesystem::path& folder, Scene& scene) {
    for (const JsonCursor& c : shapes.elements()) read_shape(c, folder, scene);
}

}  // namespace candela
