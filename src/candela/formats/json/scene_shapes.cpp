// The `shapes` part of a scene file.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include "candela/geometry/disk.h"
#include "candela/scene/enum_names.h"
#include "candela/formats/mesh/mesh_loader.h"
#include "candela/formats/json/scene_sections.h"
#include "candela/formats/json/scene_spectra.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 7> kShapeTypes = {"mesh",   "sphere", "quad",    "disk",
                                                          "cylinder", "curves", "instance"};
// |sin| of the angle between a quad's edges below which it has no usable area or normal.
constexpr double kParallelSine = 1e-6;

std::string format_vec(const Vec3f& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

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

// `disk`: centre, front normal and radius, then the transform (object to world) and
// reverse_orientation. The disk stays in double; what must hold in float is checked here, because
// hits and light samples are float: its bounds within float range and its area above 0.
Disk read_disk(JsonCursor& c, bool reverse_orientation) {
    JsonCursor center = c.require("center"), normal = c.require("normal"), radius = c.require("radius");
    Vec3d n = normal.vec3();
    if (!is_finite(normalize(n))) normal.fail_expected("a nonzero normal");
    double r = radius.number(Bounds::above(0));
    Disk disk = make_round_disk(center.vec3(), n, r);
    std::optional<JsonCursor> transform = c.get("transform");
    Transform to_world;
    if (transform) to_world = read_transform(*transform);
    c.reject_unknown_keys();
    disk = transform_disk(disk, to_world, reverse_orientation);
    const JsonCursor& blame = transform ? *transform : radius;
    // The axes an invertible transform leaves are never parallel, but they may be nearly so.
    const double spanned = length(cross(disk.axis_u, disk.axis_v));
    if (!(spanned > kParallelSine * length(disk.axis_u) * length(disk.axis_v)))
        blame.fail("the transform flattens the disk to a line; it has no area");
    Vec3d half(std::hypot(disk.axis_u.x, disk.axis_v.x), std::hypot(disk.axis_u.y, disk.axis_v.y),
               std::hypot(disk.axis_u.z, disk.axis_v.z));
    if (!is_finite(Vec3f(disk.center - half)) || !is_finite(Vec3f(disk.center + half)))
        blame.fail(transform ? "the transform moves the disk beyond float range"
                             : "the disk reaches beyond float range");
    const auto area = static_cast<float>(disk.area());
    if (!(area > 0.0f) || !std::isfinite(1.0f / area))
        blame.fail(transform ? "the transform leaves the disk with no area in float precision"
                             : "the disk has no area in float precision (its radius is too small)");
    return disk;
}

// What an error calls a clipped quadric.
std::string_view partial_name(std::string_view type) {
    return type == "cylinder" ? "cylinder" : type == "sphere" ? "partial sphere" : "partial disk";
}

// Triangles whose area is zero or not finite in float (repeated or collinear corners, or sizes
// beyond float range, as the transformed mesh has them) cannot be hit and give an emitting mesh
// nothing to sample: they are removed. Returns how many there were and the first one's index.
struct Degenerate {
    size_t count = 0;
    size_t first = 0;
};

Degenerate remove_degenerate_triangles(TriangleMesh& mesh) {
    Degenerate removed;
    size_t kept = 0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        const Vec3f& p0 = mesh.positions[i[0]];
        const float area2 = length_squared(cross(mesh.positions[i[1]] - p0, mesh.positions[i[2]] - p0));
        if (area2 > 0.0f && std::isfinite(area2)) {
            std::copy(i, i + 3, &mesh.indices[3 * kept++]);
        } else if (removed.count++ == 0) {
            removed.first = t;
        }
    }
    mesh.indices.resize(3 * kept);
    return removed;
}

