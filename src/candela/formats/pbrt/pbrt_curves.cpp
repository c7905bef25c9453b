// pbrt-v4's `Shape "curve"` as candela's `curves` shapes (docs/PBRT.md). A hair model is a run of
// thousands to millions of curve directives in the same graphics state: they are collected into
// one entry of the curve store (formats/curves/curve_file.h) and one JSON shape naming it, so that
// the document stays small and the curves load as one Embree geometry. pbrt-v4's checks and
// defaults are kept: degree 3, bezier, flat, width 1; ribbons need N at the segments' ends.
#include <fmt/format.h>

#include "candela/formats/pbrt/pbrt_import_context.h"

namespace candela::pbrt {

void translate_curve(const Params& p, const GraphicsState& state, Json& shapes, const std::string& shapes_pointer,
                     ImportContext& ctx) {
    const Parameter* P = p.find("P");
    if (!P) p.fail(nullptr, "curve: \"point3 P\" is required");
    const std::vector<double> xyz = p.numbers("P", 3);
    std::vector<Vec3f> points;
    points.reserve(xyz.size() / 3);
    for (size_t i = 0; i + 2 < xyz.size(); i += 3) points.emplace_back(float(xyz[i]), float(xyz[i + 1]), float(xyz[i + 2]));
    const long long degree = p.int_or("degree", 3);
    if (degree != 2 && degree != 3)
        p.fail(p.find("degree"), fmt::format("curve: degree {} is not supported (2 or 3)", degree));
    const std::string basis = p.string_or("basis", "bezier");
    if (basis != "bezier" && basis != "bspline")
        p.fail(p.find("basis"), fmt::format("curve: basis \"{}\" is not supported (\"bezier\" or \"bspline\")", basis));
    const std::string type = p.string_or("type", "flat");
    if (type != "flat" && type != "cylinder" && type != "ribbon")
        p.fail(p.find("type"), fmt::format("curve: type \"{}\" is not \"flat\", \"cylinder\" or \"ribbon\"", type));
    const double width = p.float_or("width", 1.0);
    const double width0 = p.float_or("width0", width), width1 = p.float_or("width1", width);
    std::vector<Vec3f> normals;
    if (const Parameter* N = p.find("N")) {
        const std::vector<double> n = p.numbers("N", 3);
        if (type != "ribbon") {
            ctx.warn(N->location, "curve: normals N are used by \"ribbon\" curves only; ignored");
        } else {
            for (size_t i = 0; i + 2 < n.size(); i += 3) normals.emplace_back(float(n[i]), float(n[i + 1]), float(n[i + 2]));
        }
    } else if (type == "ribbon") {
        p.fail(nullptr, "curve: ribbon curves need normals \"normal N\" at the segments' ends");
    }
    p.int_or("splitdepth", 3);  // pbrt-v4's own subdivision; Embree refines curves itself
    // The same checks the JSON loader makes, located here at the directive.
    if (const std::string error = curve_error(points, basis == "bezier" ? CurveBasis::kBezier : CurveBasis::kBSpline,
                                              int(degree), float(width0), float(width1), type == "ribbon", normals);
        !error.empty())
        p.fail(P, "curve: " + error);
    if (state.area_light)
        ctx.warn(p.location(), "curve: an area light on curves is not supported (pbrt-v4 cannot sample curves "
                               "either); the curves do not emit");
    if (p.has("alpha")) ctx.warn(p.find("alpha")->location, "curve: alpha on curves is not supported; ignored");
    p.report_unused([&](const Location& at, const std::string& m) { ctx.warn(at, m); });

    // Curves in the same state as the last shape added, when that was curves, join its store entry.
    const std::string key = fmt::format("{}|{}|{}|{}|{}|{}|{}", state.material, type, basis, degree,
                                        state.reverse_orientation, state.inside_medium, state.outside_medium);
    CurveRun& run = ctx.curve_run();
    // (A moving curve is a shape of its own: its motion is not in the key.)
    if (state.moving() || !(run.shapes == &shapes && run.index + 1 == shapes.size() && run.key == key &&
          run.ctm.matrix() == state.ctm.matrix())) {
        run = CurveRun{&shapes, shapes.size(), key, state.ctm, ctx.new_curves_name()};
        Json shape{{"type", "curves"}, {"file", run.file}, {"curve_type", type}};
        if (basis != "bezier") shape["basis"] = basis;
        if (degree != 3) shape["degree"] = degree;
        if (!state.ctm.is_identity()) shape["transform"] = transform_json(state.ctm);
        add_motion(state, shape);
        if (state.reverse_orientation) shape["reverse_orientation"] = true;
        shape["material"] = state.material;
        add_media(state, shape);
        if (!shapes_pointer.empty()) ctx.origin(fmt::format("{}/{}", shapes_pointer, shapes.size()), p.location());
        shapes.push_back(std::move(shape));
    }
    ctx.curves()[run.file].add(points, float(width0), float(width1), normals);
}

}  // namespace candela::pbrt
