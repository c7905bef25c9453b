// The scene file's materials, shapes, transforms and lights: every documented key, set to a value
// other than its default, changes the loaded Scene.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

constexpr float kTol = 1e-5f;

// A scene with one material "m" and the given shapes (a JSON array's contents).
Scene load_shapes(const std::string& shapes) {
    return load_json(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [)" + shapes + "]}");
}

// The unit quad in the z = 0 plane, front +z, with extra keys appended.
std::string unit_quad(const std::string& extra = "") {
    return R"({"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0],
               "material": "m")" +
           (extra.empty() ? "" : ", " + extra) + "}";
}

// The normal of a triangle's front face: counter-clockwise winding, right-hand rule.
Vec3f front_normal(const TriangleMesh& mesh, size_t triangle) {
    const Vec3f& p0 = mesh.positions[mesh.indices[3 * triangle]];
    const Vec3f& p1 = mesh.positions[mesh.indices[3 * triangle + 1]];
    const Vec3f& p2 = mesh.positions[mesh.indices[3 * triangle + 2]];
    return normalize(cross(p1 - p0, p2 - p0));
}

void expect_near(const Vec3f& a, const Vec3f& b) {
    EXPECT_NEAR(a.x, b.x, kTol);
    EXPECT_NEAR(a.y, b.y, kTol);
    EXPECT_NEAR(a.z, b.z, kTol);
}

bool has_position(const TriangleMesh& mesh, const Vec3f& p) {
    for (const Vec3f& q : mesh.positions)
        if (length(q - p) < kTol) return true;
    return false;
}

// ---- materials

// The one lobe of material `index`, as a T (the test fails if it is another lobe).
template <class T>
T only_lobe(const Scene& s, size_t index) {
    const Bsdf& bsdf = s.materials.at(index).bsdf;
    EXPECT_EQ(bsdf.lobe_count, 1u);
    const T* lobe = std::get_if<T>(&bsdf.lobes[0]);
    EXPECT_NE(lobe, nullptr);
    return lobe != nullptr ? *lobe : T{};
}

TEST(SceneLoaderMaterials, DiffuseAlbedoIsRead) {
    Scene grey = load_json(R"({"materials": {"a": {"type": "diffuse", "albedo": 0.25}}})");
    EXPECT_EQ(only_lobe<LambertianLobe>(grey, 0).reflectance, Color(0.25f));
    Scene rgb = load_json(R"({"materials": {"a": {"type": "diffuse", "albedo": [0.1, 0.2, 0.3]}}})");
    EXPECT_EQ(only_lobe<LambertianLobe>(rgb, 0).reflectance, Color(0.1f, 0.2f, 0.3f));
    Scene plain = load_json(R"({"materials": {"a": {"type": "diffuse"}}})");
    EXPECT_EQ(only_lobe<LambertianLobe>(plain, 0).reflectance, Color(0.5f));
}

TEST(SceneLoaderMaterials, MirrorAlbedoIsRead) {
    Scene s = load_json(R"({"materials": {"a": {"type": "mirror", "albedo": 0.8},
                                          "b": {"type": "mirror"}}})");
    EXPECT_EQ(only_lobe<SpecularReflectionLobe>(s, 0).reflectance, Color(0.8f));
    EXPECT_EQ(only_lobe<SpecularReflectionLobe>(s, 1).reflectance, Color(1.0f));
}

TEST(SceneLoaderMaterials, DielectricIorAndTintAreRead) {
    Scene s = load_json(R"({"materials": {"a": {"type": "dielectric", "ior": 2.4,
                                                "tint": [1, 0.5, 0.25]},
                                          "b": {"type": "dielectric"},
                                          "c": {"type": "dielectric", "ior": 1}}})");
    auto a = only_lobe<FresnelSpecularLobe>(s, 0);
    EXPECT_EQ(a.eta, 2.4f);
    EXPECT_EQ(a.tint, Color(1.0f, 0.5f, 0.25f));
    auto b = only_lobe<FresnelSpecularLobe>(s, 1);
    EXPECT_EQ(b.eta, 1.5f);
    EXPECT_EQ(b.tint, Color(1.0f));
    // An index of 1 (an interface that does not bend light) is allowed.
    EXPECT_EQ(only_lobe<FresnelSpecularLobe>(s, 2).eta, 1.0f);
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "dielectric", "ior": 0}}})").message(),
              "expected a number > 0, got 0");
}

