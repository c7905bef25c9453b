// The scene file's `objects` and `instance` shapes (pbrt-v4's ObjectBegin / ObjectInstance): what
// they load into, and the located errors for what they may not hold.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/scene/memory_budget.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// A scene with materials "m" and "n", the given objects (a JSON object's contents) and shapes.
std::string scene_with(const std::string& objects, const std::string& shapes) {
    return R"({"materials": {"m": {"type": "diffuse"}, "n": {"type": "diffuse"}},
               "objects": {)" +
           objects + R"(}, "shapes": [)" + shapes + "]}";
}

const std::string kTree =
    R"("tree": {"shapes": [
         {"type": "sphere", "center": [0, 2, 0], "radius": 1, "material": "n"},
         {"type": "mesh", "file": "meshes/triangle.obj", "material": "m",
          "transform": [{"translate": [0, 0, 5]}]}]})";

TEST(SceneObjects, ObjectShapesStayInObjectSpaceAndInstancesPlaceThem) {
    const Scene s = load_json(scene_with(
        kTree + R"(, "rock": {"shapes": [{"type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1,
                                         "material": "m"}]})",
        R"({"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], "material": "m"},
           {"type": "instance", "object": "rock"},
           {"type": "instance", "object": "tree", "transform": [{"scale": 2}, {"translate": [10, 0, 0]}]})"));
    ASSERT_EQ(s.object_names, (std::vector<std::string>{"tree", "rock"}));
    ASSERT_EQ(s.objects.size(), 2u);
    // Objects' shapes come first, in file order, then the world's own.
    EXPECT_EQ(s.objects[0].first_shape, 0u);
    EXPECT_EQ(s.objects[0].shape_count, 2u);
    EXPECT_EQ(s.objects[1].first_shape, 2u);
    EXPECT_EQ(s.objects[1].shape_count, 1u);
    ASSERT_EQ(s.shapes.size(), 4u);  // the instances are not shapes
    EXPECT_EQ(s.shapes[0].kind, ShapeKind::kSphere);
    EXPECT_EQ(s.shapes[0].material, 1u);
    EXPECT_EQ(s.shapes[1].kind, ShapeKind::kMesh);
    EXPECT_EQ(s.shapes[2].kind, ShapeKind::kDisk);
    EXPECT_EQ(s.shapes[3].kind, ShapeKind::kMesh);
    // The sphere keeps its object-space centre; the mesh its own transform only.
    EXPECT_EQ(s.spheres[0].center, Vec3d(0, 2, 0));
    const TriangleMesh& triangle = s.meshes[s.shapes[1].index];
    for (const Vec3f& p : triangle.positions) EXPECT_EQ(p.z, 5.0f);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].object, 1u);
    EXPECT_EQ(s.instances[0].to_world.apply_point(Vec3d(1, 2, 3)), Vec3d(1, 2, 3));
    EXPECT_EQ(s.instances[1].object, 0u);
    EXPECT_EQ(s.instances[1].to_world.apply_point(Vec3d(1, 1, 1)), Vec3d(12, 2, 2));
    EXPECT_EQ(s.instances[1].to_object.apply_point(Vec3d(12, 2, 2)), Vec3d(1, 1, 1));
}

TEST(SceneObjects, AnObjectMayBeEmptyOrNeverInstanced) {
    const Scene s = load_json(scene_with(R"("empty": {"shapes": []}, )" + kTree, R"({"type": "instance", "object": "empty"})"));
    EXPECT_EQ(s.objects[0].shape_count, 0u);
    EXPECT_EQ(s.objects[1].shape_count, 2u);
    EXPECT_EQ(s.instances.size(), 1u);
}

