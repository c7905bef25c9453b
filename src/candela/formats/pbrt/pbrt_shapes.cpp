// pbrt-v4's shapes as candela's (docs/SCENE_FORMAT.md, "shapes"): triangle meshes (inline ones go
// to the mesh store), PLY meshes by file, spheres, disks; each with the graphics state's material,
// area light, orientation and transform. pbrt's orientation rule (the geometric normal flips when
// ReverseOrientation or a mirroring transform, not both) is candela's too.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "candela/formats/mesh/mesh_loader.h"
#include "candela/geometry/bilinear_patches.h"
#include "candela/geometry/loop_subdivision.h"
#include "candela/formats/pbrt/pbrt_import_context.h"
#include "candela/math/constants.h"

namespace candela::pbrt {
namespace {

// True when t is a rotation, a uniform scale and a translation (a sphere stays a sphere); its
// scale factor in `s`.
bool is_similarity(const Transform& t, double& s) {
    const Vec3d x = t.apply_vector(Vec3d(1, 0, 0)), y = t.apply_vector(Vec3d(0, 1, 0)),
                z = t.apply_vector(Vec3d(0, 0, 1));
    s = length(x);
    const double tol = 1e-6 * s;
    return std::fabs(length(y) - s) <= tol && std::fabs(length(z) - s) <= tol && std::fabs(dot(x, y)) <= tol * s &&
           std::fabs(dot(y, z)) <= tol * s && std::fabs(dot(x, z)) <= tol * s;
}

double mesh_area(const TriangleMesh& mesh, const Transform& to_world) {
    double area = 0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const Vec3d p0 = to_world.apply_point(Vec3d(mesh.positions[mesh.indices[3 * t]]));
        const Vec3d p1 = to_world.apply_point(Vec3d(mesh.positions[mesh.indices[3 * t + 1]]));
        const Vec3d p2 = to_world.apply_point(Vec3d(mesh.positions[mesh.indices[3 * t + 2]]));
        area += 0.5 * length(cross(p1 - p0, p2 - p0));
    }
    return area;
}

TriangleMesh read_triangle_mesh(const Params& p) {
    const Parameter* P = p.find("P");
    if (!P) p.fail(nullptr, "trianglemesh: \"point3 P\" is required");
    const std::vector<double> positions = p.numbers("P", 3);
    const size_t n = positions.size() / 3;
    std::vector<double> indices = p.numbers("indices", 3);
    if (indices.empty()) {
        if (n != 3) p.fail(P, "trianglemesh: \"integer indices\" is required unless P holds exactly 3 points");
        indices = {0, 1, 2};
    }
    TriangleMesh mesh;
    mesh.positions.reserve(n);
    for (size_t i = 0; i < n; ++i)
        mesh.positions.emplace_back(float(positions[3 * i]), float(positions[3 * i + 1]), float(positions[3 * i + 2]));
    const Parameter* I = p.find("indices");
    mesh.indices.reserve(indices.size());
    for (double v : indices) {
        if (!(v >= 0 && v < double(n)) || v != std::floor(v))
            p.fail(I, fmt::format("trianglemesh: index {} is out of range (P has {} points)", v, n));
        mesh.indices.push_back(uint32_t(v));
    }
    if (const Parameter* N = p.find("N")) {
        const std::vector<double> normals = p.numbers("N", 3);
        if (normals.size() != positions.size())
            p.fail(N, fmt::format("trianglemesh: N has {} normals for {} points", normals.size() / 3, n));
        for (size_t i = 0; i < n; ++i)
            mesh.normals.emplace_back(float(normals[3 * i]), float(normals[3 * i + 1]), float(normals[3 * i + 2]));
    }
    const char* uv_name = p.has("uv") ? "uv" : p.has("st") ? "st" : nullptr;
    if (uv_name) {
        const std::vector<double> uvs = p.numbers(uv_name, 2);
        if (uvs.size() != 2 * n)
            p.fail(p.find(uv_name), fmt::format("trianglemesh: {} has {} pairs for {} points", uv_name, uvs.size() / 2, n));
        for (size_t i = 0; i < n; ++i) mesh.uvs.emplace_back(float(uvs[2 * i]), float(uvs[2 * i + 1]));
    }
    return mesh;
}

std::vector<Vec3f> points3(const std::vector<double>& v) {
    std::vector<Vec3f> out;
    out.reserve(v.size() / 3);
    for (size_t i = 0; i + 2 < v.size(); i += 3) out.emplace_back(float(v[i]), float(v[i + 1]), float(v[i + 2]));
    return out;
}

std::vector<int> int_indices(const Params& p, const char* name) {
    std::vector<int> out;
    for (double v : p.numbers(name)) {
        if (!(v >= 0 && v <= 2147483647.0)) p.fail(p.find(name), fmt::format("{}: index {} is out of range", p.directive(), v));
        out.push_back(int(v));
    }
    return out;
}

// Runs a mesh builder whose SceneErrors carry no location, locating them at the directive.
template <class Build>
TriangleMesh located(const Params& p, Build&& build) {
    try {
        return build();
    } catch (const SceneError& e) {
        p.fail(nullptr, fmt::format("{}: {}", p.directive(), e.message()));
    }
}

// pbrt-v4's loopsubdiv: `levels` (3) of Loop subdivision of the triangles P / indices.
TriangleMesh read_loop_subdivision(const Params& p) {
    if (!p.has("P")) p.fail(nullptr, "loopsubdiv: \"point3 P\" is required");
    const std::vector<Vec3f> positions = points3(p.numbers("P", 3));
    const std::vector<int> indices = int_indices(p, "indices");
    if (indices.empty()) p.fail(nullptr, "loopsubdiv: \"integer indices\" is required");
    const long long levels = p.int_or("levels", 3);
    if (levels < 0 || levels > kMaxLoopLevels)
        p.fail(p.find("levels"), fmt::format("loopsubdiv: levels must be in 0 .. {}", kMaxLoopLevels));
    return located(p, [&] { return loop_subdivide(positions, indices, int(levels)); });
}

// pbrt-v4's bilinearmesh: patches of four corners (P / indices, optional N and uv), two triangles each.
TriangleMesh read_bilinear_mesh(const Params& p) {
    if (!p.has("P")) p.fail(nullptr, "bilinearmesh: \"point3 P\" is required");
    const std::vector<Vec3f> positions = points3(p.numbers("P", 3));
    const std::vector<int> indices = int_indices(p, "indices");
    const std::vector<Vec3f> normals = points3(p.numbers("N", 3));
    std::vector<Vec2f> uvs;
    const std::vector<double> uv = p.numbers("uv", 2);
    for (size_t i = 0; i + 1 < uv.size(); i += 2) uvs.emplace_back(float(uv[i]), float(uv[i + 1]));
    return located(p, [&] { return bilinear_patches_to_triangles(positions, indices, normals, uvs); });
}

// Whether a sphere of this material shows its (u, v) or tangent frame: textured parameters,
// normal or bump maps, anisotropic roughness. Such spheres keep pbrt's parametrization.
bool needs_sphere_frame(const std::string& material, ImportContext& ctx) {
    if (ImportContext::is_later_material(material)) return true;  // unknown yet: keep pbrt's frame
    const Json& m = ctx.doc()["materials"][material];
    if (m.value("type", "") == "blend") return true;
    const std::string text = m.dump();
    return text.find("\"texture\"") != std::string::npos || m.contains("normal_map") || m.contains("bump_map") ||
           (m.contains("roughness") && m["roughness"].is_array());
}

// The media on the shape's two sides (MediumInterface). pbrt-v4 makes a shape whose two media are
// the same no boundary at all (GeometricPrimitive only for a medium transition): a ray crossing it
// keeps the medium it is in. So the keys are written only where the two differ.
}  // namespace

