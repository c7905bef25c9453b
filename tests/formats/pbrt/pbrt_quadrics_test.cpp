// pbrt-v4's cylinders, partial spheres and partial disks in the importer (pbrt_shapes.cpp): the
// JSON they become (candela's cylinder, and sphere and disk with z_min, z_max, phi_max,
// inner_radius), pbrt-v4's defaults and clamping, orientation under ReverseOrientation and
// mirrors, power of an emitting one, and the loaded quadrics; full spheres and disks stay
// candela's own shapes. No warnings for any of it.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "candela/formats/scene_file.h"
#include "candela/math/constants.h"
#include "formats/pbrt/pbrt_import_text.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

using test::import;

ImportedScene import_shapes(const std::string& shapes) {
    return import("WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n" + shapes);
}

TEST(PbrtQuadrics, CylinderWithPbrtsDefaults) {
    const ImportedScene s = import_shapes("Shape \"cylinder\"\n");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const auto& c = s.document["shapes"][0];
    EXPECT_EQ(c["type"], "cylinder");
    EXPECT_EQ(c["radius"], 1.0);
    EXPECT_EQ(c["z_min"], -1.0);
    EXPECT_EQ(c["z_max"], 1.0);
    EXPECT_EQ(c["phi_max"], 360.0);
    EXPECT_FALSE(c.contains("transform"));
    EXPECT_FALSE(c.contains("reverse_orientation"));
    const Scene scene = load_imported_scene(s, test::kInlineFile);
    ASSERT_EQ(scene.quadrics.size(), 1u);
    EXPECT_EQ(scene.shapes[0].kind, ShapeKind::kQuadric);
    EXPECT_EQ(scene.quadrics[0].kind, QuadricKind::kCylinder);
    EXPECT_NEAR(scene.quadrics[0].object_area(), 4 * kPiD, 1e-12);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

TEST(PbrtQuadrics, PartialSphereAndDiskBecomeQuadricsWithTheirTransform) {
    const ImportedScene s = import_shapes(R"(Translate 1 2 3
Shape "sphere" "float radius" 2 "float zmin" -1 "float zmax" 1.5 "float phimax" 270
Shape "disk" "float height" 0.5 "float radius" 2 "float innerradius" 0.5 "float phimax" 180
)");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const auto& sphere = s.document["shapes"][0];
    EXPECT_EQ(sphere["type"], "sphere");
    EXPECT_EQ(sphere["z_min"], -1.0);
    EXPECT_EQ(sphere["z_max"], 1.5);
    EXPECT_EQ(sphere["phi_max"], 270.0);
    EXPECT_TRUE(sphere.contains("transform"));
    const auto& disk = s.document["shapes"][1];
    EXPECT_EQ(disk["type"], "disk");
    EXPECT_EQ(disk["inner_radius"], 0.5);
    EXPECT_EQ(disk["phi_max"], 180.0);
    EXPECT_EQ(disk["center"][2], 0.5);
    const Scene scene = load_imported_scene(s, test::kInlineFile);
    ASSERT_EQ(scene.quadrics.size(), 2u);
    EXPECT_TRUE(scene.spheres.empty());
    EXPECT_TRUE(scene.disks.empty());
    // The disk's object space is pbrt-v4's: its point (2, 0, 0.5) is at the world's (3, 2, 3.5).
    const Quadric& d = scene.quadrics[1];
    const Vec3d p = d.to_world.apply_point(Vec3d(2, 0, d.height));
    EXPECT_NEAR(p.x, 3.0, 1e-12);
    EXPECT_NEAR(p.y, 2.0, 1e-12);
    EXPECT_NEAR(p.z, 3.5, 1e-12);
}

TEST(PbrtQuadrics, FullSpheresAndDisksStayCandelasOwn) {
    const ImportedScene s = import_shapes(R"(Shape "sphere" "float radius" 2 "float zmin" -2 "float zmax" 5 "float phimax" 360
Shape "disk" "float innerradius" 0 "float phimax" 360
)");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const Scene scene = load_imported_scene(s, test::kInlineFile);
    EXPECT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.disks.size(), 1u);
    EXPECT_TRUE(scene.quadrics.empty());
}

