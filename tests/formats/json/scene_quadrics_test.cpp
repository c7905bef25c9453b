// The scene file's clipped quadrics (scene_quadrics.cpp): `cylinder`, and `sphere` and `disk` with
// z_min, z_max, phi_max, inner_radius; each key changes the loaded quadric; bad values are
// located errors (more in tests/data/bad_inputs/).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/math/constants.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

Scene load_shape(const std::string& shape) {
    return load_json(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [{"material": "m", )" + shape + "}]}");
}

void expect_error(const std::string& shape, const std::string& pointer, const std::string& message) {
    SceneError e = load_error(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [{"material": "m", )" + shape + "}]}");
    EXPECT_EQ(e.where().json_pointer, pointer) << shape;
    EXPECT_EQ(e.message(), message) << shape;
}

TEST(SceneLoaderQuadrics, CylinderKeys) {
    const Scene s = load_shape(R"("type": "cylinder", "radius": 2, "z_min": -0.5, "z_max": 1.5, "phi_max": 90,
                                  "reverse_orientation": true, "transform": [{"translate": [1, 0, 0]}])");
    ASSERT_EQ(s.quadrics.size(), 1u);
    EXPECT_EQ(s.shapes[0].kind, ShapeKind::kQuadric);
    const Quadric& q = s.quadrics[0];
    EXPECT_EQ(q.kind, QuadricKind::kCylinder);
    EXPECT_EQ(q.radius, 2.0);
    EXPECT_EQ(q.z_min, -0.5);
    EXPECT_EQ(q.z_max, 1.5);
    EXPECT_NEAR(q.phi_max, kPiD / 2, 1e-15);
    EXPECT_TRUE(q.reverse_orientation);
    EXPECT_EQ(q.to_world.apply_point(Vec3d(0, 0, 0)).x, 1.0);
    // Defaults: pbrt-v4's z range [-1, 1], phi_max 360.
    const Scene defaults = load_shape(R"("type": "cylinder", "radius": 1)");
    const Quadric& d = defaults.quadrics[0];
    EXPECT_EQ(d.z_min, -1.0);
    EXPECT_EQ(d.z_max, 1.0);
    EXPECT_NEAR(d.phi_max, 2 * kPiD, 1e-15);
    EXPECT_FALSE(d.reverse_orientation);
}

TEST(SceneLoaderQuadrics, PartialSphereIsCentredAndClampsItsZRange) {
    const Scene s = load_shape(R"("type": "sphere", "center": [1, 2, 3], "radius": 1, "z_min": -5, "z_max": 0.5)");
    ASSERT_EQ(s.quadrics.size(), 1u);
    EXPECT_TRUE(s.spheres.empty());
    const Quadric& q = s.quadrics[0];
    EXPECT_EQ(q.kind, QuadricKind::kSphere);
    EXPECT_EQ(q.z_min, -1.0);  // clamped to the radius, as pbrt-v4 clamps it
    EXPECT_EQ(q.z_max, 0.5);
    const Vec3d c = q.to_world.apply_point(Vec3d(0, 0, 0));
    EXPECT_EQ(c.x, 1.0);
    EXPECT_EQ(c.z, 3.0);
    // Without partial keys, a sphere is candela's own.
    EXPECT_EQ(load_shape(R"("type": "sphere", "center": [1, 2, 3], "radius": 1)").spheres.size(), 1u);
}

TEST(SceneLoaderQuadrics, PartialDiskHasTheRoundDisksFrame) {
    const Scene s = load_shape(R"("type": "disk", "center": [0, 1, 0], "normal": [0, 0, 1], "radius": 2,
                                  "inner_radius": 0.5, "phi_max": 180, "emission": 3)");
    ASSERT_EQ(s.quadrics.size(), 1u);
    const Quadric& q = s.quadrics[0];
    EXPECT_EQ(q.kind, QuadricKind::kDisk);
    EXPECT_EQ(q.inner_radius, 0.5);
    EXPECT_NEAR(q.object_area(), 0.5 * kPiD * (4 - 0.25), 1e-12);
    // Normal +z: the frame is the world's axes, so phi runs from +x.
    const Vec3d p = q.to_world.apply_point(Vec3d(2, 0, 0));
    EXPECT_NEAR(p.x, 2.0, 1e-15);
    EXPECT_NEAR(p.y, 1.0, 1e-15);
    EXPECT_EQ(s.shapes[0].emission, Rgb(3.0f));
}

TEST(SceneLoaderQuadrics, BadValuesAreLocated) {
    expect_error(R"("type": "cylinder", "radius": 1, "z_min": 1, "z_max": 1)", "/shapes/0/z_max",
                 "expected z_min < z_max, got z_min 1 and z_max 1");
    expect_error(R"("type": "cylinder", "radius": 1, "phi_max": 361)", "/shapes/0/phi_max",
                 "expected a number in (0, 360], got 361");
    expect_error(R"("type": "cylinder", "radius": 0)", "/shapes/0/radius", "expected a number > 0, got 0");
    expect_error(R"("type": "sphere", "center": [0, 0, 0], "radius": 1, "z_min": -3, "z_max": -1)", "/shapes/0/z_max",
                 "the z range [-3, -1] misses the sphere of radius 1");
    expect_error(R"("type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1, "inner_radius": -0.5)",
                 "/shapes/0/inner_radius", "expected a number >= 0, got -0.5");
    expect_error(R"("type": "cylinder", "radius": 1, "transform": [{"scale": [1, 0, 1]}])", "/shapes/0/transform/0/scale/1",
                 "expected a nonzero scale factor, got 0");
    expect_error(R"("type": "cylinder", "radius": 1, "height": 1)", "/shapes/0",
                 "unknown key \"height\"; expected one of: emission, emission_scale, exterior, interior, material, "
                 "motion, phi_max, radius, reverse_orientation, transform, two_sided, type, z_max, z_min");
}

}  // namespace
}  // namespace candela