TEST(SceneLoaderMaterials, DielectricFresnelSelectsSchlick) {
    Scene s = load_json(R"({"materials": {"a": {"type": "dielectric", "fresnel": "schlick"},
                                          "b": {"type": "dielectric", "fresnel": "exact"},
                                          "c": {"type": "dielectric"}}})");
    EXPECT_TRUE(only_lobe<FresnelSpecularLobe>(s, 0).schlick);
    EXPECT_FALSE(only_lobe<FresnelSpecularLobe>(s, 1).schlick);
    EXPECT_FALSE(only_lobe<FresnelSpecularLobe>(s, 2).schlick);
    EXPECT_EQ(
        load_error(R"({"materials": {"a": {"type": "dielectric", "fresnel": true}}})").message(),
        "expected a fresnel (one of: exact, schlick), got true");
}

TEST(SceneLoaderMaterials, TransmissionIorAndTintAreRead) {
    Scene s = load_json(R"({"materials": {"a": {"type": "transmission", "ior": 1.33, "tint": 0.5},
                                          "b": {"type": "transmission"}}})");
    auto a = only_lobe<SpecularTransmissionLobe>(s, 0);
    EXPECT_EQ(a.eta, 1.33f);
    EXPECT_EQ(a.tint, Color(0.5f));
    auto b = only_lobe<SpecularTransmissionLobe>(s, 1);
    EXPECT_EQ(b.eta, 1.5f);
    EXPECT_EQ(b.tint, Color(1.0f));
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "transmission", "fresnel": "exact"}}})")
                  .message(),
              "unknown key \"fresnel\"; expected one of: alpha, bump_map, ior, normal_map, normal_map_convention, tint, type");
}

TEST(SceneLoaderMaterials, MixConcatenatesTheLobesInOrder) {
    Scene s = load_json(R"({"materials": {"m": {"type": "mix", "lobes": [
        {"type": "diffuse", "albedo": 0.5}, {"type": "mirror", "albedo": 0.25},
        {"type": "dielectric", "ior": 1.33, "fresnel": "schlick"},
        {"type": "transmission", "ior": 2}]}}})");
    const Bsdf& bsdf = s.materials[0].bsdf;
    ASSERT_EQ(bsdf.lobe_count, 4u);
    EXPECT_EQ(std::get<LambertianLobe>(bsdf.lobes[0]).reflectance, Color(0.5f));
    EXPECT_EQ(std::get<SpecularReflectionLobe>(bsdf.lobes[1]).reflectance, Color(0.25f));
    EXPECT_EQ(std::get<FresnelSpecularLobe>(bsdf.lobes[2]).eta, 1.33f);
    EXPECT_TRUE(std::get<FresnelSpecularLobe>(bsdf.lobes[2]).schlick);
    EXPECT_EQ(std::get<SpecularTransmissionLobe>(bsdf.lobes[3]).eta, 2.0f);
    // One part is a mix too.
    Scene one =
        load_json(R"({"materials": {"m": {"type": "mix", "lobes": [{"type": "mirror"}]}}})");
    EXPECT_EQ(only_lobe<SpecularReflectionLobe>(one, 0).reflectance, Color(1.0f));
}

