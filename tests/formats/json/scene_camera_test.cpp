// The camera keys of version 2 (docs/SCENE_FORMAT.md, `camera`): type, height, fov_axis,
// aperture_radius, focus_distance. Each, set to a value other than its default, changes the loaded
// Scene; bad values and keys of the other camera type are located errors.
#include <gtest/gtest.h>

#include <cmath>

#include <array>
#include <string>

#include "candela/camera/camera_frame.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

TEST(SceneLoaderCamera, VersionTwoKeysHaveTheDocumentedDefaults) {
    const CameraSettings c = load_json("{}").camera;
    EXPECT_EQ(c.type, CameraType::kPerspective);
    EXPECT_EQ(c.fov_axis, FovAxis::kY);
    EXPECT_EQ(c.aperture_radius, 0.0f);
    EXPECT_EQ(c.focus_distance, 0.0f);  // not given: the distance to look_at
}

TEST(SceneLoaderCamera, TypeSelectsPerspectiveOrOrthographic) {
    const Scene p = load_json(R"({"camera": {"type": "perspective", "fov": 30}})");
    EXPECT_EQ(p.camera.type, CameraType::kPerspective);
    EXPECT_EQ(p.camera.fov_degrees, 30.0f);
    const Scene o = load_json(R"({"camera": {"type": "orthographic", "height": 2.5}})");
    EXPECT_EQ(o.camera.type, CameraType::kOrthographic);
    SceneError e = load_error(R"({"camera": {"type": "fisheye"}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/type");
    EXPECT_EQ(e.message(), "unknown camera type \"fisheye\"; expected one of: orthographic, perspective");
}

TEST(SceneLoaderCamera, HeightIsTheOrthographicFilmHeight) {
    EXPECT_EQ(load_json(R"({"camera": {"type": "orthographic", "height": 7}})").camera.ortho_height, 7.0f);
    SceneError missing = load_error(R"({"camera": {"type": "orthographic"}})");
    EXPECT_EQ(missing.where().json_pointer, "/camera");
    EXPECT_EQ(missing.message(), "missing required key \"height\"");
    EXPECT_EQ(load_error(R"({"camera": {"type": "orthographic", "height": 0}})").message(),
              "expected a number > 0, got 0");
    // The film's width is height times the aspect ratio: it must stay a float.
    SceneError wide = load_error(R"({"camera": {"type": "orthographic", "height": 3e38, "resolution": [64, 1]}})");
    EXPECT_EQ(wide.where().json_pointer, "/camera/height");
    EXPECT_NE(wide.message().find("overflows float range"), std::string::npos);
}

TEST(SceneLoaderCamera, KeysOfTheOtherCameraTypeSayWhoseTheyAre) {
    SceneError height = load_error(R"({"camera": {"fov": 30, "height": 2}})");
    EXPECT_EQ(height.where().json_pointer, "/camera");
    EXPECT_EQ(height.where().line, 1);
    EXPECT_EQ(height.where().column, 24);  // at the key's opening quote
    EXPECT_EQ(height.message(),
              "\"height\" is a key of the orthographic camera; a perspective camera takes \"fov\" (degrees)");
    SceneError fov = load_error(R"({"camera": {"type": "orthographic", "height": 2, "fov": 30}})");
    EXPECT_EQ(fov.message(), "\"fov\" is a key of the perspective camera; an orthographic camera takes \"height\" "
                             "(the image's height in scene units)");
    EXPECT_EQ(load_error(R"({"camera": {"type": "orthographic", "height": 2, "fov_axis": "x"}})").message().rfind(
                  "\"fov_axis\" is a key of the perspective camera; ", 0),
              0u);
}

TEST(SceneLoaderCamera, FovAxisIsRead) {
    const std::pair<const char*, FovAxis> names[] = {{"x", FovAxis::kX},
                                                     {"y", FovAxis::kY},
                                                     {"diagonal", FovAxis::kDiagonal},
                                                     {"smaller", FovAxis::kSmaller},
                                                     {"larger", FovAxis::kLarger}};
    for (auto [name, axis] : names)
        EXPECT_EQ(load_json(std::string(R"({"camera": {"fov_axis": ")") + name + "\"}}").camera.fov_axis, axis) << name;
    SceneError e = load_error(R"({"camera": {"fov_axis": "vertical"}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/fov_axis");
    EXPECT_EQ(e.message(), "unknown fov axis \"vertical\"; expected one of: diagonal, larger, smaller, x, y");
}

