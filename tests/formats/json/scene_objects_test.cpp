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

}  // namespace
}  // namespace candela
