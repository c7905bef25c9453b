// The film keys of issue 15 (docs/SCENE_FORMAT.md, `film`): `filter` as an object (pbrt-v4's
// filters and parameters) and `crop_window`. Each changes the loaded Scene; the string names keep
// their meaning; bad values are located errors.
#include <gtest/gtest.h>

#include <string>

#include "candela/film/pixel_filter.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

FilterSettings filter_of(const std::string& filter) {
    return load_json(R"({"film": {"filter": )" + filter + "}}").film.filter;
}

TEST(SceneLoaderFilm, FilterNamesKeepTheirMeaning) {
    for (auto [name, type] : {std::pair{"box", FilterType::kBox}, std::pair{"tent", FilterType::kTent},
                              std::pair{"gaussian", FilterType::kGaussian}, std::pair{"smallpt", FilterType::kSmallpt}}) {
        const FilterSettings f = filter_of(std::string("\"") + name + "\"");
        EXPECT_EQ(f.type, type) << name;
        EXPECT_EQ(f.radius, FilterSettings(type).radius) << name;
    }
    EXPECT_EQ(filter_of("\"tent\"").radius, Vec2f(1.0f, 1.0f));
    EXPECT_EQ(load_json("{}").film.filter.type, FilterType::kBox);
}

TEST(SceneLoaderFilm, FilterObjectsHavePbrtsDefaults) {
    const FilterSettings box = filter_of(R"({"type": "box"})");
    EXPECT_EQ(box.type, FilterType::kBox);
    EXPECT_EQ(box.radius, Vec2f(0.5f, 0.5f));  // the string "box" exactly
    EXPECT_EQ(filter_of(R"({"type": "triangle"})").radius, Vec2f(2.0f, 2.0f));
    EXPECT_EQ(filter_of(R"({"type": "triangle"})").type, FilterType::kTent);
    const FilterSettings gaussian = filter_of(R"({"type": "gaussian"})");
    EXPECT_EQ(gaussian.type, FilterType::kOffsetGaussian);  // pbrt-v4's, not the string's
    EXPECT_EQ(gaussian.radius, Vec2f(1.5f, 1.5f));
    EXPECT_EQ(gaussian.sigma, 0.5f);
    const FilterSettings mitchell = filter_of(R"({"type": "mitchell"})");
    EXPECT_EQ(mitchell.radius, Vec2f(2.0f, 2.0f));
    EXPECT_EQ(mitchell.b, 1.0f / 3.0f);
    EXPECT_EQ(mitchell.c, 1.0f / 3.0f);
    const FilterSettings lanczos = filter_of(R"({"type": "lanczos"})");
    EXPECT_EQ(lanczos.type, FilterType::kLanczos);
    EXPECT_EQ(lanczos.radius, Vec2f(4.0f, 4.0f));
    EXPECT_EQ(lanczos.tau, 3.0f);
}

TEST(SceneLoaderFilm, FilterParametersAreRead) {
    EXPECT_EQ(filter_of(R"({"type": "box", "radius": [1, 0.25]})").radius, Vec2f(1.0f, 0.25f));
    EXPECT_EQ(filter_of(R"({"type": "triangle", "radius": 1})").radius, Vec2f(1.0f, 1.0f));
    const FilterSettings g = filter_of(R"({"type": "gaussian", "radius": [1.5, 2], "sigma": 0.7})");
    EXPECT_EQ(g.radius, Vec2f(1.5f, 2.0f));
    EXPECT_EQ(g.sigma, 0.7f);
    const FilterSettings m = filter_of(R"({"type": "mitchell", "radius": [2, 2], "B": 0.5, "C": 0.25})");
    EXPECT_EQ(m.b, 0.5f);
    EXPECT_EQ(m.c, 0.25f);
    EXPECT_EQ(filter_of(R"({"type": "lanczos", "radius": [3, 3], "tau": 2})").tau, 2.0f);
}

TEST(SceneLoaderFilm, BadFiltersAreLocatedErrors) {
    SceneError type = load_error(R"({"film": {"filter": {"type": "sinc"}}})");
    EXPECT_EQ(type.where().json_pointer, "/film/filter/type");
    EXPECT_EQ(type.message(),
              "unknown filter type \"sinc\"; expected one of: box, gaussian, lanczos, mitchell, triangle");
    SceneError radius = load_error(R"({"film": {"filter": {"type": "box", "radius": [1, 0]}}})");
    EXPECT_EQ(radius.where().json_pointer, "/film/filter/radius/1");
    EXPECT_EQ(radius.message(), "expected a number in (0, 1024], got 0");
    // A parameter of another type is an unknown key.
    SceneError sigma = load_error(R"({"film": {"filter": {"type": "mitchell", "sigma": 1}}})");
    EXPECT_EQ(sigma.where().json_pointer, "/film/filter");
    EXPECT_NE(sigma.message().find("unknown key \"sigma\""), std::string::npos) << sigma.message();
    EXPECT_EQ(load_error(R"({"film": {"filter": {"type": "gaussian", "sigma": -1}}})").message(),
              "expected a number > 0, got -1");
    EXPECT_EQ(load_error(R"({"film": {"filter": {"radius": 2}}})").message(), "missing required key \"type\"");
    EXPECT_EQ(load_error(R"({"film": {"filter": 3}})").where().json_pointer, "/film/filter");
    // B = 6 makes Mitchell's filter 0 at its centre and negative around: still has |f|; a Gaussian
    // whose sigma dwarfs its radius rounds to 0 everywhere and has nothing to sample.
    SceneError flat = load_error(R"({"film": {"filter": {"type": "gaussian", "radius": 0.01, "sigma": 1e30}}})");
    EXPECT_EQ(flat.where().json_pointer, "/film/filter");
    EXPECT_NE(flat.message().find("nothing to sample"), std::string::npos) << flat.message();
}