TEST(SceneLoaderCamera, ApertureRadiusIsRead) {
    EXPECT_EQ(load_json(R"({"camera": {"aperture_radius": 0.25}})").camera.aperture_radius, 0.25f);
    EXPECT_EQ(load_json(R"({"camera": {"aperture_radius": 0}})").camera.aperture_radius, 0.0f);  // a pinhole
    SceneError e = load_error(R"({"camera": {"aperture_radius": -0.1}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/aperture_radius");
    EXPECT_EQ(e.message(), "expected a number >= 0, got -0.1");
    // Also on the orthographic camera.
    EXPECT_EQ(load_json(R"({"camera": {"type": "orthographic", "height": 1, "aperture_radius": 0.5}})")
                  .camera.aperture_radius,
              0.5f);
}

TEST(SceneLoaderCamera, FocusDistanceIsReadAndDefaultsToTheDistanceToLookAt) {
    const Scene given = load_json(R"({"camera": {"aperture_radius": 0.1, "focus_distance": 4.5}})");
    EXPECT_EQ(given.camera.focus_distance, 4.5f);
    EXPECT_EQ(resolved_focus_distance(given.camera), 4.5f);
    const Scene by_default = load_json(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 3, 1],
                                                      "aperture_radius": 0.1}})");
    EXPECT_EQ(resolved_focus_distance(by_default.camera), 5.0f);
    SceneError e = load_error(R"({"camera": {"focus_distance": 0}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/focus_distance");
    EXPECT_EQ(e.message(), "expected a number > 0, got 0");
    // A lens whose rays to the focus plane's corners would overflow float.
    SceneError far = load_error(R"({"camera": {"fov": 170, "aperture_radius": 1, "focus_distance": 1e37}})");
    EXPECT_EQ(far.where().json_pointer, "/camera/focus_distance");
    EXPECT_NE(far.message().find("beyond float range"), std::string::npos);
}

// pbrt-v4's camera space: at the origin, looking along +z, +y up, image right along +x.
TEST(SceneLoaderCamera, TransformGivesTheFrameFromCameraSpace) {
    // A rotation of 90 degrees about y takes +z (forward) to +x and +x (right) to -z; then a move.
    const Scene s = load_json(R"({"camera": {"transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}},
                                                           {"translate": [1, 2, 3]}]}})");
    ASSERT_TRUE(s.camera.basis.has_value());
    const CameraFrame f(s.camera);
    EXPECT_EQ(f.position, Vec3f(1, 2, 3));
    EXPECT_NEAR(f.forward.x, 1.0f, 1e-6f);
    EXPECT_NEAR(f.right.z, -1.0f, 1e-6f);
    EXPECT_NEAR(f.up.y, 1.0f, 1e-6f);
    EXPECT_FALSE(load_json("{}").camera.basis.has_value());
}

TEST(SceneLoaderCamera, TransformEqualToALookAtCameraGivesItsFrame) {
    const Scene a = load_json(R"({"camera": {"position": [1, 2, 3], "look_at": [1, 2, -1]}})");
    // Columns: right (1, 0, 0), up (0, 1, 0), forward (0, 0, -1), position (1, 2, 3): right-handed
    // in the world, so det = -1 as a map from pbrt-v4's left-handed camera space.
    const Scene b = load_json(R"({"camera": {"transform": [{"matrix": [1, 0, 0, 1,  0, 1, 0, 2,  0, 0, -1, 3,
                                                                       0, 0, 0, 1]}]}})");
    const CameraFrame fa(a.camera), fb(b.camera);
    EXPECT_EQ(fa.position, fb.position);
    EXPECT_EQ(fa.right, fb.right);
    EXPECT_EQ(fa.up, fb.up);
    EXPECT_EQ(fa.forward, fb.forward);
}

TEST(SceneLoaderCamera, TransformKeepsTheMatrixHandednessAndNormalizesAxes) {
    // pbrt-v4's LookAt from (0, 0, 0) to (0, 0, -1), up +y: its right is cross(up, dir) = -x.
    const Scene s = load_json(R"({"camera": {"transform": [{"matrix": [-2, 0, 0, 0,  0, 3, 0, 0,  0, 0, -0.5, 0,
                                                                       0, 0, 0, 1]}]}})");
    const CameraFrame f(s.camera);
    EXPECT_EQ(f.right, Vec3f(-1, 0, 0));
    EXPECT_EQ(f.up, Vec3f(0, 1, 0));
    EXPECT_EQ(f.forward, Vec3f(0, 0, -1));
}

TEST(SceneLoaderCamera, TransformFocusesAtPbrtsDefaultDistance) {
    const Scene s = load_json(R"({"camera": {"transform": [{"translate": [0, 0, 1]}], "aperture_radius": 0.1}})");
    EXPECT_EQ(resolved_focus_distance(s.camera), 1e6f);
    const Scene given = load_json(R"({"camera": {"transform": [], "aperture_radius": 0.1, "focus_distance": 3}})");
    EXPECT_EQ(resolved_focus_distance(given.camera), 3.0f);
}

