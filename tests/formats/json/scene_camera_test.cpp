// The camera keys of version 2 (docs/SCENE_FORMAT.md, `camera`): type, height, fov_axis,
// aperture_radius, focus_distance. Each, set to a value other than its default, changes the loaded
// Scene; bad values and keys of the other camera type are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/camera/camera_frame.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace {

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

}  // namespace
}  // namespace candela