// Each instance costs a fixed record in the memory estimate, not another copy of its object.
TEST(SceneObjects, MemoryEstimateCountsAMatrixPerInstance) {
    std::string instances;
    for (int i = 0; i < 100; ++i) instances += std::string(i ? ", " : "") + R"({"type": "instance", "object": "tree"})";
    const Scene one = load_json(scene_with(kTree, R"({"type": "instance", "object": "tree"})"));
    const Scene hundred = load_json(scene_with(kTree, instances));
    EXPECT_EQ(scene_memory_bytes(hundred) - scene_memory_bytes(one), 99 * instance_memory_bytes());
    EXPECT_LT(instance_memory_bytes(), 4096u);
}

struct ErrorCase {
    std::string objects, shapes, pointer, message;
};

void expect_error(const ErrorCase& c) {
    const SceneError e = load_error(scene_with(c.objects, c.shapes));
    EXPECT_EQ(e.where().json_pointer, c.pointer) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
}

TEST(SceneObjects, UnknownObjectsAreLocatedWithTheNearestName) {
    expect_error({kTree, R"({"type": "instance", "object": "tre"})", "/shapes/0/object",
                  "unknown object \"tre\" (did you mean \"tree\"?)"});
    expect_error({kTree, R"({"type": "instance", "object": "boulder"})", "/shapes/0/object",
                  "unknown object \"boulder\"; defined objects: tree"});
    const SceneError none = load_error(R"({"shapes": [{"type": "instance", "object": "tree"}]})");
    EXPECT_EQ(none.where().json_pointer, "/shapes/0/object");
    EXPECT_NE(std::string(none.what()).find("no objects are defined"), std::string::npos) << none.what();
    // An object is defined in `objects`, not by the instance's other keys.
    expect_error({kTree, R"({"type": "instance", "object": "tree", "material": "m"})", "/shapes/0",
                  "unknown key \"material\""});
    expect_error({kTree, R"({"type": "instance"})", "/shapes/0", "missing required key \"object\""});
}

TEST(SceneObjects, ObjectsCannotEmitNorHoldInstances) {
    expect_error({R"("lamp": {"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
                                          "emission": [1, 1, 1]}]})",
                  "", "/objects/lamp/shapes/0", "the shapes of object \"lamp\" cannot emit"});
    expect_error({R"("lamp": {"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
                                          "two_sided": true}]})",
                  "", "/objects/lamp/shapes/0", "cannot emit"});
    expect_error({kTree + R"(, "forest": {"shapes": [{"type": "instance", "object": "tree"}]})", "",
                  "/objects/forest/shapes/0/type", "object \"forest\" cannot hold an instance: objects do not nest"});
    expect_error({R"("tree": {"shape": []})", "", "/objects/tree", "\"shape\""});
}

TEST(SceneObjects, InstanceTransformsAreCheckedAgainstTheObject) {
    expect_error({kTree, R"({"type": "instance", "object": "tree", "transform": [{"scale": 1e38}]})",
                  "/shapes/0/transform", "the transform moves object \"tree\" beyond float range"});
    expect_error({kTree, R"({"type": "instance", "object": "tree", "transform": [{"scale": 1e-39}]})",
                  "/shapes/0/transform", "the transform of object \"tree\" has an inverse beyond float range"});
    expect_error({kTree, R"({"type": "instance", "object": "tree", "transform": [{"scale": [1, 0, 1]}]})",
                  "/shapes/0/transform/0/scale/1", "a nonzero scale factor"});
}

// --- motion (geometry/instance_motion.h)

TEST(SceneObjects, AMovingInstanceKeepsItsPathAndEndTransform) {
    const Scene s = load_json(scene_with(kTree, R"({"type": "instance", "object": "tree",
        "transform": [{"translate": [1, 0, 0]}],
        "motion": {"transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [4, 0, 0]}],
                   "times": [0, 2]}})"));
    ASSERT_EQ(s.instances.size(), 1u);
    ASSERT_EQ(s.instances[0].motion, 0u);
    ASSERT_EQ(s.instance_motions.size(), 1u);
    const AnimatedTransform& path = s.instance_motions[0].path;
    EXPECT_EQ(path.start().apply_point(Vec3d(0, 0, 0)), Vec3d(1, 0, 0));
    EXPECT_NEAR(path.end().apply_point(Vec3d(1, 0, 0)).z, -1.0, 1e-12);
    EXPECT_EQ(path.end_time(), 2.0);
    EXPECT_TRUE(s.instance_motions[0].placement.is_identity());
    // At the shutter's opening (0) the instance is at its start.
    EXPECT_EQ(s.instances[0].to_world.m[0][3], 1.0f);
}