TEST(SceneLoaderCamera, TransformAndLookAtTogetherAreAnError) {
    SceneError e = load_error(R"({"camera": {"transform": [], "look_at": [0, 0, 1]}})");
    EXPECT_EQ(e.where().json_pointer, "/camera");
    EXPECT_EQ(e.where().column, 30);  // at the key
    EXPECT_EQ(e.message(), "\"look_at\" and \"transform\" both place the camera; give one of them");
    SceneError singular = load_error(R"({"camera": {"transform": [{"scale": [1, 1, 0]}]}})");
    EXPECT_EQ(singular.where().json_pointer, "/camera/transform/0/scale/2");
}

TEST(SceneLoaderCamera, ScreenWindowIsRead) {
    const Scene p = load_json(R"({"camera": {"fov": 60, "screen_window": [-1, 0.5, -0.25, 1]}})");
    ASSERT_TRUE(p.camera.screen_window.has_value());
    EXPECT_EQ(*p.camera.screen_window, (std::array<float, 4>{-1, 0.5f, -0.25f, 1}));
    const Scene o = load_json(R"({"camera": {"type": "orthographic", "screen_window": [-3, 3, -2, 2]}})");
    EXPECT_EQ(orthographic_screen_window(o.camera).half, Vec2f(3, 2));
    EXPECT_FALSE(load_json("{}").camera.screen_window.has_value());
}

TEST(SceneLoaderCamera, BadScreenWindowsAreLocatedErrors) {
    SceneError order = load_error(R"({"camera": {"screen_window": [1, -1, -1, 1]}})");
    EXPECT_EQ(order.where().json_pointer, "/camera/screen_window/1");
    EXPECT_EQ(order.message(), "expected a number > 1 (xmin), got -1");
    SceneError axis = load_error(R"({"camera": {"screen_window": [-1, 1, -1, 1], "fov_axis": "x"}})");
    EXPECT_EQ(axis.where().json_pointer, "/camera/fov_axis");
    EXPECT_NE(axis.message().find("fov_axis chooses the default screen window"), std::string::npos);
    SceneError both = load_error(R"({"camera": {"type": "orthographic", "height": 2, "screen_window": [-1, 1, -1, 1]}})");
    EXPECT_EQ(both.where().json_pointer, "/camera/height");
    EXPECT_EQ(both.message(), "an orthographic camera takes \"height\" or \"screen_window\" (in scene units), not both");
    SceneError far = load_error(R"({"camera": {"fov": 170, "screen_window": [-1e30, 1e30, -1, 1]}})");
    EXPECT_EQ(far.where().json_pointer, "/camera/screen_window");
    EXPECT_NE(far.message().find("beyond float range"), std::string::npos) << far.message();
    EXPECT_EQ(load_error(R"({"camera": {"screen_window": [-1, 1]}})").message(),
              "expected an array of 4 numbers [xmin, xmax, ymin, ymax], got [-1, 1]");
}

TEST(SceneLoaderCamera, ShutterIsRead) {
    const auto shutter = load_json(R"({"camera": {"shutter": [0.25, 2]}})").camera.shutter;
    EXPECT_EQ(shutter[0], 0.25);
    EXPECT_EQ(shutter[1], 2.0);
    EXPECT_EQ(load_json(R"({"camera": {}})").camera.shutter[1], 1.0);  // pbrt-v4's default [0, 1]
    EXPECT_EQ(load_error(R"({"camera": {"shutter": [1, 1]}})").where().json_pointer, "/camera/shutter/1");
}

TEST(SceneLoaderCamera, MotionIsTheEndFrameInTheStartFramesForm) {
    const Scene s = load_json(
        R"({"camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "motion": {"position": [1, 0, 0], "times": [0, 2]}}})");
    ASSERT_TRUE(s.camera.motion.has_value());
    EXPECT_EQ(s.camera.motion->end.position, Vec3f(1, 0, 0));
    // look_at and up stay the start's: from (1, 0, 0) the camera still looks at (0, 0, -1).
    EXPECT_NEAR(s.camera.motion->end.forward.x, -std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(s.camera.motion->end.forward.z, -std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(s.camera.motion->end_time, 2.0);
    EXPECT_FALSE(load_json(R"({"camera": {}})").camera.motion.has_value());
    // A look_at camera's end frame is not a matrix: the two must have the same handedness.
    const SceneError e = load_error(R"({"camera": {"motion": {"transform": [{"translate": [1, 0, 0]}]}}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/motion");
    EXPECT_NE(e.message().find("takes those too"), std::string::npos);
}

}  // namespace
}  // namespace candela
