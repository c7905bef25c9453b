// A `curves` shape of a scene file (docs/SCENE_FORMAT.md, "curves"): one curve given inline, as a
// pbrt-v4 `Shape "curve"` gives it, or many from a `.curves` file (formats/curves/curve_file.h) or
// the curve store of a translated scene; built into Bezier segments (geometry/curves.h).
#include <fmt/format.h>

#include <array>
#include <string_view>

#include "candela/formats/curves/curve_file.h"
#include "candela/formats/json/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 3> kCurveTypes = {"flat", "cylinder", "ribbon"};
constexpr std::array<std::string_view, 2> kCurveBases = {"bezier", "bspline"};

std::vector<Vec3f> read_points(const JsonCursor& c) {
    std::vector<Vec3f> points;
    for (const JsonCursor& p : c.elements()) points.push_back(p.vec3f());
    return points;
}

}  // namespace

void read_curves(JsonCursor& c, const ShapeSection& section, Scene& scene, MemoryBudget& budget, Shape shape,
                 bool reverse_orientation) {
    // pbrt-v4 cannot sample a curve's area either; an alpha test would need Embree curve filters.
    for (std::string_view key : {"emission", "emission_scale", "two_sided"})
        if (auto v = c.get(key)) v->fail("curves cannot emit light (nor can pbrt-v4's)");
    if (scene.materials[shape.material].surface.cuts_out())
        c.require("material").fail(fmt::format("curves cannot be cut out: material {} has alpha < 1",
                                               json_quoted(scene.material_names[shape.material])));
    CurveSet set;
    set.type = CurveType::kFlat;
    if (auto v = c.get("curve_type")) {
        const std::string_view t = v->choice("curve type", kCurveTypes);
        set.type = t == "flat" ? CurveType::kFlat : t == "cylinder" ? CurveType::kCylinder : CurveType::kRibbon;
    }
    CurveBasis basis = CurveBasis::kBezier;
    if (auto v = c.get("basis"))
        basis = v->choice("curve basis", kCurveBases) == "bezier" ? CurveBasis::kBezier : CurveBasis::kBSpline;
    int degree = 3;
    if (auto v = c.get("degree")) degree = v->integer(Bounds::closed(2, 3));
    Transform to_world;
    std::optional<JsonCursor> transform = c.get("transform");
    if (transform) to_world = read_transform(*transform);

    std::optional<JsonCursor> file = c.get("file");
    std::optional<JsonCursor> points = c.get("points");
    if (file && points) points->fail("a curves shape takes either \"points\" (one curve) or \"file\", not both");
    std::string error;
    const JsonCursor& blame = file ? *file : c.require("points");
    if (file) {
        for (std::string_view key : {"width", "width0", "width1", "normals"})
            if (c.has(key))
                c.document().fail_at_key(c.pointer(), key,
                                         "a curves file gives each curve's widths and normals; remove the key");
        c.reject_unknown_keys();
        const CurveStore* store = section.curves;
        const auto stored = store ? store->find(file->string()) : CurveStore::const_iterator{};
        CurveData loaded;
        const CurveData* data = nullptr;
        if (store && stored != store->end()) {
            data = &stored->second;
        } else {
            std::filesystem::path path = referenced_file(*file, section.folder, "curves");
            loaded = load_referenced(*file, [&] { return read_curve_file(path); });
            data = &loaded;
        }
        // The segments take about the file's size again, and Embree copies them.
        if (auto refused = budget.charge(3 * data->bytes(), fmt::format("curves file {} ({} curves)",
                                                                        json_quoted(file->string()),
                                                                        data->curve_count())))
            file->fail(*refused);
        error = add_curves(set, *data, basis, degree);
    } else {
        const std::vector<Vec3f> cp = read_points(blame);
        float width = 1.0f;
        if (auto v = c.get("width")) width = v->number_f(Bounds::at_least(0));
        float width0 = width, width1 = width;
        if (auto v = c.get("width0")) width0 = v->number_f(Bounds::at_least(0));
        if (auto v = c.get("width1")) width1 = v->number_f(Bounds::at_least(0));
        std::vector<Vec3f> normals;
        if (auto v = c.get("normals")) {
            if (set.type != CurveType::kRibbon)
                v->fail("normals orient ribbons only; this curve's curve_type is not \"ribbon\"");
            normals = read_points(*v);
        }
        c.reject_unknown_keys();
        error = add_curve(set, cp, basis, degree, width0, width1, normals);
    }
    if (!error.empty()) blame.fail(error);
    // pbrt's orientation rule, as for meshes: a mirroring transform flips the front side too.
    set.reverse_orientation = reverse_orientation != to_world.swaps_handedness();
    if (transform) {
        transform_curves(set, to_world);
        for (const CurvePoint& p : set.points)
            if (!is_finite(p.p) || !std::isfinite(p.r))
                transform->fail("the transform moves the curves beyond float range");
    }
    if (!file) {
        if (auto refused = budget.charge(2 * set.bytes(), "a curve")) blame.fail(*refused);
    }
    shape.kind = ShapeKind::kCurves;
    shape.index = static_cast<uint32_t>(scene.curves.size());
    if (section.bounds)
        for (const CurvePoint& p : set.points) {
            section.bounds->add(Vec3d(p.p) - Vec3d(double(p.r)));
            section.bounds->add(Vec3d(p.p) + Vec3d(double(p.r)));
        }
    scene.curves.push_back(std::move(set));
    scene.shapes.push_back(shape);
}

}  // namespace candela