void add_media(const GraphicsState& state, Json& shape) {
    if (state.inside_medium == state.outside_medium) return;
    shape["interior"] = state.inside_medium;
    shape["exterior"] = state.outside_medium;
}

void add_motion(const GraphicsState& state, Json& shape, const Transform& frame) {
    if (!state.moving()) return;
    Json motion{{"transform", transform_json(state.ctm_end * frame)}};
    if (state.start_time != 0.0 || state.end_time != 1.0)
        motion["times"] = Json::array({state.start_time, state.end_time});
    shape["motion"] = std::move(motion);
}

namespace {

// An instance of a sphere of radius r at the origin (an object shared by the spheres of the same
// radius, material and orientation), placed by to_world after turning candela's sphere frame (pole
// +y, u = 1/4 towards -z) into pbrt-v4's (pole +z, u = 1/4 towards +y): a rotation of 90 degrees
// about x.
Json sphere_instance(double r, const std::string& material, bool reversed, const GraphicsState& state,
                     const Transform& to_world, ImportContext& ctx) {
    std::string name = fmt::format("sphere {} {}{}", r, material, reversed ? " reversed" : "");
    const bool media = state.inside_medium != state.outside_medium;
    if (media) name += fmt::format(" in \"{}\" out \"{}\"", state.inside_medium, state.outside_medium);
    Json& objects = ctx.doc()["objects"];
    if (!objects.contains(name)) {
        Json sphere{{"type", "sphere"}, {"center", Json::array({0.0, 0.0, 0.0})}, {"radius", r}, {"material", material}};
        if (reversed) sphere["reverse_orientation"] = true;
        add_media(state, sphere);
        objects[name] = Json{{"shapes", Json::array({sphere})}};
    }
    const Transform frame = Transform::rotate(Vec3d(1, 0, 0), kPiD / 2);
    Json instance{{"type", "instance"}, {"object", name}, {"transform", transform_json(to_world * frame)}};
    add_motion(state, instance, frame);
    return instance;
}

// pbrt-v4's clipped quadrics (cylinder, partial sphere, partial disk) as candela's (quadric.h), in
// their object space placed by the CTM. The front side follows pbrt-v4's quadrics: the outside,
// flipped by ReverseOrientation or by a mirroring transform (not both). Parameters as pbrt-v4
// clamps them (shapes.h): z_min and z_max in either order, a sphere's clamped to [-r, r], phimax
// to [0, 360]; a shape left with no area is skipped with a warning. `area` is pbrt-v4's Area(),
// the object-space area, which its DiffuseAreaLight divides `power` by.
std::optional<Json> clipped_quadric(const std::string& type, const Params& p, const GraphicsState& state,
                                    const Transform& ctm, double& area, ImportContext& ctx) {
    const double phi_max = std::clamp(p.float_or("phimax", 360.0), 0.0, 360.0);
    Json shape;
    if (type == "disk") {
        const double h = p.float_or("height", 0.0), r = p.float_or("radius", 1.0);
        if (!(r > 0)) p.fail(p.find("radius"), "disk: radius must be > 0");
        const double inner = std::fabs(p.float_or("innerradius", 0.0));
        if (!(inner < r) || !(phi_max > 0)) {
            ctx.warn(p.location(), "disk: innerradius >= radius or phimax 0 leaves no surface; skipped, as pbrt-v4 "
                                   "renders nothing");
            return std::nullopt;
        }
        area = 0.5 * (phi_max * kPiD / 180) * (r * r - inner * inner);
        shape = Json{{"type", "disk"},      {"center", Json::array({0.0, 0.0, h})}, {"normal", Json::array({0.0, 0.0, 1.0})},
                     {"radius", r},         {"phi_max", phi_max}};
        if (inner > 0) shape["inner_radius"] = inner;
    } else {
        const double r = p.float_or("radius", 1.0);
        if (!(r > 0)) p.fail(p.find("radius"), type + ": radius must be > 0");
        const double d = type == "sphere" ? r : 1.0;
        const double z0 = p.float_or("zmin", -d), z1 = p.float_or("zmax", d);
        double lo = std::min(z0, z1), hi = std::max(z0, z1);
        if (type == "sphere") {
            lo = std::clamp(lo, -r, r);
            hi = std::clamp(hi, -r, r);
        }
        if (!(lo < hi) || !(phi_max > 0)) {
            ctx.warn(p.location(), type + ": an empty z range or phimax 0 leaves no surface; skipped, as pbrt-v4 "
                                          "renders nothing");
            return std::nullopt;
        }
        area = (phi_max * kPiD / 180) * r * (hi - lo);
        shape = Json{{"type", type}, {"radius", r}, {"z_min", lo}, {"z_max", hi}, {"phi_max", phi_max}};
        if (type == "sphere") shape["center"] = Json::array({0.0, 0.0, 0.0});
    }
    if (!ctm.is_identity()) shape["transform"] = transform_json(ctm);
    add_motion(state, shape);
    if (state.reverse_orientation != ctm.swaps_handedness()) shape["reverse_orientation"] = true;
    if (p.has("alpha")) {
        ctx.warn(p.find("alpha")->location, type + ": alpha on a cylinder, partial sphere or partial disk is not "
                                                   "supported; ignored");
    }
    return shape;
}

// Whether a pbrt-v4 sphere or disk is clipped (else candela's own full sphere or disk takes it).
bool is_clipped(const std::string& type, const Params& p) {
    if (type == "cylinder") return true;
    const double phi_max = p.float_or("phimax", 360);
    if (type == "disk") return p.float_or("innerradius", 0.0) != 0 || phi_max < 360;
    const double r = p.float_or("radius", 1.0);
    const double z0 = p.float_or("zmin", -r), z1 = p.float_or("zmax", r);
    return std::min(z0, z1) > -r || std::max(z0, z1) < r || phi_max < 360;
}

// The area light of the graphics state on `shape`; `area` is asked for only when `power` needs it.
void add_emission(const GraphicsState& state, Json& shape, const std::function<double()>& area, ImportContext& ctx) {
    if (!state.area_light) return;
    if (ctx.is_interface(state.material)) {
        // pbrt-v4 makes no light of a shape that has no material (scene.cpp, CreateLights).
        ctx.warn(state.area_light->at, "AreaLightSource on a shape of material \"interface\": ignored, as in pbrt-v4");
        return;
    }
    Params l(state.area_light->params, "AreaLightSource \"diffuse\"", state.area_light->at);
    Json L = l.colour("L", [&](const Parameter& t) -> std::string {
        fail(t.location, "AreaLightSource: L cannot be a texture");
    });
    double scale = l.float_or("scale", 1.0);
    const bool two_sided = l.bool_or("twosided", false);
    if (l.has("filename"))
        ctx.warn(l.find("filename")->location, "AreaLightSource: an image-textured area light is not supported; L is used");
    if (auto power = l.get_float("power"); power && *power > 0) {
        // pbrt-v4's DiffuseAreaLight: power / (pi (2 if two-sided) area), the spectrum at luminance 1.
        const double k = kPiD * (two_sided ? 2.0 : 1.0) * area();
        if (!(k > 0)) l.fail(l.find("power"), "AreaLightSource: power on a shape of zero area");
        scale *= *power / k;
    }
    if (!(scale > 0)) {
        ctx.warn(l.location(), "AreaLightSource: scale 0, the shapes do not emit");
        return;
    }
    shape["emission"] = L.is_null() ? Json(1.0) : L;
    if (scale != 1) shape["emission_scale"] = scale;
    if (two_sided) shape["two_sided"] = true;
    l.report_unused([&](const Location& at, const std::string& m) { ctx.warn(at, m); });
}

}  // namespace

