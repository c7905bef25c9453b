// Projective transforms (a matrix whose last row is not 0 0 0 1), which pbrt-v4 takes anywhere and
// its scenes use (the sssdragon scenes' infinite light). What pbrt-v4 does, measured with its
// binary (docs/PBRT.md, "Transforms"): a mesh's vertices are divided by w; a light's and the
// camera's directions take the upper 3x3 of the transform in pbrt-v4's render space (the world
// translated to put the camera at the origin); a sphere or disk cannot follow and warns.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"

namespace candela::pbrt {
namespace CANDELA_UNITY_ID {

const std::filesystem::path kFile =
    std::filesystem::path(CANDELA_TEST_DATA_DIR) / "pbrt" / "transform" / "inline.pbrt";

ImportedScene import(const std::string& text) { return import_pbrt_string(text, kFile); }
Scene load(const std::string& text) { return load_imported_scene(import(text), kFile); }

// A camera at (0, 0, -4) looking at the origin; pbrt-v4's render space puts it at the origin.
const std::string kCamera = "LookAt 0 0 -4  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n";
// The matrix with last row (0.5, 0, 0, 1): w = 1 + x / 2. pbrt's numbers are its columns.
const std::string kProjective = "ConcatTransform [1 0 0 0.5  0 1 0 0  0 0 1 0  0 0 0 1]\n";

TEST(PbrtTransform, AProjectiveMeshHasItsVerticesDividedByW) {
    const Scene scene = load(kCamera + kProjective +
                             "Shape \"trianglemesh\" \"point3 P\" [2 0 0  0 2 0  -1 1 0  0 0 0] "
                             "\"integer indices\" [0 1 2 0 2 3]\n");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const auto& p = scene.meshes[0].positions;
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p[0], Vec3f(1, 0, 0));   // w = 2
    EXPECT_EQ(p[1], Vec3f(0, 2, 0));   // w = 1
    EXPECT_EQ(p[2], Vec3f(-2, 2, 0));  // w = 1/2
    EXPECT_EQ(p[3], Vec3f(0, 0, 0));
}

TEST(PbrtTransform, AProjectiveInfiniteLightTakesPbrtsRenderSpaceDirections) {
    const std::string text = kCamera + "AttributeBegin\n" + kProjective +
                             "LightSource \"infinite\" \"string filename\" \"env.exr\"\nAttributeEnd\n";
    const ImportedScene s = import(text);
    // Translate(-camera) x M: row 2 of M3x3 gains -camera.z times M's last row, (0.5, 0, 0).
    const nlohmann::ordered_json m = s.document["lights"][0]["transform"][0]["matrix"];
    EXPECT_EQ(m, nlohmann::ordered_json::array({1.0, 0.0, 0.0, 0.0,  //
                                                 0.0, 1.0, 0.0, 0.0,  //
                                                 2.0, 0.0, 1.0, 4.0,  //
                                                 0.5, 0.0, 0.0, 1.0}));
    const Scene scene = load(text);
    ASSERT_TRUE(scene.environment.has_value());
    // Directions: the upper 3x3 of the matrix and of its inverse, as pbrt-v4's Le and SampleLi.
    EXPECT_EQ(scene.environment->to_world.apply_vector(Vec3d(1, 0, 0)), Vec3d(1, 0, 2));
    // The inverse's upper 3x3 is M^-1's, the identity here: M^-1 has last row (-0.5, 0, 0, 1).
    const Vec3d back = scene.environment->to_world.inverse().apply_vector(Vec3d(0.3, 0.2, 1));
    EXPECT_NEAR(back.x, 0.3, 1e-12);
    EXPECT_NEAR(back.y, 0.2, 1e-12);
    EXPECT_NEAR(back.z, 1.0, 1e-12);
}

TEST(PbrtTransform, AnAffineInfiniteLightIsWrittenAsItWas) {
    const ImportedScene s = import(kCamera + "AttributeBegin\nTranslate 1 2 3\nRotate 30 0 1 0\n"
                                   "LightSource \"infinite\" \"string filename\" \"env.exr\"\nAttributeEnd\n");
    const nlohmann::ordered_json m = s.document["lights"][0]["transform"][0]["matrix"];
    EXPECT_EQ(m[3], 1.0);  // the translation stays: no render-space change for an affine matrix
    EXPECT_EQ(m[15], 1.0);
}

TEST(PbrtTransform, AProjectiveCameraMakesPbrtsRays) {
    // P (last row 0 0 0.125 1) before LookAt: world_from_camera = LookAt^-1 P^-1 keeps the origin
    // at (2, 0, -4), and in pbrt-v4's render space its directions are LookAt's rotation again (the
    // projective row cancels): pbrt-v4 renders the same image as without P (measured: equal means).
    const std::string rest = "LookAt 2 0 -4  2 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n";
    const ImportedScene with = import("ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0.125  0 0 0 1]\n" + rest);
    const ImportedScene without = import(rest);
    // (pbrt's camera frame, right = +x, is written as the camera's matrix.)
    const auto& a = with.document["camera"]["transform"][0]["matrix"];
    const auto& b = without.document["camera"]["transform"][0]["matrix"];
    ASSERT_EQ(a.size(), 16u);
    for (size_t i = 0; i < 16; ++i) EXPECT_NEAR(a[i].get<double>(), b[i].get<double>(), 1e-12) << i;
    // P after LookAt acts on the world: the camera's origin is P^-1 (2, 0, -4), and P^-1's last
    // row (-0.05, -0.03, 0, 1) makes w = 0.9 there. (Rendered, this scene's image agrees with
    // pbrt-v4's, and differs from the image without P: docs/PBRT.md.)
    const ImportedScene moved = import("LookAt 2 0 -4  2 0 0  0 1 0\n"
                                       "ConcatTransform [1 0 0 0.05  0 1 0 0.03  0 0 1 0  0 0 0 1]\n"
                                       "Camera \"perspective\"\nWorldBegin\n");
    const auto& m = moved.document["camera"]["transform"][0]["matrix"];
    EXPECT_NEAR(m[3].get<double>(), 2 / 0.9, 1e-12);
    EXPECT_NEAR(m[7].get<double>(), 0, 1e-12);
    EXPECT_NEAR(m[11].get<double>(), -4 / 0.9, 1e-12);
    EXPECT_EQ(m[15].get<double>(), 1.0);
    EXPECT_NO_THROW(load_imported_scene(moved, kFile));
}

TEST(PbrtTransform, AProjectiveSphereOrDiskWarns) {
    const ImportedScene s = import(kCamera + kProjective + "Shape \"sphere\"\nShape \"disk\"\n");
    ASSERT_EQ(s.warnings.size(), 2u);
    EXPECT_NE(s.warnings[0].find("sphere: a projective transform"), std::string::npos) << s.warnings[0];
    EXPECT_NE(s.warnings[1].find("disk: a projective transform"), std::string::npos) << s.warnings[1];
    EXPECT_NO_THROW(load_imported_scene(s, kFile));
}

// pbrt-v4 renders such a scene (its Transform keeps a NaN inverse) with the mesh flattened;
// candela keeps its located error, as for a zero Scale.
TEST(PbrtTransform, ASingularMatrixIsAnError) {
    try {
        load(kCamera + "ConcatTransform [1 0 0 0  0 1 0 0  0 0 0 0  0 0 0 1]\n"
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n");
        ADD_FAILURE() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("inline.pbrt:4:1: the transform is not invertible"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace candela::pbrt
