// Instances render as the same shapes placed directly by the same transforms: the Cornell box with
// its tall block made of glass and mirrored (a transform with negative determinant: if the
// instance's normals came out on the wrong side, the glass would refract inside out) and its short
// block an anisotropic rough metal, rotated and stretched (its tangent frame comes from the
// instance's shading geometry), once as instances of objects and once as plain shapes. The hits
// differ in their last bits (object-space intersection), so the images agree within their noise:
// z-tests of every block and the whole image on two independent renders.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kBlock = 8;

// The transforms, as the scene file writes them: the tall block mirrored across its own centre
// plane x = 368.5, the short one stretched and turned about its centre.
constexpr const char* kMirror = R"([{"translate": [-368.5, 0, 0]}, {"scale": [-1, 1, 1]}, {"translate": [368.5, 0, 0]}])";
constexpr const char* kStretch =
    R"([{"translate": [-185, 0, -169]}, {"scale": [0.8, 1.6, 1.1]}, {"rotate": {"axis": [0, 1, 0], "angle": 25}},
        {"translate": [185, 0, 169]}])";

std::string cornell_box(bool instanced) {
    std::string objects, blocks;
    if (instanced) {
        objects = R"(, "objects": {
            "tall": {"shapes": [{"type": "mesh", "file": "meshes/tall_block.obj", "material": "glass"}]},
            "short": {"shapes": [{"type": "mesh", "file": "meshes/short_block.obj", "material": "brushed"}]}})";
        blocks = std::string(R"({"type": "instance", "object": "tall", "transform": )") + kMirror + "},\n" +
                 R"({"type": "instance", "object": "short", "transform": )" + kStretch + "}";
    } else {
        blocks = std::string(R"({"type": "mesh", "file": "meshes/tall_block.obj", "material": "glass", "transform": )") +
                 kMirror + "},\n" +
                 R"({"type": "mesh", "file": "meshes/short_block.obj", "material": "brushed", "transform": )" +
                 kStretch + "}";
    }
    return R"({
  "integrator": {"type": "path", "max_depth": 12},
  "sampler": {"type": "independent", "spp": 256, "seed": )" +
           std::string(instanced ? "1" : "2") + R"(},
  "camera": {"type": "perspective", "position": [278, 273, -800], "look_at": [278, 273, 0],
             "up": [0, 1, 0], "fov": 40, "resolution": [32, 32]},
  "materials": {
    "white": {"type": "diffuse", "albedo": [0.725, 0.71, 0.68]},
    "red":   {"type": "diffuse", "albedo": [0.63, 0.065, 0.05]},
    "green": {"type": "diffuse", "albedo": [0.14, 0.45, 0.091]},
    "glass": {"type": "dielectric", "ior": 1.5},
    "brushed": {"type": "conductor", "metal": "Cu", "roughness": [0.05, 0.4]}
  })" + objects + R"(,
  "shapes": [
    {"type": "mesh", "file": "meshes/white_walls.obj", "material": "white"},
    {"type": "mesh", "file": "meshes/left_wall.obj", "material": "red"},
    {"type": "mesh", "file": "meshes/right_wall.obj", "material": "green"},
    )" + blocks + R"(,
    {"type": "quad", "corner": [343, 548.7, 227], "edge1": [0, 0, 105], "edge2": [-130, 0, 0],
     "material": "white", "emission": [47.8348, 38.5664, 31.0808]}
  ]
})";
}

Scene load(bool instanced) {
    return load_scene_from_string(cornell_box(instanced),
                                  std::filesystem::path(CANDELA_SOURCE_DIR) / "scenes" / "cornell-box" / "inline.json");
}

TEST(InstanceRender, InstancesRenderAsShapesPlacedDirectly) {
    const Scene instanced = load(true), direct = load(false);
    ASSERT_EQ(instanced.instances.size(), 2u);
    ASSERT_TRUE(direct.instances.empty());
    ASSERT_TRUE(instanced.materials[instanced.shapes[1].material].needs_shading_geometry);
    const test::RenderMoments a = test::render_moments(instanced), b = test::render_moments(direct);
    EXPECT_EQ(a.dropped, 0u);
    EXPECT_EQ(b.dropped, 0u);
    test::ZTestFamily family = test::compare_blocks_and_whole(a, b, kBlock);
    if (!family.passed()) {
        test::write_diagnostic(a, "instance_render_instanced");
        test::write_diagnostic(b, "instance_render_direct");
    }
    EXPECT_TRUE(family.passed()) << family.summary();
}

// The control: the test sees a glass block mirrored the wrong way round (its normals inwards), so
// agreement above is not for want of power.
TEST(InstanceRender, ReversedGlassIsSeen) {
    std::string json = cornell_box(false);
    const std::string glass = R"("material": "glass", "transform")";
    json.replace(json.find(glass), glass.size(), R"("material": "glass", "reverse_orientation": true, "transform")");
    const Scene reversed =
        load_scene_from_string(json, std::filesystem::path(CANDELA_SOURCE_DIR) / "scenes" / "cornell-box" / "x.json");
    const test::RenderMoments a = test::render_moments(load(true)), b = test::render_moments(reversed);
    test::ZTestFamily family = test::compare_blocks_and_whole(a, b, kBlock);
    EXPECT_FALSE(family.passed()) << family.summary();
}

}  // namespace
}  // namespace candela