void translate_shape(const std::string& type, const Params& p, const GraphicsState& state, Json& shapes,
                     const std::string& shapes_pointer, ImportContext& ctx) {
    if (type == "curve") {
        translate_curve(p, state, shapes, shapes_pointer, ctx);
        return;
    }
    Json shape = Json::object();
    std::function<double()> area;
    // A mesh takes a projective transform vertex by vertex, as pbrt-v4's triangles do; pbrt-v4's
    // quadrics intersect rays taken into their object space by it, which candela's cannot.
    Transform affine_ctm = state.ctm;
    if (!state.ctm.is_affine() && (type == "sphere" || type == "disk" || type == "cylinder")) {
        ctx.warn(p.location(), type + ": a projective transform (a last row other than 0 0 0 1) is not supported; "
                                      "its last row is taken as 0 0 0 1");
        Transform::Matrix m = state.ctm.matrix();
        m[3] = {0, 0, 0, 1};
        affine_ctm = Transform(m);
    }
    const Transform& ctm = affine_ctm;
    if (type == "trianglemesh" || type == "plymesh" || type == "loopsubdiv" || type == "bilinearmesh") {
        std::string file;
        if (type != "plymesh") {
            file = ctx.new_mesh_name(type);
            ctx.meshes()[file] = type == "trianglemesh" ? read_triangle_mesh(p)
                                 : type == "loopsubdiv" ? read_loop_subdivision(p)
                                                        : read_bilinear_mesh(p);
            const TriangleMesh* mesh = &ctx.meshes()[file];
            area = [mesh, &ctm] { return mesh_area(*mesh, ctm); };
            if (p.has("S")) ctx.warn(p.find("S")->location, "trianglemesh: per-vertex tangents S are ignored");
            p.numbers("faceIndices");
        } else {
            file = p.string_or("filename", "");
            if (file.empty()) p.fail(nullptr, "plymesh: \"string filename\" is required");
            area = [&, file] {
                const TriangleMesh mesh = load_mesh(ctx.folder() / file);
                return mesh_area(mesh, ctm);
            };
            if (p.has("displacement"))
                ctx.warn(p.find("displacement")->location, "plymesh: displacement is not supported; ignored");
            p.float_or("edgelength", 1.0);
        }
        shape = Json{{"type", "mesh"}, {"file", file}};
        if (!ctm.is_identity()) shape["transform"] = transform_json(ctm);
        add_motion(state, shape);
        if (state.reverse_orientation) shape["reverse_orientation"] = true;
    } else if ((type == "sphere" || type == "disk" || type == "cylinder") && is_clipped(type, p)) {
        double quadric_area = 0;
        std::optional<Json> quadric = clipped_quadric(type, p, state, ctm, quadric_area, ctx);
        if (!quadric) {
            p.mark_all_used();
            return;
        }
        shape = std::move(*quadric);
        area = [quadric_area] { return quadric_area; };
        shape["material"] = state.material;
        add_media(state, shape);
        add_emission(state, shape, area, ctx);
        if (!shapes_pointer.empty()) ctx.origin(fmt::format("{}/{}", shapes_pointer, shapes.size()), p.location());
        shapes.push_back(std::move(shape));
        return;
    } else if (type == "sphere") {
        const double r = p.float_or("radius", 1.0);
        if (!(r > 0)) p.fail(p.find("radius"), "sphere: radius must be > 0");
        double s = 1;
        const bool similarity = is_similarity(ctm, s);
        const Vec3d c = ctm.apply_point(Vec3d(0, 0, 0));
        shape = Json{{"type", "sphere"}, {"center", Json::array({c.x, c.y, c.z})}, {"radius", r * s}};
        // pbrt's front: the outside, flipped by ReverseOrientation or a mirroring transform.
        const bool reversed = state.reverse_orientation != ctm.swaps_handedness();
        if (reversed) shape["reverse_orientation"] = true;
        if (!similarity) {
            s = std::cbrt(std::fabs(ctm.determinant()));
            shape["radius"] = r * s;
        }
        area = [r, s] { return 4 * kPiD * r * r * s * s; };
        if (!similarity || needs_sphere_frame(state.material, ctx) || state.moving()) {
            // An ellipsoid, or a sphere whose material reads its surface frame (textures, maps,
            // anisotropy), or that moves (about its own centre, as pbrt-v4's AnimatedTransform
            // moves it): an instance of a sphere in pbrt's object space, so that the transform
            // is exact and (u, v) are pbrt's (pole on z, not candela's y).
            if (state.area_light || shapes_pointer != "/shapes") {
                ctx.warn(p.location(), similarity ? "sphere: an emitting or instanced textured sphere keeps candela's "
                                                    "(u, v) (its pole on y, pbrt-v4's on z)"
                                                  : "sphere: an emitting or instanced ellipsoid is rendered as a "
                                                    "sphere of the same volume");
            } else {
                shape = sphere_instance(r, state.material, reversed, state, ctm, ctx);
                shape.erase("material");
            }
        }
    } else if (type == "disk") {
        const double h = p.float_or("height", 0.0), r = p.float_or("radius", 1.0);
        if (!(r > 0)) p.fail(p.find("radius"), "disk: radius must be > 0");
        shape = Json{{"type", "disk"},
                     {"center", Json::array({0.0, 0.0, h})},
                     {"normal", Json::array({0.0, 0.0, 1.0})},
                     {"radius", r}};
        if (!ctm.is_identity()) shape["transform"] = transform_json(ctm);
        add_motion(state, shape);
        if (state.reverse_orientation) shape["reverse_orientation"] = true;
        area = [r, &ctm] {
            const Vec3d u = ctm.apply_vector(Vec3d(r, 0, 0)), v = ctm.apply_vector(Vec3d(0, r, 0));
            return kPiD * length(cross(u, v));
        };
    } else {
        ctx.warn(p.location(), fmt::format("Shape \"{}\" is not supported; skipped", type));
        p.mark_all_used();
        return;
    }
    std::string material = state.material;
    if (p.has("alpha")) {
        if (ImportContext::is_later_material(material))
            p.fail(p.find("alpha"),
                   "alpha on a shape whose NamedMaterial is defined later in the file is not supported");
        Json alpha = p.number_or_texture("alpha", [&](const Parameter& t) { return ctx.texture_reference(t, true); });
        if (state.area_light && alpha.is_number() && alpha.get<double>() <= 0 && !ctx.is_interface(material)) {
            // pbrt-v4 masks an area light by its shape's alpha (DiffuseAreaLight::AlphaMasked): at
            // alpha 0 the light emits nothing and the shape is invisible, so it adds nothing to the
            // image (pbrt-v4 still spends light samples on it). candela leaves the shape out.
            return;
        }
        if (!(alpha.is_number() && alpha.get<double>() >= 1)) {
            if (ctx.is_interface(material))
                ctx.warn(p.find("alpha")->location, "alpha on a shape of material \"interface\" is not supported; "
                                                    "ignored (the shape is a medium boundary everywhere)");
            else
                material = material_with_alpha(material, alpha, ctx);
        }
    }
    if (shape["type"] == "instance") {
        if (material != state.material)
            ctx.warn(p.location(), "sphere: alpha on a textured or non-uniformly scaled sphere is not supported");
        if (!shapes_pointer.empty()) ctx.origin(fmt::format("{}/{}", shapes_pointer, shapes.size()), p.location());
        shapes.push_back(std::move(shape));
        return;
    }
    shape["material"] = material;
    add_media(state, shape);
    add_emission(state, shape, area, ctx);
    if (!shapes_pointer.empty()) ctx.origin(fmt::format("{}/{}", shapes_pointer, shapes.size()), p.location());
    shapes.push_back(std::move(shape));
}

}  // namespace candela::pbrt