TEST(SceneLoaderMaterials, MixPartsAreCheckedLikeMaterials) {
    SceneError e = load_error(R"({"materials": {"m": {"type": "mix", "lobes": [
        {"type": "diffuse"}, {"type": "mirror", "ior": 1.5}]}}})");
    EXPECT_EQ(e.where().json_pointer, "/materials/m/lobes/1");
    EXPECT_EQ(e.message(), "unknown key \"ior\"; expected one of: albedo, type");
    SceneError missing = load_error(R"({"materials": {"m": {"type": "mix"}}})");
    EXPECT_EQ(missing.message(), "missing required key \"lobes\"");
    SceneError not_array = load_error(R"({"materials": {"m": {"type": "mix", "lobes": {}}}})");
    EXPECT_EQ(not_array.message(), "expected an array, got an empty object");
    SceneError extra = load_error(
        R"({"materials": {"m": {"type": "mix", "lobes": [{"type": "mirror"}], "albedo": 1}}})");
    EXPECT_EQ(extra.message(), "unknown key \"albedo\"; expected one of: alpha, bump_map, lobes, normal_map, normal_map_convention, type");
}

TEST(SceneLoaderMaterials, NamesKeepFileOrderAndParallelTheMaterials) {
    Scene s = load_json(R"({"materials": {"zinc": {"type": "mirror"}, "ash": {"type": "diffuse"},
                                          "glass": {"type": "dielectric"}}})");
    ASSERT_EQ(s.material_names, (std::vector<std::string>{"zinc", "ash", "glass"}));
    EXPECT_TRUE(std::holds_alternative<SpecularReflectionLobe>(s.materials[0].bsdf.lobes[0]));
    EXPECT_TRUE(std::holds_alternative<LambertianLobe>(s.materials[1].bsdf.lobes[0]));
    EXPECT_TRUE(std::holds_alternative<FresnelSpecularLobe>(s.materials[2].bsdf.lobes[0]));
}

TEST(SceneLoaderMaterials, KeysOfOtherTypesAreUnknown) {
    SceneError e = load_error(R"({"materials": {"a": {"type": "diffuse", "ior": 1.5}}})");
    EXPECT_EQ(e.where().json_pointer, "/materials/a");
    EXPECT_EQ(e.message(), "unknown key \"ior\"; expected one of: albedo, alpha, bump_map, normal_map, normal_map_convention, type");
    EXPECT_EQ(load_error(R"({"materials": {"a": {"albedo": 0.5}}})").message(),
              "missing required key \"type\"");
}

