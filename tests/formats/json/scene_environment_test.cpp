// The environment light's keys for pbrt-v4's infinite light: `mapping` (equirectangular or
// equal_area, which must be square), `filter` (bilinear or point) and `illuminance` (the scale
// that gives that illuminance facing the light frame's up direction). Each changes the loaded
// scene; bad values are located errors.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "candela/image/image_io.h"
#include "formats/json/scene_test_util.h"
#include "image/test_files.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

// Loads `json` as a scene file in `dir`, next to the images the test wrote there.
Scene load_in(const testing::TempDir& dir, const std::string& json) {
    return load_scene_from_string(json, dir / "scene.json");
}

SceneError load_error_in(const testing::TempDir& dir, const std::string& json) {
    try {
        load_in(dir, json);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError loading " << json;
    return SceneError(SourceLocation{}, "no error");
}

// Writes a w x h EXR of a gradient named `name` into `dir`.
void write_map(const testing::TempDir& dir, const std::string& name, int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = Rgb(0.5f + static_cast<float>(x), 1.0f, 0.25f * static_cast<float>(y + 1));
    write_image(dir / name, img, FilmSettings{});
}

TEST(SceneLoaderEnvironment, MappingIsEquirectangularUnlessEqualAreaIsAsked) {
    testing::TempDir dir;
    write_map(dir, "square.exr", 4, 4);
    Scene by_default = load_in(dir, R"({"lights": [{"type": "environment", "file": "square.exr"}]})");
    EXPECT_EQ(by_default.environment->mapping, EnvironmentMapping::kEquirectangular);
    ASSERT_EQ(by_default.warnings.size(), 1u);  // a square equirectangular map is not 2:1
    Scene equirect = load_in(dir, R"({"lights": [{"type": "environment", "color": 1, "mapping": "equirectangular"}]})");
    EXPECT_EQ(equirect.environment->mapping, EnvironmentMapping::kEquirectangular);
    Scene equal_area = load_in(dir, R"({"lights": [{"type": "environment", "file": "square.exr",
                                                     "mapping": "equal_area"}]})");
    EXPECT_EQ(equal_area.environment->mapping, EnvironmentMapping::kEqualArea);
    EXPECT_EQ(equal_area.environment->radiance.width, 4);
    EXPECT_TRUE(equal_area.warnings.empty());  // square is what an equal-area map should be
}

TEST(SceneLoaderEnvironment, EqualAreaMapMustBeSquare) {
    testing::TempDir dir;
    write_map(dir, "wide.exr", 8, 4);
    SceneError e = load_error_in(dir, R"({"lights": [{"type": "environment", "file": "wide.exr",
                                                      "mapping": "equal_area"}]})");
    EXPECT_EQ(e.where().json_pointer, "/lights/0/file");
    EXPECT_EQ(e.message(), "environment image \"wide.exr\" is 8x4; an equal_area map must be square");
    // A colour is a 1 x 1 map: square.
    Scene colour = load_json(R"({"lights": [{"type": "environment", "color": 1, "mapping": "equal_area"}]})");
    EXPECT_EQ(colour.environment->mapping, EnvironmentMapping::kEqualArea);
}

TEST(SceneLoaderEnvironment, UnknownMappingOrFilterListsTheValidNames) {
    SceneError m = load_error(R"({"lights": [{"type": "environment", "color": 1, "mapping": "octahedral"}]})");
    EXPECT_EQ(m.where().json_pointer, "/lights/0/mapping");
    EXPECT_EQ(m.message(), "unknown environment mapping \"octahedral\"; expected one of: equal_area, equirectangular");
    SceneError f = load_error(R"({"lights": [{"type": "environment", "color": 1, "filter": "nearest"}]})");
    EXPECT_EQ(f.where().json_pointer, "/lights/0/filter");
    EXPECT_EQ(f.message(), "unknown environment filter \"nearest\"; expected one of: bilinear, point");
}

TEST(SceneLoaderEnvironment, FilterIsBilinearUnlessPointIsAsked) {
    Scene by_default = load_json(R"({"lights": [{"type": "environment", "color": 1}]})");
    EXPECT_EQ(by_default.environment->filter, EnvironmentFilter::kBilinear);
    Scene point = load_json(R"({"lights": [{"type": "environment", "color": 1, "filter": "point"}]})");
    EXPECT_EQ(point.environment->filter, EnvironmentFilter::kPoint);
    Scene bilinear = load_json(R"({"lights": [{"type": "environment", "color": 1, "filter": "bilinear"}]})");
    EXPECT_EQ(bilinear.environment->filter, EnvironmentFilter::kBilinear);
}

TEST(SceneLoaderEnvironment, IlluminanceOfAColourIsPiTimesItsLuminanceTimesScale) {
    Scene s = load_json(R"({"lights": [{"type": "environment", "color": [0.5, 1, 2], "scale": 2,
                                        "illuminance": 10}]})");
    const double k = kPiD * static_cast<double>(Rgb(0.5f, 1.0f, 2.0f).luminance());
    EXPECT_NEAR(static_cast<double>(s.environment->scale), 2.0 * 10.0 / k, 1e-6);
    EXPECT_EQ(s.environment->radiance.at(0, 0), Rgb(0.5f, 1.0f, 2.0f));  // the map is kept as it is
}

TEST(SceneLoaderEnvironment, IlluminanceOfAMapIsMeasuredFacingItsUpDirection) {
    testing::TempDir dir;
    write_map(dir, "square.exr", 4, 4);
    write_map(dir, "sky.exr", 8, 4);
    for (auto [file, mapping, enum_value] :
         {std::tuple{"square.exr", "equal_area", EnvironmentMapping::kEqualArea},
          std::tuple{"sky.exr", "equirectangular", EnvironmentMapping::kEquirectangular}}) {
        Scene s = load_in(dir, std::string(R"({"lights": [{"type": "environment", "file": ")") + file +
                                   R"(", "mapping": ")" + mapping + R"(", "illuminance": 5}]})");
        const double up = environment_up_illuminance(s.environment->radiance, enum_value, EnvironmentFilter::kBilinear);
        EXPECT_NEAR(static_cast<double>(s.environment->scale) * up, 5.0, 5e-6) << mapping;
    }
}

TEST(SceneLoaderEnvironment, IlluminanceMustBePositiveAndTheUpperHemisphereLit) {
    SceneError zero = load_error(R"({"lights": [{"type": "environment", "color": 1, "illuminance": 0}]})");
    EXPECT_EQ(zero.where().json_pointer, "/lights/0/illuminance");
    EXPECT_EQ(zero.message(), "expected a number > 0, got 0");
    testing::TempDir dir;
    // An equal-area map lit only in its corners (z < 0) gives nothing facing +z.
    Image corners(4, 4);
    corners.at(0, 0) = Rgb(1.0f);
    write_image(dir / "corners.exr", corners, FilmSettings{});
    SceneError dark = load_error_in(dir, R"({"lights": [{"type": "environment", "file": "corners.exr",
                                                        "mapping": "equal_area", "filter": "point",
                                                        "illuminance": 3}]})");
    EXPECT_EQ(dark.where().json_pointer, "/lights/0/illuminance");
    EXPECT_EQ(dark.message(), "the environment gives no light to a surface facing its up direction (+z), "
                              "so no scale can make its illuminance 3");
}

}  // namespace
}  // namespace candela