TEST(SceneObjects, AMovingShapeBecomesAOneShapeObjectAndItsInstance) {
    const Scene s = load_json(scene_with(kTree, R"(
        {"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], "material": "m",
         "transform": [{"translate": [0, 0, 2]}], "motion": {"transform": [{"translate": [3, 0, 2]}]}},
        {"type": "sphere", "center": [0, 5, 0], "radius": 1, "material": "n",
         "motion": {"transform": [{"translate": [0, 1, 0]}]}},
        {"type": "sphere", "center": [0, 9, 0], "radius": 1, "material": "n",
         "motion": {"transform": []}})"));
    // tree's two shapes, then the quad, the moving sphere and the sphere whose motion is none.
    ASSERT_EQ(s.shapes.size(), 5u);
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[1].first_shape, 2u);
    EXPECT_EQ(s.objects[1].shape_count, 1u);
    EXPECT_EQ(s.objects[2].first_shape, 3u);
    ASSERT_EQ(s.instances.size(), 2u);
    ASSERT_EQ(s.instance_motions.size(), 2u);
    // The quad's geometry is placed at its start; the placement takes it back to the quad's space.
    EXPECT_EQ(s.meshes.back().positions[0], Vec3f(0, 0, 2));
    const InstanceMotion& quad = s.instance_motions[0];
    EXPECT_EQ((quad.path.end() * quad.placement).apply_point(Vec3d(0, 0, 2)), Vec3d(3, 0, 2));
    // A whole sphere starts where its centre is: the end moves it up by 1.
    const InstanceMotion& sphere = s.instance_motions[1];
    EXPECT_EQ((sphere.path.end() * sphere.placement).apply_point(Vec3d(0, 5, 0)), Vec3d(0, 6, 0));
}

TEST(SceneObjects, BadMotionsAreLocatedErrors) {
    const std::string quad = R"({"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], )";
    auto error_at = [&](const std::string& shapes, const std::string& objects = "") {
        return load_error(scene_with(objects, shapes)).where().json_pointer;
    };
    EXPECT_EQ(error_at(quad + R"("material": "m", "motion": [1, 2]})"), "/shapes/0/motion");
    EXPECT_EQ(error_at(quad + R"("material": "m", "motion": {"times": [0, 1]}})"), "/shapes/0/motion");
    EXPECT_EQ(error_at(quad + R"("material": "m", "motion": {"transform": [{"scale": [-1, 1, 1]}]}})"),
              "/shapes/0/motion/transform");
    EXPECT_EQ(error_at(quad + R"("material": "m", "motion": {"transform": [], "times": [1, 1]}})"),
              "/shapes/0/motion/times/1");
    EXPECT_EQ(error_at(quad + R"("material": "m", "emission": 1, "motion": {"transform": []}})"), "/shapes/0");
    EXPECT_EQ(error_at(quad + R"("material": "m", "motion": {"transform": [], "speed": 1}})"), "/shapes/0/motion");
    EXPECT_EQ(error_at("", R"("o": {"shapes": [)" + quad +
                               R"("material": "m", "motion": {"transform": [{"translate": [1, 0, 0]}]}}]})"),
              "/objects/o/shapes/0/motion");
    EXPECT_EQ(error_at(quad +
                       R"("material": "m", "motion": {"transform": [{"translate": [1e38, 0, 0]}, {"scale": 100}]}})"),
              "/shapes/0/motion");
    EXPECT_EQ(error_at(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
                          "transform": [], "motion": {"transform": []}})"),
              "/shapes/0");  // a whole sphere takes no transform, moving or not
}

}  // namespace
}  // namespace candela