TEST(SceneLoaderMaterials, NormalMapIsReadOnAnyMaterial) {
    Scene s = load_json(R"({"materials": {"a": {"type": "diffuse", "normal_map": [0.6, 0.5, 0.9]},
                                          "b": {"type": "mirror", "normal_map": [0.5, 0.4, 1],
                                                "normal_map_convention": "directx"},
                                          "c": {"type": "mix", "lobes": [{"type": "diffuse"}],
                                                "normal_map": 0.75},
                                          "d": {"type": "dielectric"}}})");
    ASSERT_TRUE(s.materials[0].surface.normal_map);
    EXPECT_EQ(s.materials[0].surface.normal_map->value, Rgb(0.6f, 0.5f, 0.9f));
    EXPECT_EQ(s.materials[0].surface.normal_map_convention, NormalMapConvention::kOpenGl);
    EXPECT_TRUE(s.materials[0].needs_shading_geometry);
    EXPECT_TRUE(s.materials[0].per_hit);
    EXPECT_EQ(s.materials[1].surface.normal_map_convention, NormalMapConvention::kDirectX);
    ASSERT_TRUE(s.materials[2].surface.normal_map);
    EXPECT_EQ(s.materials[2].surface.normal_map->value, Rgb(0.75f));
    EXPECT_FALSE(s.materials[3].surface.normal_map);
    EXPECT_FALSE(s.materials[3].needs_shading_geometry);
    EXPECT_FALSE(s.materials[3].per_hit);
    // A file name is an image texture of it, read linearly (data, not colour); the same file as
    // an sRGB albedo is a second image.
    Scene files = load_json(R"({"textures": {"n": {"type": "image", "file": "textures/rgb_2x2.png",
                                                   "colorspace": "linear"}},
                                "materials": {"a": {"type": "diffuse", "normal_map": "textures/rgb_2x2.png",
                                                    "albedo": {"type": "image", "file": "textures/rgb_2x2.png"}},
                                              "b": {"type": "diffuse", "normal_map": {"texture": "n"}}}})");
    ASSERT_TRUE(files.materials[0].surface.normal_map);
    EXPECT_TRUE(files.materials[0].surface.normal_map->is_textured());
    EXPECT_TRUE(std::holds_alternative<ImageTexture>(files.textures.texture(files.materials[0].surface.normal_map->texture)));
    ASSERT_EQ(files.texture_files.size(), 2u);
    EXPECT_EQ(files.texture_files[0].colorspace, TextureColorspace::kLinear);
    EXPECT_EQ(files.texture_files[1].colorspace, TextureColorspace::kSrgb);
    EXPECT_EQ(files.materials[1].surface.normal_map->texture, 0u);  // "n", the linear file again
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "diffuse", "normal_map": "meshes/triangle.obj"}}})")
                  .where()
                  .json_pointer,
              "/materials/a/normal_map");
    SceneError alone = load_error(R"({"materials": {"a": {"type": "diffuse", "normal_map_convention": "opengl"}}})");
    EXPECT_EQ(alone.where().json_pointer, "/materials/a/normal_map_convention");
    EXPECT_EQ(alone.message(), "normal_map_convention needs a normal_map");
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "diffuse", "normal_map": 0.5,
                                                 "normal_map_convention": "vulkan"}}})")
                  .message(),
              "unknown normal map convention \"vulkan\"; expected one of: directx, opengl");
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "diffuse", "normal_map": 1.5}}})").message(),
              "expected a number in [0, 1], got 1.5");
    // A mix's parts are lobes: the surface keys belong to the mix.
    EXPECT_EQ(load_error(R"({"materials": {"m": {"type": "mix", "lobes": [{"type": "mirror", "alpha": 0.5}]}}})")
                  .where()
                  .json_pointer,
              "/materials/m/lobes/0");
}

TEST(SceneLoaderMaterials, BumpMapIsReadOnAnyMaterial) {
    Scene s = load_json(R"({"materials": {"a": {"type": "dielectric", "bump_map": -0.25},
                                          "b": {"type": "diffuse"}}})");
    ASSERT_TRUE(s.materials[0].surface.bump_map);
    EXPECT_EQ(s.materials[0].surface.bump_map->value, -0.25f);
    EXPECT_TRUE(s.materials[0].needs_shading_geometry);
    EXPECT_FALSE(s.materials[1].surface.bump_map);
    SceneError both = load_error(R"({"materials": {"a": {"type": "diffuse", "normal_map": 0.5, "bump_map": 1}}})");
    EXPECT_EQ(both.where().json_pointer, "/materials/a/bump_map");
    EXPECT_EQ(both.message(), "give \"normal_map\" or \"bump_map\", not both");
}

TEST(SceneLoaderMaterials, AlphaIsReadOnAnyMaterial) {
    Scene s = load_json(R"({"materials": {"a": {"type": "diffuse", "alpha": 0.25},
                                          "b": {"type": "transmission", "alpha": 0},
                                          "c": {"type": "mirror"}}})");
    EXPECT_EQ(s.materials[0].surface.alpha.value, 0.25f);
    EXPECT_TRUE(s.materials[0].surface.cuts_out());
    EXPECT_EQ(s.materials[1].surface.alpha.value, 0.0f);
    EXPECT_EQ(s.materials[2].surface.alpha.value, 1.0f);
    EXPECT_FALSE(s.materials[2].surface.cuts_out());
    // Alpha does not touch the shading frame.
    EXPECT_FALSE(s.materials[0].needs_shading_geometry);
    EXPECT_FALSE(s.materials[0].per_hit);
    // Emitters cannot be cut out (light sampling would see the whole surface).
    SceneError light = load_error(R"({"materials": {"leaf": {"type": "diffuse", "alpha": 0.5}},
        "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "leaf", "emission": 1}]})");
    EXPECT_EQ(light.where().json_pointer, "/shapes/0/emission");
    EXPECT_EQ(light.message(), "a light cannot be cut out: its material \"leaf\" has alpha < 1");
    EXPECT_EQ(load_error(R"({"materials": {"a": {"type": "diffuse", "alpha": -0.1}}})").message(),
              "expected a number in [0, 1], got -0.1");
}