TEST(PbrtQuadrics, ParametersAreClampedAsPbrtV4ClampsThem) {
    const ImportedScene s = import_shapes(R"(Shape "sphere" "float zmin" 0.9 "float zmax" -3 "float phimax" 500
Shape "cylinder" "float zmin" 2 "float zmax" -2 "float phimax" 90
)");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const auto& sphere = s.document["shapes"][0];
    EXPECT_EQ(sphere["z_min"], -1.0);  // swapped, then clamped to the radius
    EXPECT_EQ(sphere["z_max"], 0.9);
    EXPECT_EQ(sphere["phi_max"], 360.0);
    const auto& cylinder = s.document["shapes"][1];
    EXPECT_EQ(cylinder["z_min"], -2.0);
    EXPECT_EQ(cylinder["z_max"], 2.0);
}

TEST(PbrtQuadrics, EmptyShapesAreSkippedWithAWarning) {
    for (const char* shape : {"Shape \"cylinder\" \"float phimax\" 0", "Shape \"sphere\" \"float zmin\" 2 \"float zmax\" 3",
                              "Shape \"disk\" \"float innerradius\" 1", "Shape \"cylinder\" \"float zmin\" 1 \"float zmax\" 1"}) {
        const ImportedScene s = import_shapes(std::string(shape) + "\n");
        EXPECT_TRUE(s.document["shapes"].empty()) << shape;
        ASSERT_EQ(s.warnings.size(), 1u) << shape;
        EXPECT_NE(s.warnings[0].find("leaves no surface; skipped, as pbrt-v4 renders nothing"), std::string::npos)
            << s.warnings[0];
    }
}

TEST(PbrtQuadrics, ReverseOrientationOrAMirrorFlipsTheFrontNotBoth) {
    // pbrt-v4's quadrics flip their normal when ReverseOrientation xor the transform mirrors.
    const ImportedScene s = import_shapes(R"(AttributeBegin
ReverseOrientation
Shape "cylinder"
AttributeEnd
AttributeBegin
Scale -1 1 1
Shape "cylinder"
AttributeEnd
AttributeBegin
ReverseOrientation
Scale -1 1 1
Shape "cylinder"
AttributeEnd
)");
    const auto& shapes = s.document["shapes"];
    EXPECT_EQ(shapes[0]["reverse_orientation"], true);
    EXPECT_EQ(shapes[1]["reverse_orientation"], true);
    EXPECT_FALSE(shapes[2].contains("reverse_orientation"));
}

TEST(PbrtQuadrics, EmittingCylinderPowerDividesByPbrtsArea) {
    // pbrt-v4's DiffuseAreaLight: scale = power / (pi area), area = the shape's Area() (object
    // space for quadrics), L at luminance 1.
    const ImportedScene s = import(R"(WorldBegin
AreaLightSource "diffuse" "float power" 10
Shape "cylinder" "float radius" 0.5 "float zmin" 0 "float zmax" 2 "float phimax" 180
)");
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    const auto& c = s.document["shapes"][0];
    const double area = kPiD * 0.5 * 2.0;
    EXPECT_NEAR(c["emission_scale"].get<double>(), 10.0 / (kPiD * area), 1e-9);
    const Scene scene = load_imported_scene(s, test::kInlineFile);
    EXPECT_FALSE(scene.shapes[0].emission.is_black());
}

TEST(PbrtQuadrics, TheFuzzingSeedLoadsWithoutWarnings) {
    const Scene scene = load_scene_file(std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "quadrics.pbrt");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.quadrics.size(), 4u);
    EXPECT_EQ(scene.quadrics[1].kind, QuadricKind::kSphere);
    EXPECT_EQ(scene.quadrics[2].kind, QuadricKind::kDisk);
    EXPECT_TRUE(scene.quadrics[3].reverse_orientation);
    EXPECT_FALSE(scene.shapes[3].emission.is_black());
}

}  // namespace
}  // namespace candela::pbrt