TEST(SceneLoaderFilm, CropWindowIsRead) {
    EXPECT_EQ(load_json("{}").film.crop_window, (std::array<float, 4>{0, 1, 0, 1}));
    const Scene s = load_json(R"({"camera": {"resolution": [40, 20]}, "film": {"crop_window": [0.25, 0.5, 0, 0.1]}})");
    EXPECT_EQ(s.film.crop_window, (std::array<float, 4>{0.25f, 0.5f, 0.0f, 0.1f}));
    const PixelBounds b = crop_pixel_bounds(40, 20, s.film.crop_window);
    EXPECT_EQ(b.x0, 10);
    EXPECT_EQ(b.x1, 20);
    EXPECT_EQ(b.y0, 0);
    EXPECT_EQ(b.y1, 2);
}

TEST(SceneLoaderFilm, BadCropWindowsAreLocatedErrors) {
    SceneError range = load_error(R"({"film": {"crop_window": [0, 1.5, 0, 1]}})");
    EXPECT_EQ(range.where().json_pointer, "/film/crop_window/1");
    EXPECT_EQ(range.message(), "expected a number in [0, 1], got 1.5");
    SceneError order = load_error(R"({"film": {"crop_window": [0, 1, 0.5, 0.5]}})");
    EXPECT_EQ(order.where().json_pointer, "/film/crop_window/3");
    EXPECT_EQ(order.message(), "expected a number > 0.5 (y0), got 0.5");
    SceneError empty = load_error(R"({"camera": {"resolution": [10, 10]}, "film": {"crop_window": [0.01, 0.02, 0, 1]}})");
    EXPECT_EQ(empty.where().json_pointer, "/film/crop_window");
    EXPECT_EQ(empty.message(), "the crop window covers no pixel of the 10x10 image (pixels [1, 1) x [0, 10))");
    EXPECT_EQ(load_error(R"({"film": {"crop_window": [0, 1]}})").message(),
              "expected an array of 4 numbers [x0, x1, y0, y1] in [0, 1], got [0, 1]");
}

// `filename` (pbrt-v4's Film "filename") names the default output image; the CLI's -o overrides it
// (the render job: render/job/job.cpp).
TEST(SceneLoaderFilm, FilenameIsTheDefaultOutput) {
    EXPECT_EQ(load_json("{}").output_file, "");
    EXPECT_EQ(load_json(R"({"film": {"filename": "out/cbox.exr"}})").output_file, "out/cbox.exr");
    SceneError empty = load_error(R"({"film": {"filename": ""}})");
    EXPECT_EQ(empty.where().json_pointer, "/film/filename");
    EXPECT_NE(empty.message().find("an image file name"), std::string::npos) << empty.message();
    EXPECT_EQ(load_error(R"({"film": {"filename": 3}})").where().json_pointer, "/film/filename");
}

TEST(SceneLoaderFilm, AovsAreRead) {
    EXPECT_TRUE(load_json("{}").film.aovs.empty());
    EXPECT_TRUE(load_json(R"({"film": {"aovs": []}})").film.aovs.empty());
    const AovLayers aovs = load_json(R"({"film": {"aovs": ["position", "albedo", "depth"]}})").film.aovs;
    EXPECT_TRUE(aovs.has(AovLayer::kAlbedo));
    EXPECT_TRUE(aovs.has(AovLayer::kDepth));
    EXPECT_TRUE(aovs.has(AovLayer::kPosition));
    EXPECT_FALSE(aovs.has(AovLayer::kNormal));
    EXPECT_EQ(aovs.value_count(), 3 + 1 + 3);
    EXPECT_EQ(aovs.offset(AovLayer::kPosition), 4);  // after albedo and depth, whatever the listed order
}

TEST(SceneLoaderFilm, BadAovsAreLocatedErrors) {
    SceneError unknown = load_error(R"({"film": {"aovs": ["albedo", "normals"]}})");
    EXPECT_EQ(unknown.where().json_pointer, "/film/aovs/1");
    EXPECT_EQ(unknown.message(),
              "unknown AOV layer \"normals\"; expected one of: albedo, depth, normal, position, spp, variance");
    SceneError twice = load_error(R"({"film": {"aovs": ["depth", "albedo", "depth"]}})");
    EXPECT_EQ(twice.where().json_pointer, "/film/aovs/2");
    EXPECT_EQ(twice.message(), "AOV layer \"depth\" is listed twice");
    SceneError not_array = load_error(R"({"film": {"aovs": "albedo"}})");
    EXPECT_EQ(not_array.where().json_pointer, "/film/aovs");
    EXPECT_NE(not_array.message().find("an array of AOV layer names"), std::string::npos) << not_array.message();
    // The layers derived from the film's statistics load like the others.
    const AovLayers derived = load_json(R"({"film": {"aovs": ["variance", "spp"]}})").film.aovs;
    EXPECT_TRUE(derived.has(AovLayer::kVariance));
    EXPECT_TRUE(derived.has(AovLayer::kSpp));
    EXPECT_EQ(derived.value_count(), 0);
}

}  // namespace
}  // namespace candela