// ---- shapes: common keys

TEST(SceneLoaderShapes, MaterialNamesAnIndex) {
    Scene s = load_json(R"({"materials": {"a": {"type": "diffuse"}, "b": {"type": "mirror"}},
                           "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                       "material": "b"},
                                      {"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                       "material": "a"}]})");
    EXPECT_EQ(s.shapes[0].material, 1u);
    EXPECT_EQ(s.shapes[1].material, 0u);
    EXPECT_EQ(load_error(R"({"shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                                         "material": "a"}]})")
                  .message(),
              "unknown material \"a\"; no materials are defined");
}

TEST(SceneLoaderShapes, EmissionMakesAnAreaLight) {
    Scene s = load_shapes(unit_quad(R"("emission": [1, 2, 3])") + "," + unit_quad(R"("emission": 5)") +
                          "," + unit_quad());
    EXPECT_EQ(s.shapes[0].emission, Rgb(1, 2, 3));
    EXPECT_EQ(s.shapes[1].emission, Rgb(5.0f));
    EXPECT_TRUE(s.shapes[2].emission.is_black());
}

TEST(SceneLoaderShapes, TwoSidedIsRead) {
    Scene s = load_shapes(unit_quad(R"("emission": 1, "two_sided": true)") + "," + unit_quad());
    EXPECT_TRUE(s.shapes[0].two_sided);
    EXPECT_FALSE(s.shapes[1].two_sided);
    EXPECT_EQ(load_error("{\"materials\": {\"m\": {\"type\": \"diffuse\"}}, \"shapes\": [" +
                         unit_quad(R"("two_sided": 1)") + "]}")
                  .message(),
              "expected true or false, got 1");
}

TEST(SceneLoaderShapes, ShapesIndexTheirKindsArrays) {
    Scene s = load_shapes(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"},)" +
                          unit_quad() + "," +
                          R"({"type": "sphere", "center": [0, 0, 0], "radius": 2, "material": "m"},
                             {"type": "mesh", "file": "meshes/triangle.obj", "material": "m"})");
    ASSERT_EQ(s.shapes.size(), 4u);
    EXPECT_EQ(s.shapes[0].kind, ShapeKind::kSphere);
    EXPECT_EQ(s.shapes[0].index, 0u);
    EXPECT_EQ(s.shapes[1].kind, ShapeKind::kMesh);
    EXPECT_EQ(s.shapes[1].index, 0u);
    EXPECT_EQ(s.shapes[2].kind, ShapeKind::kSphere);
    EXPECT_EQ(s.shapes[2].index, 1u);
    EXPECT_EQ(s.spheres[1].radius, 2.0);
    EXPECT_EQ(s.shapes[3].kind, ShapeKind::kMesh);
    EXPECT_EQ(s.shapes[3].index, 1u);
    EXPECT_EQ(s.meshes[1].triangle_count(), 1u);
}

// ---- spheres

TEST(SceneLoaderShapes, SphereCenterAndRadiusAreReadInDouble) {
    Scene s = load_shapes(
        R"({"type": "sphere", "center": [100000.5, -2, 3], "radius": 100000.25, "material": "m"})");
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_EQ(s.spheres[0].center, Vec3d(100000.5, -2, 3));
    EXPECT_EQ(s.spheres[0].radius, 100000.25);
    EXPECT_FALSE(s.spheres[0].reverse_orientation);
}

