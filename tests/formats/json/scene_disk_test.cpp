// The scene file's `disk` shape: centre, normal, radius, transform, reverse_orientation and
// emission change the loaded disk; bad values are located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene with one material "m" and one disk with the given keys (besides type and material).
Scene load_disk(const std::string& keys) {
    return load_json(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [{"type": "disk", "material": "m", )" +
                     keys + "}]}");
}

void expect_near(const Vec3d& a, const Vec3d& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneLoaderDisk, CenterNormalAndRadius) {
    Scene s = load_disk(R"("center": [1, 2, 3], "normal": [0, -2, 0], "radius": 0.5)");
    ASSERT_EQ(s.disks.size(), 1u);
    ASSERT_EQ(s.shapes.size(), 1u);
    EXPECT_EQ(s.shapes[0].kind, ShapeKind::kDisk);
    EXPECT_EQ(s.shapes[0].index, 0u);
    const Disk& d = s.disks[0];
    expect_near(d.center, {1, 2, 3});
    expect_near(d.normal, {0, -1, 0});
    EXPECT_NEAR(length(d.axis_u), 0.5, 1e-15);
    EXPECT_NEAR(length(d.axis_v), 0.5, 1e-15);
    EXPECT_NEAR(d.area(), kPiD * 0.25, 1e-15);
}

TEST(SceneLoaderDisk, EmissionMakesItALight) {
    Scene s = load_disk(R"("center": [0, 5, 0], "normal": [0, -1, 0], "radius": 1, "emission": [20, 10, 5],
                           "two_sided": true)");
    EXPECT_EQ(s.shapes[0].emission, Rgb(20, 10, 5));
    EXPECT_TRUE(s.shapes[0].two_sided);
    EXPECT_TRUE(s.warnings.empty());  // a light: no "no lights" warning
}

TEST(SceneLoaderDisk, TransformMovesScalesAndTurnsIt) {
    Scene s = load_disk(R"("center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
                           "transform": [{"scale": [2, 1, 1]}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                                         {"translate": [0, 3, 0]}])");
    const Disk& d = s.disks[0];
    expect_near(d.center, {0, 3, 0});
    expect_near(d.normal, {0, -1, 0});  // +z turned 90 degrees about +x
    EXPECT_NEAR(d.area(), 2.0 * kPiD, 1e-12);  // an ellipse of semi-axes 2 and 1
    expect_near(d.axis_u, {2, 0, 0});
}

TEST(SceneLoaderDisk, ReverseOrientationFlipsItsFront) {
    Scene s = load_disk(R"("center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1, "reverse_orientation": true)");
    expect_near(s.disks[0].normal, {0, 0, -1});
    // A mirroring transform alone keeps the front; with reverse_orientation it flips.
    Scene mirrored = load_disk(R"("center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
                                  "transform": [{"scale": [-1, 1, 1]}])");
    expect_near(mirrored.disks[0].normal, {0, 0, 1});
}

// The error's pointer and message for a disk with the given keys.
void expect_error(const std::string& keys, const std::string& pointer, const std::string& message) {
    SceneError e = load_error(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [{"type": "disk",
                                  "material": "m", )" + keys + "}]}");
    EXPECT_EQ(e.where().json_pointer, pointer) << keys;
    EXPECT_EQ(e.message(), message) << keys;
}

TEST(SceneLoaderDisk, BadValuesAreLocated) {
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": -1)", "/shapes/0/radius",
                 "expected a number > 0, got -1");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": 0)", "/shapes/0/radius",
                 "expected a number > 0, got 0");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 0, 0], "radius": 1)", "/shapes/0/normal",
                 "expected a nonzero normal, got [0, 0, 0]");
    expect_error(R"("center": [0, 0, 0], "radius": 1)", "/shapes/0", "missing required key \"normal\"");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1e-30)", "/shapes/0/radius",
                 "the disk has no area in float precision (its radius is too small)");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1e39)", "/shapes/0/radius",
                 "the disk reaches beyond float range");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1, "transform": [{"scale": 1e-20}])",
                 "/shapes/0/transform", "the transform leaves the disk with no area in float precision");
    expect_error(R"("center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1, "edge1": [1, 0, 0])", "/shapes/0",
                 "unknown key \"edge1\"; expected one of: center, emission, emission_scale, exterior, inner_radius, "
                 "interior, material, motion, normal, phi_max, radius, reverse_orientation, transform, two_sided, "
                 "type");
}

}  // namespace
}  // namespace candela
