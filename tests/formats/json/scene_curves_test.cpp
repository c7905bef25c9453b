// The scene file's `curves` shape (docs/SCENE_FORMAT.md): one curve inline as pbrt-v4 gives it, or
// many from a `.curves` file; its kind, basis, degree, widths, normals and transform reach the
// loaded CurveSet; bad curves are located errors.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "candela/formats/curves/curve_file.h"
#include "formats/json/scene_test_util.h"
#include "support/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

Scene load_curves(const std::string& keys, const std::string& material = R"({"type": "diffuse"})") {
    return load_json(R"({"materials": {"m": )" + material + R"(}, "shapes": [{"type": "curves", "material": "m", )" +
                     keys + "}]}");
}
SceneError curves_error(const std::string& keys, const std::string& material = R"({"type": "diffuse"})") {
    return load_error(R"({"materials": {"m": )" + material + R"(}, "shapes": [{"type": "curves", "material": "m", )" +
                      keys + "}]}");
}

constexpr const char* kFour = R"("points": [[0, 0, 0], [1, 1, 0], [2, 1, 0], [3, 0, 0]])";

TEST(SceneLoaderCurves, AnInlineCurveWithItsDefaults) {
    Scene s = load_curves(kFour);
    ASSERT_EQ(s.curves.size(), 1u);
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(s.shapes[0].kind, ShapeKind::kCurves);
    const CurveSet& c = s.curves[0];
    EXPECT_EQ(c.type, CurveType::kFlat);  // pbrt-v4's default
    EXPECT_EQ(c.segment_count(), 1u);
    EXPECT_FLOAT_EQ(c.points[0].r, 0.5f);  // width 1
    EXPECT_FALSE(c.reverse_orientation);
}

TEST(SceneLoaderCurves, KindBasisDegreeWidthsAndTransform) {
    Scene s = load_curves(R"("curve_type": "cylinder", "basis": "bspline", "degree": 2, "width0": 0.2, "width1": 0.1,
        "points": [[0, 0, 0], [1, 1, 0], [2, 1, 0], [3, 0, 0]], "transform": [{"scale": 2}, {"translate": [0, 0, 5]}])");
    const CurveSet& c = s.curves[0];
    EXPECT_EQ(c.type, CurveType::kCylinder);
    EXPECT_EQ(c.segment_count(), 2u);  // 4 points of a quadratic B-spline
    EXPECT_FLOAT_EQ(c.points.front().r, 0.2f);  // 0.1 scaled by 2
    EXPECT_NEAR(c.points.back().r, 0.1f, 1e-6f);
    EXPECT_FLOAT_EQ(c.points.front().p.z, 5.0f);
    EXPECT_FLOAT_EQ(c.points.front().p.x, 1.0f);  // the midpoint of (0, 0, 0) and (1, 1, 0), scaled
    // A mirroring transform flips the front side, as it does for meshes.
    Scene m = load_curves(std::string(kFour) + R"(, "transform": [{"scale": [-1, 1, 1]}])");
    EXPECT_TRUE(m.curves[0].reverse_orientation);
    Scene r = load_curves(std::string(kFour) + R"(, "reverse_orientation": true)");
    EXPECT_TRUE(r.curves[0].reverse_orientation);
}

TEST(SceneLoaderCurves, RibbonsTakeNormalsAtTheSegmentsEnds) {
    Scene s = load_curves(std::string(kFour) + R"(, "curve_type": "ribbon", "normals": [[0, 0, 1], [0, 0, 2]])");
    EXPECT_EQ(s.curves[0].type, CurveType::kRibbon);
    EXPECT_EQ(s.curves[0].normals.size(), 4u);
}