TEST(SceneLoaderShapes, SphereReverseOrientationIsRead) {
    Scene s = load_shapes(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
                              "reverse_orientation": true})");
    EXPECT_TRUE(s.spheres[0].reverse_orientation);
}

// ---- quads

TEST(SceneLoaderShapes, QuadCornerAndEdgesSpanIt) {
    Scene s = load_shapes(
        R"({"type": "quad", "corner": [1, 2, 3], "edge1": [0, 0, 2], "edge2": [-3, 0, 0], "material": "m"})");
    const TriangleMesh& q = s.meshes[0];
    ASSERT_EQ(q.triangle_count(), 2u);
    EXPECT_TRUE(has_position(q, {1, 2, 3}));
    EXPECT_TRUE(has_position(q, {1, 2, 5}));
    EXPECT_TRUE(has_position(q, {-2, 2, 5}));
    EXPECT_TRUE(has_position(q, {-2, 2, 3}));
    // Front: cross(edge1, edge2) = cross(+z, -x) = -y.
    expect_near(front_normal(q, 0), {0, -1, 0});
    expect_near(front_normal(q, 1), {0, -1, 0});
}

TEST(SceneLoaderShapes, QuadReverseOrientationFlipsItsFront) {
    Scene s = load_shapes(unit_quad(R"("reverse_orientation": true)") + "," + unit_quad());
    expect_near(front_normal(s.meshes[0], 0), {0, 0, -1});
    expect_near(front_normal(s.meshes[1], 0), {0, 0, 1});
}

// ---- meshes

TEST(SceneLoaderShapes, MeshFileIsRelativeToTheSceneFile) {
    Scene s = load_shapes(R"({"type": "mesh", "file": "meshes/triangle.obj", "material": "m"})");
    const TriangleMesh& m = s.meshes[0];
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_TRUE(has_position(m, {0, 0, 0}));
    EXPECT_TRUE(has_position(m, {1, 0, 0}));
    EXPECT_TRUE(has_position(m, {0, 1, 0}));
    expect_near(front_normal(m, 0), {0, 0, 1});
}

TEST(SceneLoaderShapes, MeshTransformMovesItToWorldSpace) {
    Scene s = load_shapes(R"({"type": "mesh", "file": "meshes/triangle.obj", "material": "m",
                              "transform": [{"translate": [0, 0, 7]}]})");
    EXPECT_TRUE(has_position(s.meshes[0], {1, 0, 7}));
    EXPECT_FALSE(has_position(s.meshes[0], {1, 0, 0}));
}

TEST(SceneLoaderShapes, MeshReverseOrientationFlipsItsFront) {
    Scene s = load_shapes(R"({"type": "mesh", "file": "meshes/triangle.obj", "material": "m",
                              "reverse_orientation": true})");
    expect_near(front_normal(s.meshes[0], 0), {0, 0, -1});
}

TEST(SceneLoaderShapes, MeshErrorKeepsItsFileAndNamesTheShape) {
    try {
        load_shapes(R"({"type": "mesh", "file": "meshes/bad_index.obj", "material": "m"})");
        FAIL() << "loaded a mesh with a bad index";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, (test::scenes_dir() / "meshes/bad_index.obj").string());
        EXPECT_EQ(e.where().line, 6);
        const std::string scene = (test::scenes_dir() / "inline.json").string();
        EXPECT_NE(e.message().find("(referenced by /shapes/0/file at " + scene + ":1:"),
                  std::string::npos)
            << e.message();
    }
}

// ---- transforms (on quads, whose vertices are known: corner, +edge1, +edge1+edge2, +edge2)

Vec3f transformed_quad_vertex(const std::string& transform, size_t vertex) {
    Scene s = load_shapes(unit_quad(R"("transform": )" + transform));
    return s.meshes[0].positions[vertex];
}

TEST(SceneLoaderTransform, TranslateMoves) {
    expect_near(transformed_quad_vertex(R"([{"translate": [1, 2, 3]}])", 0), {1, 2, 3});
}