// A mesh file keeps its usable triangles, with a warning (a pbrt or Mitsuba user expects scanned
// and exported meshes to contain a few); with none left it is an error, as an empty file is.
void drop_degenerate_triangles(TriangleMesh& mesh, const JsonCursor& file, Scene& scene) {
    const size_t total = mesh.triangle_count();
    const Degenerate removed = remove_degenerate_triangles(mesh);
    if (removed.count == 0) return;
    if (removed.count == total)
        file.fail(fmt::format("all {} triangles of mesh file {} have zero area (degenerate)", total,
                              json_quoted(file.string())));
    add_warning(scene, file,
                fmt::format("mesh file {}: skipped {} of {} triangles that have zero area (degenerate; "
                            "the first is triangle {})",
                            json_quoted(file.string()), removed.count, total, removed.first + 1));
}

// What loading a mesh file will need, charged before it is built; refused, the error names the
// file (load_referenced adds the scene key).
MeshSizeCheck budget_check(const std::filesystem::path& path, const std::string& name,
                           MemoryBudget& budget) {
    return [&budget, path, name](const MeshSize& size) {
        const std::string what = fmt::format("mesh file {} ({} vertices, {}{} triangles)", json_quoted(name),
                                             size.vertices, size.corners == 0 ? "at least " : "",
                                             size.triangles);
        if (auto refused = budget.charge(mesh_memory_bytes(size.vertices, size.triangles, size.normals, size.uvs),
                                         what, mesh_loading_memory_bytes(size.vertices, size.corners)))
            throw SceneError(SourceLocation{path.string(), 0, 0, {}}, *refused);
    };
}

void read_still_shape(JsonCursor& c, std::string_view type, const ShapeSection& section, Scene& scene,
                      MemoryBudget& budget);

// A shape with a `motion` (motion blur): read as any shape, at its start transform, then made a
// one-shape object and its moving instance (geometry/instance_motion.h). Not an object's shape
// (its instance moves), nor a light (pbrt-v4 refuses animated area lights: its light sampling
// would need the emitter's time), nor cut out (alpha tests see the object's space).
void read_moving_shape(JsonCursor& c, const JsonCursor& motion, std::string_view type, const ShapeSection& section,
                       Scene& scene, MemoryBudget& budget);

void read_shape(JsonCursor c, const ShapeSection& section, Scene& scene, MemoryBudget& budget) {
    JsonCursor type_key = c.require("type");
    std::string_view type = type_key.choice("shape type", kShapeTypes);
    if (type == "instance") {
        if (section.object)
            type_key.fail(fmt::format("object {} cannot hold an instance: objects do not nest (nor do pbrt-v4's); "
                                      "place the instance in the scene's \"shapes\"",
                                      json_quoted(*section.object)));
        read_instance(c, section, scene, budget);
        return;
    }
    if (std::optional<JsonCursor> motion = c.get("motion")) {
        read_moving_shape(c, *motion, type, section, scene, budget);
        return;
    }
    read_still_shape(c, type, section, scene, budget);
}