TEST(SceneLoaderCurves, ACurvesFileHoldsManyCurves) {
    const auto dir = test::fresh_dir("scene_curves_file");
    {
        std::ofstream f(dir / "hair.curves");
        f << "# two curves\n7 0.1 0.05 0 0 0 1 1 0 2 1 0 3 0 0 4 0 0 5 0 0 6 0 0\n\n4 0.2 0.2 0 0 0 1 0 0 2 0 0 3 0 0\n";
    }
    Scene s = load_curves(R"("file": ")" + (dir / "hair.curves").string() + R"(", "curve_type": "cylinder")");
    const CurveSet& c = s.curves[0];
    EXPECT_EQ(c.segment_count(), 3u);
    EXPECT_EQ(c.points.size(), 7u + 4u);
    EXPECT_FLOAT_EQ(c.points[0].r, 0.05f);  // width0 0.1
    EXPECT_FLOAT_EQ(c.points[6].r, 0.025f);
    EXPECT_FLOAT_EQ(c.points[7].r, 0.1f);

    // The writer's output reads back to the same curves.
    CurveData data = read_curve_file(dir / "hair.curves");
    write_curve_file(dir / "again.curves", data);
    const CurveData again = read_curve_file(dir / "again.curves");
    EXPECT_EQ(again.points, data.points);
    EXPECT_EQ(again.widths, data.widths);
    EXPECT_EQ(again.point_end, data.point_end);

    {
        std::ofstream f(dir / "bad.curves");
        f << "4 0.1 0.1 0 0 0 1 1 0 2 1 0 3 0 0\n5 0.1 0.1 0 0 0 1 1 0\n";
    }
    const SceneError e = curves_error(R"("file": ")" + (dir / "bad.curves").string() + R"(")");
    EXPECT_NE(e.formatted().find("bad.curves:2"), std::string::npos) << e.formatted();
    EXPECT_NE(e.formatted().find("5 control points announced"), std::string::npos) << e.formatted();
    const SceneError odd = curves_error(R"("file": ")" + (dir / "hair.curves").string() + R"(", "degree": 2)");
    EXPECT_NE(odd.formatted().find("curve 2: 4 control points do not make a degree 2 Bezier"), std::string::npos)
        << odd.formatted();
}

TEST(SceneLoaderCurves, BadCurvesAreLocatedErrors) {
    const auto expect_error = [](const SceneError& e, const std::string& pointer, const std::string& text) {
        EXPECT_EQ(e.where().json_pointer, pointer) << e.formatted();
        EXPECT_NE(e.message().find(text), std::string::npos) << e.formatted();
    };
    expect_error(curves_error(R"("points": [[0, 0, 0], [1, 1, 0], [2, 1, 0]])"), "/shapes/0/points",
                 "3 control points do not make a degree 3 Bezier curve");
    expect_error(curves_error(std::string(kFour) + R"(, "width": -1)"), "/shapes/0/width", "");
    expect_error(curves_error(std::string(kFour) + R"(, "width": 0)"), "/shapes/0/points", "not 0 at both ends");
    expect_error(curves_error(std::string(kFour) + R"(, "curve_type": "tube")"), "/shapes/0/curve_type", "tube");
    expect_error(curves_error(std::string(kFour) + R"(, "degree": 4)"), "/shapes/0/degree", "");
    expect_error(curves_error(std::string(kFour) + R"(, "curve_type": "ribbon")"), "/shapes/0/points",
                 "needs 2 normals");
    expect_error(curves_error(std::string(kFour) + R"(, "normals": [[0, 0, 1], [0, 0, 1]])"), "/shapes/0/normals",
                 "ribbons only");
    expect_error(curves_error(std::string(kFour) + R"(, "emission": 1)"), "/shapes/0/emission", "cannot emit");
    expect_error(curves_error(kFour, R"({"type": "diffuse", "alpha": 0.5})"), "/shapes/0/material", "cut out");
    expect_error(curves_error(std::string(kFour) + R"(, "file": "x.curves")"), "/shapes/0/points", "not both");
    expect_error(curves_error(R"("file": "missing.curves")"), "/shapes/0/file", "missing.curves");
}

}  // namespace
}  // namespace candela