TEST(SceneLoaderTransform, ScaleIsUniformOrPerAxis) {
    expect_near(transformed_quad_vertex(R"([{"scale": 2}])", 2), {2, 2, 0});
    expect_near(transformed_quad_vertex(R"([{"scale": [3, 4, 5]}])", 2), {3, 4, 0});
}

TEST(SceneLoaderTransform, RotateIsCounterClockwiseInDegrees) {
    // 90 degrees about +z takes +x to +y.
    expect_near(transformed_quad_vertex(R"([{"rotate": {"axis": [0, 0, 1], "angle": 90}}])", 1),
                {0, 1, 0});
    // The axis need not be unit length.
    expect_near(transformed_quad_vertex(R"([{"rotate": {"axis": [0, 0, 5], "angle": 180}}])", 1),
                {-1, 0, 0});
}

TEST(SceneLoaderTransform, MatrixIsRowMajor) {
    const char* translate = R"([{"matrix": [1, 0, 0, 5,  0, 1, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1]}])";
    expect_near(transformed_quad_vertex(translate, 0), {5, 6, 7});
    // Row 0 = [1, 2, 0, 0]: x' = x + 2y, so the corner (0, 1, 0) goes to (2, 1, 0).
    const char* shear = R"([{"matrix": [1, 2, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1]}])";
    expect_near(transformed_quad_vertex(shear, 3), {2, 1, 0});
}

TEST(SceneLoaderTransform, StepsApplyInListedOrder) {
    // (1, 0, 0): rotated to (0, 1, 0), then moved to (1, 1, 0) ...
    expect_near(transformed_quad_vertex(R"([{"rotate": {"axis": [0, 0, 1], "angle": 90}},
                                            {"translate": [1, 0, 0]}])",
                                        1),
                {1, 1, 0});
    // ... or moved to (2, 0, 0), then rotated to (0, 2, 0).
    expect_near(transformed_quad_vertex(R"([{"translate": [1, 0, 0]},
                                            {"rotate": {"axis": [0, 0, 1], "angle": 90}}])",
                                        1),
                {0, 2, 0});
    // Scale then translate: the translation is not scaled.
    expect_near(transformed_quad_vertex(R"([{"scale": 2}, {"translate": [1, 0, 0]}])", 1),
                {3, 0, 0});
    expect_near(transformed_quad_vertex(R"([{"translate": [1, 0, 0]}, {"scale": 2}])", 1),
                {4, 0, 0});
}

TEST(SceneLoaderTransform, MirrorKeepsTheFrontAndReverseOrientationFlipsIt) {
    Scene s = load_shapes(unit_quad(R"("transform": [{"scale": [-1, 1, 1]}])") + "," +
                          unit_quad(R"("transform": [{"scale": [-1, 1, 1]}],
                                       "reverse_orientation": true)"));
    EXPECT_TRUE(has_position(s.meshes[0], {-1, 1, 0}));
    expect_near(front_normal(s.meshes[0], 0), {0, 0, 1});
    expect_near(front_normal(s.meshes[1], 0), {0, 0, -1});
}

TEST(SceneLoaderTransform, EmptyTransformIsIdentity) {
    expect_near(transformed_quad_vertex("[]", 2), {1, 1, 0});
}

TEST(SceneLoaderTransform, ProductOfValidStepsMustStayInvertible) {
    SceneError e = load_error(R"({"materials": {"m": {"type": "diffuse"}}, "shapes": [)" +
                              unit_quad(R"("transform": [{"scale": 1e-200}, {"scale": 1e-200}])") +
                              "]}");
    EXPECT_EQ(e.where().json_pointer, "/shapes/0/transform");
    EXPECT_NE(e.message().find("the transform is singular"), std::string::npos) << e.message();
}

// ---- lights

TEST(SceneLoaderLights, EnvironmentColorIsAOnePixelImage) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "color": [0.1, 0.2, 0.3]}]})");
    ASSERT_TRUE(s.environment);
    EXPECT_EQ(s.environment->radiance.width, 1);
    EXPECT_EQ(s.environment->radiance.height, 1);
    EXPECT_EQ(s.environment->radiance.at(0, 0), Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s.environment->scale, 1.0f);
    EXPECT_TRUE(s.environment->to_world.is_identity());
    Scene grey = load_json(R"({"lights": [{"type": "environment", "color": 2}]})");
    EXPECT_EQ(grey.environment->radiance.at(0, 0), Rgb(2.0f));
}