void read_still_shape(JsonCursor& c, std::string_view type, const ShapeSection& section, Scene& scene,
                      MemoryBudget& budget) {
    Shape shape;
    shape.material = material_index(c.require("material"), scene);
    // The media on its two sides (pbrt-v4's MediumInterface); none by default.
    if (auto v = c.get("interior")) shape.interior = medium_index(*v, scene);
    if (auto v = c.get("exterior")) shape.exterior = medium_index(*v, scene);
    // A subsurface random walk: the shape's interior is its material's medium.
    if (const uint32_t s = scene.materials[shape.material].subsurface;
        s != kNoSubsurface && scene.subsurfaces[s].method == SubsurfaceMethod::kRandomWalk) {
        if (auto v = c.get("interior"))
            v->fail(fmt::format("the material {} is a subsurface random walk: its medium is the shape's interior "
                                "(leave \"interior\" out)",
                                json_quoted(scene.material_names[shape.material])));
        shape.interior = scene.subsurfaces[s].medium;
    }
    std::optional<JsonCursor> emission_scale = c.get("emission_scale");
    if (section.object) {
        // A light must be sampled where it is, once per placement; pbrt-v4 refuses area lights in
        // instances too.
        for (std::string_view key : {"emission", "emission_scale", "two_sided"})
            if (c.has(key))
                c.document().fail_at_key(
                    c.pointer(), key,
                    fmt::format("the shapes of object {} cannot emit: instances are not lights (pbrt-v4 has no area "
                                "lights in instances either); place the light as a shape of \"shapes\"",
                                json_quoted(*section.object)));
    }
    if (auto v = c.get("emission")) {
        // pbrt-v4's area light: its `L` (RGB, or a spectrum normalized to luminance 1) times
        // its `scale`.
        std::optional<LightSpectrum> spectrum = read_light_spectrum(*v, scene.file.parent_path());
        shape.emission = spectrum ? spectrum->rgb : v->colour(Bounds::at_least(0));
        float scale = 1.0f;
        if (emission_scale) {
            scale = emission_scale->number_f(Bounds::above(0));
            shape.emission *= scale;
            if (!shape.emission.is_finite()) emission_scale->fail("the emission overflows float range");
        }
        if (spectrum && !shape.emission.is_black()) {
            spectrum->normalized *= scale;
            shape.emission_spectrum = scene.textures.add_spectrum(spectrum->normalized);
        }
        // Zero is the default, so stating it is likely a light switched off or a mistake.
        if (shape.emission.is_black())
            add_warning(scene, *v,
                        "emission 0: the shape is not a light (leave the key out for a shape that "
                        "does not emit)");
        // Light sampling would count the whole surface while rays pass through its cut-out
        // parts: the two estimates of its light would disagree.
        else if (scene.materials[shape.material].surface.cuts_out())
            v->fail(fmt::format("a light cannot be cut out: its material {} has alpha < 1",
                                json_quoted(scene.material_names[shape.material])));
    } else if (emission_scale) {
        emission_scale->fail("emission_scale without emission: the shape is not a light");
    }
    if (auto v = c.get("two_sided")) shape.two_sided = v->boolean();
    bool reverse_orientation = false;
    if (auto v = c.get("reverse_orientation")) reverse_orientation = v->boolean();

    if (is_partial_quadric(c, type)) {
        // An alpha test would need a cut-out form of the quadrics' intersection; none yet.
        if (scene.materials[shape.material].surface.cuts_out())
            c.require("material").fail(fmt::format("a {} cannot be cut out: material {} has alpha < 1",
                                                   partial_name(type), json_quoted(scene.material_names[shape.material])));
        const Quadric quadric = read_quadric(c, type, reverse_orientation);
        shape.kind = ShapeKind::kQuadric;
        shape.index = static_cast<uint32_t>(scene.quadrics.size());
        scene.quadrics.push_back(quadric);
        scene.shapes.push_back(shape);
        if (section.bounds) section.bounds->add(quadric);
        return;
    }

    if (type == "sphere") {
        // Spheres take no transform: Sphere stores the world-space centre and radius exactly.
        Sphere sphere = read_sphere(c, reverse_orientation);
        c.reject_unknown_keys();
        shape.kind = ShapeKind::kSphere;
        shape.index = static_cast<uint32_t>(scene.spheres.size());
        scene.spheres.push_back(sphere);
        scene.shapes.push_back(shape);
        if (section.bounds) section.bounds->add(sphere);
        return;
    }

    if (type == "curves") {
        read_curves(c, section, scene, budget, shape, reverse_orientation);
        return;
    }

    if (type == "disk") {
        Disk disk = read_disk(c, reverse_orientation);
        shape.kind = ShapeKind::kDisk;
        shape.index = static_cast<uint32_t>(scene.disks.size());
        scene.disks.push_back(disk);
        scene.shapes.push_back(shape);
        if (section.bounds) section.bounds->add(disk);
        return;
    }

    Transform to_world;
    std::optional<JsonCursor> transform = c.get("transform");
    if (transform) to_world = read_transform(*transform, MatrixRows::kProjective);
    TriangleMesh mesh;
    if (type == "quad") {
        std::optional<JsonCursor> edge2 = c.get("edge2");
        mesh = read_quad(c);
        c.reject_unknown_keys();
        transform_mesh(mesh, to_world, reverse_orientation);
        // The edges were checked in double; in float, or scaled by the transform, the area may
        // still vanish (edges of 1e-30 have a product that underflows).
        if (remove_degenerate_triangles(mesh).count > 0)
            (transform ? *transform : *edge2)
                .fail(transform ? "the transform leaves the quad with no area in float precision"
                                : "the quad has no area in float precision (its edges are too short)");
    } else {
        JsonCursor file = c.require("file");
        const MeshStore* meshes = section.meshes;
        const auto stored = meshes ? meshes->find(file.string()) : MeshStore::const_iterator{};
        if (meshes && stored != meshes->end()) {
            c.reject_unknown_keys();
            mesh = stored->second;
            const TriangleMesh& m = stored->second;
            budget_check(file.string(), file.string(), budget)(
                MeshSize{m.positions.size(), m.triangle_count(), 0, !m.normals.empty(), !m.uvs.empty()});
            load_referenced(file, [&] { finish_loaded_mesh(mesh, file.string()); });
        } else {
            std::filesystem::path path = referenced_file(file, section.folder, "mesh");
            // Every key is checked before the (possibly slow) load.
            c.reject_unknown_keys();
            mesh = load_referenced(file, [&] { return load_mesh(path, budget_check(path, file.string(), budget)); });
        }
        if (mesh.triangle_count() == 0)
            file.fail(fmt::format("mesh file {} has no triangles", json_quoted(file.string())));
        transform_mesh(mesh, to_world, reverse_orientation);
        for (size_t i = 0; i < mesh.positions.size(); ++i)
            if (!is_finite(mesh.positions[i]))
                (transform ? *transform : file)
                    .fail(fmt::format("the transform moves vertex {} of mesh file {} beyond float range", i + 1,
                                      json_quoted(file.string())));
        drop_degenerate_triangles(mesh, file, scene);
    }
    shape.kind = ShapeKind::kMesh;
    shape.index = static_cast<uint32_t>(scene.meshes.size());
    if (section.bounds) section.bounds->add(mesh);
    scene.meshes.push_back(std::move(mesh));
    scene.shapes.push_back(shape);
}

