// pbrt-v4's `Shape "curve"` in the importer (pbrt_curves.cpp): pbrt-v4's defaults and checks, runs
// of curves in one graphics state collected into one curves shape of the curve store, a change of
// state starting another, and `candela convert` writing the store as `.curves` files that load to
// the same curves.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_convert.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "candela/formats/scene_file.h"
#include "formats/pbrt/pbrt_import_text.h"
#include "candela/render/renderer.h"
#include "support/test_files.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

const std::filesystem::path& kFile = test::kInlineFile;
using test::import;
std::string error_of(const std::string& text) { return test::import_error(text); }

constexpr const char* kLight = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
constexpr const char* kHair = R"(Material "diffuse"
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "float width0" 0.1 "float width1" 0.05
Shape "curve" "point3 P" [0 0 1 1 1 1 2 1 1 3 0 1] "float width" 0.2
)";

TEST(PbrtCurves, ARunOfCurvesInOneStateIsOneShapeOfTheStore) {
    const ImportedScene s = import(std::string("WorldBegin\n") + kLight + kHair + "Shape \"sphere\"\n" + kHair);
    const auto& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 3u);  // curves, sphere, curves: another shape ends a run
    EXPECT_EQ(shapes[0]["type"], "curves");
    EXPECT_EQ(shapes[0]["curve_type"], "flat");  // pbrt-v4's default
    EXPECT_EQ(shapes[2]["type"], "curves");
    ASSERT_EQ(s.curves.size(), 2u);
    const CurveData& data = s.curves.at(shapes[0]["file"].get<std::string>());
    EXPECT_EQ(data.curve_count(), 2u);
    EXPECT_EQ(data.widths, (std::vector<float>{0.1f, 0.05f, 0.2f, 0.2f}));
    const Scene scene = load_imported_scene(s, kFile);
    ASSERT_EQ(scene.curves.size(), 2u);
    EXPECT_EQ(scene.curves[0].segment_count(), 2u);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

TEST(PbrtCurves, AnotherMaterialTypeOrTransformStartsAnotherShape) {
    const ImportedScene s = import(R"(WorldBegin
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string type" "cylinder"
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string type" "flat"
Translate 0 0 1
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0]
Material "conductor"
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0]
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string type" "ribbon" "normal N" [0 0 1 0 1 0]
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string basis" "bspline" "integer degree" 2
)");
    const auto& shapes = s.document["shapes"];
    ASSERT_EQ(shapes.size(), 6u);
    EXPECT_EQ(shapes[0]["curve_type"], "cylinder");
    EXPECT_TRUE(shapes[2].contains("transform"));
    EXPECT_EQ(shapes[4]["curve_type"], "ribbon");
    EXPECT_EQ(shapes[5]["basis"], "bspline");
    EXPECT_EQ(shapes[5]["degree"], 2);
    const Scene scene = load_imported_scene(s, kFile);
    EXPECT_EQ(scene.curves.size(), 6u);
    EXPECT_EQ(scene.curves[5].segment_count(), 2u);
    EXPECT_FLOAT_EQ(scene.curves[2].points[0].p.z, 1.0f);
}

TEST(PbrtCurves, PbrtsChecksAreLocatedErrors) {
    const auto expect = [](const std::string& shape, const std::string& part) {
        const std::string e = error_of("WorldBegin\n" + shape + "\n");
        EXPECT_NE(e.find("inline.pbrt:2:"), std::string::npos) << e;
        EXPECT_NE(e.find(part), std::string::npos) << e;
    };
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0])", "3 control points do not make a degree 3 Bezier");
    expect(R"(Shape "curve")", "\"point3 P\" is required");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "integer degree" 4)", "degree 4");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string basis" "hermite")", "hermite");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string type" "tube")", "tube");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "string type" "ribbon")", "need normals");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 nan 0 3 0 0])", "finite");
    expect(R"(Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0] "float width" -1)", "width");
}

TEST(PbrtCurves, AnAreaLightOnCurvesIsAWarningAndNoLight) {
    const ImportedScene s = import(R"(WorldBegin
AreaLightSource "diffuse" "rgb L" [1 1 1]
Shape "curve" "point3 P" [0 0 0 1 1 0 2 1 0 3 0 0]
)");
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings[0].find("area light on curves is not supported"), std::string::npos) << s.warnings[0];
    EXPECT_FALSE(s.document["shapes"][0].contains("emission"));
}

TEST(PbrtCurves, ConvertWritesCurvesFilesThatLoadToTheSameCurves) {
    const auto dir = candela::test::fresh_dir("pbrt_curves_convert");
    {
        std::ofstream f(dir / "hair.pbrt");
        f << "WorldBegin\n" << kLight << kHair;
    }
    const ConvertResult r = convert_pbrt_scene(dir / "hair.pbrt", dir / "out" / "hair.json");
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "curves" / "curve-1.curves"));
    const Scene converted = load_scene_file(dir / "out" / "hair.json");
    const Scene direct = load_scene_file(dir / "hair.pbrt");
    ASSERT_EQ(converted.curves.size(), 1u);
    ASSERT_EQ(direct.curves.size(), 1u);
    ASSERT_EQ(converted.curves[0].points.size(), direct.curves[0].points.size());
    for (size_t i = 0; i < direct.curves[0].points.size(); ++i) {
        EXPECT_EQ(converted.curves[0].points[i].p, direct.curves[0].points[i].p);
        EXPECT_EQ(converted.curves[0].points[i].r, direct.curves[0].points[i].r);
    }
    (void)r;
}

TEST(PbrtCurves, TheFixtureOfEveryKindLoadsWithoutWarningsAndRendersFinite) {
    Scene scene = load_scene_file(std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "curves.pbrt");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.curves.size(), 4u);  // each curve differs from the last in kind, basis or degree
    scene.sampler.spp = 4;
    const Image image = render(scene, {.threads = 2}).image;
    double sum = 0;
    for (const Rgb& p : image.pixels) {
        ASSERT_TRUE(p.is_finite());
        sum += double(p.r);
    }
    // The diffuse curves block part of the environment of 1 and reflect half of it.
    const double mean = sum / double(image.pixels.size());
    EXPECT_LT(mean, 0.99);
    EXPECT_GT(mean, 0.5);
}

}  // namespace
}  // namespace candela::pbrt