TEST(SceneLoaderLights, EnvironmentFileIsReadRelativeToTheScene) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "file": "sky_2x1.hdr"}]})");
    ASSERT_TRUE(s.environment);
    const Image& sky = s.environment->radiance;
    ASSERT_EQ(sky.width, 2);
    ASSERT_EQ(sky.height, 1);
    EXPECT_NEAR(sky.at(0, 0).r, 1.0f, 0.01f);
    EXPECT_NEAR(sky.at(1, 0).r, 0.5f, 0.01f);
    EXPECT_NEAR(sky.at(1, 0).g, 0.25f, 0.01f);
    EXPECT_NEAR(sky.at(1, 0).b, 2.0f, 0.02f);
}

TEST(SceneLoaderLights, EnvironmentScaleIsRead) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "color": 1, "scale": 3}]})");
    EXPECT_EQ(s.environment->scale, 3.0f);
    EXPECT_EQ(load_error(R"({"lights": [{"type": "environment", "color": 1, "scale": -1}]})")
                  .message(),
              "expected a number >= 0, got -1");
}

TEST(SceneLoaderLights, EnvironmentTransformRotatesIt) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "color": 1,
                             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}]}]})");
    // 90 degrees about +y takes +x to -z.
    Vec3d x = s.environment->to_world.apply_vector(Vec3d(1, 0, 0));
    EXPECT_NEAR(x.x, 0.0, 1e-12);
    EXPECT_NEAR(x.z, -1.0, 1e-12);
}

TEST(SceneLoaderLights, EnvironmentSamplingIsImportanceUnlessUniformIsAsked) {
    Scene by_default = load_json(R"({"lights": [{"type": "environment", "color": 1}]})");
    EXPECT_EQ(by_default.environment->sampling, EnvironmentSampling::kImportance);
    Scene importance = load_json(
        R"({"lights": [{"type": "environment", "color": 1, "sampling": "importance"}]})");
    EXPECT_EQ(importance.environment->sampling, EnvironmentSampling::kImportance);
    Scene uniform = load_json(
        R"({"lights": [{"type": "environment", "color": 1, "sampling": "uniform"}]})");
    EXPECT_EQ(uniform.environment->sampling, EnvironmentSampling::kUniform);
}

TEST(SceneLoaderLights, EnvironmentImageNotTwoToOneLoadsWithAWarning) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "file": "sky_3x2.hdr"}]})");
    ASSERT_TRUE(s.environment);
    EXPECT_EQ(s.environment->radiance.width, 3);
    EXPECT_EQ(s.environment->radiance.height, 2);
    ASSERT_EQ(s.warnings.size(), 1u);
    const std::string& w = s.warnings[0];
    EXPECT_NE(w.find("/lights/0/file: environment image \"sky_3x2.hdr\" is 3x2, not 2:1"),
              std::string::npos) << w;
    Scene two_to_one = load_json(R"({"lights": [{"type": "environment", "file": "sky_2x1.hdr"}]})");
    EXPECT_TRUE(two_to_one.warnings.empty());
}

TEST(SceneLoaderLights, ImageErrorKeepsItsFileAndNamesTheLight) {
    try {
        load_json(R"({"lights": [{"type": "environment", "file": "truncated.hdr"}]})");
        FAIL() << "loaded a truncated image";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, (test::scenes_dir() / "truncated.hdr").string());
        EXPECT_NE(e.message().find("(referenced by /lights/0/file at "), std::string::npos)
            << e.message();
    }
}

}  // namespace
}  // namespace candela