void read_moving_shape(JsonCursor& c, const JsonCursor& motion, std::string_view type, const ShapeSection& section,
                       Scene& scene, MemoryBudget& budget) {
    if (section.object)
        motion.fail(fmt::format("a shape of object {} cannot move: give the instances that place it a \"motion\"",
                                json_quoted(*section.object)));
    for (std::string_view key : {"emission", "emission_scale", "two_sided"})
        if (c.has(key))
            c.document().fail_at_key(c.pointer(), key,
                                     "a moving shape cannot emit: animated area lights are not supported (as in "
                                     "pbrt-v4)");
    if (auto m = c.get("material"))
        if (const uint32_t material = material_index(*m, scene); scene.materials[material].surface.cuts_out())
            motion.fail(fmt::format("a moving shape cannot be cut out: its material {} has alpha < 1",
                                    json_quoted(scene.material_names[material])));
    // Its start: the shape's `transform` (a sphere's is its centre and radius), which must be
    // affine for the path to decompose it.
    Transform start;
    const bool placed = type != "sphere" || is_partial_quadric(c, type);  // a whole sphere takes no transform
    if (std::optional<JsonCursor> t = placed ? c.get("transform") : std::nullopt) {
        start = read_transform(*t, MatrixRows::kProjective);
        if (!start.is_affine()) t->fail("a moving shape's transform must be affine (its last row [0, 0, 0, 1])");
    }
    read_still_shape(c, type, section, scene, budget);
    make_shape_move(motion, start, scene);
}

}  // namespace

void read_shapes(const JsonCursor& shapes, const ShapeSection& section, Scene& scene, MemoryBudget& budget) {
    for (const JsonCursor& c : shapes.elements()) read_shape(c, section, scene, budget);
}

}  // namespace candela
