// The `materials` and `shapes` parts of a scene file.
#include <fmt/format.h>

#include <array>
#include <string_view>
#include <vector>

#include "candela/scene/enum_names.h"
#include "candela/scene/mesh_loader.h"
#include "candela/scene/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 5> kMaterialTypes = {"diffuse", "mirror", "dielectric",
                                                          "transmission", "mix"};
// The types a `mix` may combine: every material type but `mix` itself.
constexpr std::array<std::string_view, 4> kLobeMaterialTypes = {"diffuse", "mirror", "dielectric",
                                                              "transmission"};
constexpr std::array<std::string_view, 2> kFresnelNames = {"exact", "schlick"};
constexpr std::array<std::string_view, 3> kShapeTypes = {"mesh", "sphere", "quad"};
// Reflectances above 1 would create energy; negative ones are meaningless.
constexpr Bounds kReflectance = Bounds::closed(0, 1);
// |sin| of the angle between a quad's edges below which it has no usable area or normal.
constexpr double kParallelSine = 1e-6;

std::string format_vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

// A material of one of kLobeMaterialTypes, whose `type` (already read) is `type`.
Material read_single_material(JsonCursor& c, std::string_view type) {
    if (type == "diffuse") {
        Rgb albedo(0.5f);
        if (auto v = c.get("albedo")) albedo = v->colour(kReflectance);
        return make_diffuse(albedo);
    }
    if (type == "mirror") {
        Rgb albedo(1.0f);
        if (auto v = c.get("albedo")) albedo = v->colour(kReflectance);
        return make_mirror(albedo);
    }
    float ior = 1.5f;
    Rgb tint(1.0f);
    if (auto v = c.get("ior")) ior = v->number_f(Bounds::above(0));
    if (auto v = c.get("tint")) tint = v->colour(kReflectance);
    if (type == "transmission") return make_transmission(ior, tint);
    bool schlick = false;
    if (auto v = c.get("fresnel")) schlick = v->choice("fresnel", kFresnelNames) == "schlick";
    return make_dielectric(ior, tint, schlick);
}

// `mix`: 1 to Bsdf::kMaxLobes materials of the other types, their lobes in one material. Mixes do
// not nest, so each part is one lobe and the count bounds the lobes.
Material read_mix(JsonCursor& c) {
    JsonCursor lobes = c.require("lobes");
    std::vector<JsonCursor> parts = lobes.elements();
    if (parts.empty() || parts.size() > Bsdf::kMaxLobes)
        lobes.fail_expected(fmt::format("an array of 1 to {} materials", Bsdf::kMaxLobes));
    std::vector<Material> materials;
    for (JsonCursor& part : parts) {
        JsonCursor type_cursor = part.require("type");
        if (type_cursor.is_string() && type_cursor.string() == "mix")
            type_cursor.fail(fmt::format("a mix cannot contain a mix; expected one of: {}",
                                         names_list(kLobeMaterialTypes)));
        std::string_view type = type_cursor.choice("material type", kLobeMaterialTypes);
        materials.push_back(read_single_material(part, type));
        part.reject_unknown_keys();
    }
    return make_mix(materials);
}

Material read_material(JsonCursor c) {
    std::string_view type = c.require("type").choice("material type", kMaterialTypes);
    Material material = type == "mix" ? read_mix(c) : read_single_material(c, type);
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
