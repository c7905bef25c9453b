// The scene file's settings sections (integrator, sampler, camera, film) and loading from files:
// every documented key, set to a value other than its default, changes the loaded Scene.
#include "candela/formats/json/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/scene/enum_names.h"
#include "candela/spectrum/camera_sensors.h"
#include "formats/json/scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

TEST(SceneLoader, EmptySceneHasTheDocumentedDefaults) {
    Scene s = load_json("{}");
    EXPECT_EQ(s.integrator.type, IntegratorType::kPath);
    EXPECT_EQ(s.integrator.max_depth, 64);
    EXPECT_EQ(s.integrator.rr_depth, 3);
    EXPECT_EQ(s.integrator.rr_probability, 0.0f);
    EXPECT_TRUE(s.integrator.mis);
    EXPECT_EQ(s.integrator.light_selection, LightSelection::kPower);
    EXPECT_TRUE(std::isinf(s.integrator.max_distance));
    EXPECT_EQ(s.sampler.spp, 16);
    EXPECT_EQ(s.sampler.seed, 0u);
    EXPECT_EQ(s.camera.position, Vec3f(0, 0, 0));
    EXPECT_EQ(s.camera.look_at, Vec3f(0, 0, -1));
    EXPECT_EQ(s.camera.up, Vec3f(0, 1, 0));
    EXPECT_EQ(s.camera.fov_degrees, 40.0f);
    EXPECT_EQ(s.camera.width, 512);
    EXPECT_EQ(s.camera.height, 512);
    EXPECT_EQ(s.camera.near, 0.0f);  // the other camera keys: scene_camera_test.cpp
    EXPECT_EQ(s.film.filter, FilterType::kBox);
    EXPECT_EQ(s.film.tonemap, Tonemap::kClamp);
    EXPECT_EQ(s.film.exposure, 0.5f);
    EXPECT_EQ(s.film.transfer, Transfer::kSrgb);
    EXPECT_EQ(s.film.gamma, 2.2f);
    EXPECT_EQ(s.film.iso, 100.0f);
    EXPECT_EQ(s.film.exposure_time, 1.0f);
    EXPECT_EQ(s.film.white_balance, 0.0f);
    EXPECT_TRUE(s.materials.empty());
    EXPECT_TRUE(s.shapes.empty());
    EXPECT_FALSE(s.environment);
    // Empty sections are the same as absent ones.
    Scene e = load_json(R"({"integrator": {}, "sampler": {}, "camera": {}, "film": {},
                            "materials": {}, "shapes": [], "lights": []})");
    EXPECT_EQ(e.integrator.max_depth, 64);
    EXPECT_EQ(e.camera.width, 512);
    EXPECT_FALSE(e.environment);
}

// ---- integrator

TEST(SceneLoaderIntegrator, TypeSelectsEachIntegrator) {
    for (std::string_view name : integrator_type_names()) {
        Scene s = load_json(R"({"integrator": {"type": ")" + std::string(name) + "\"}}");
        EXPECT_EQ(integrator_type_name(s.integrator.type), name);
    }
    EXPECT_EQ(load_json(R"({"integrator": {"type": "normals"}})").integrator.type,
              IntegratorType::kNormals);
}

TEST(SceneLoaderIntegrator, MaxDepthIsRead) {
    EXPECT_EQ(load_json(R"({"integrator": {"max_depth": 5}})").integrator.max_depth, 5);
    EXPECT_EQ(load_json(R"({"integrator": {"max_depth": 1}})").integrator.max_depth, 1);
    EXPECT_EQ(load_error(R"({"integrator": {"max_depth": 0}})").message(),
              "expected an integer >= 1, got 0");
}

TEST(SceneLoaderIntegrator, RrDepthIsRead) {
    EXPECT_EQ(load_json(R"({"integrator": {"rr_depth": 0}})").integrator.rr_depth, 0);
    EXPECT_EQ(load_json(R"({"integrator": {"rr_depth": 10}})").integrator.rr_depth, 10);
    EXPECT_EQ(load_error(R"({"integrator": {"rr_depth": -1}})").message(),
              "expected an integer >= 0, got -1");
}

TEST(SceneLoaderIntegrator, MaxDistanceIsRead) {
    EXPECT_EQ(load_json(R"({"integrator": {"max_distance": 2.5}})").integrator.max_distance, 2.5f);
    EXPECT_EQ(load_error(R"({"integrator": {"max_distance": 0}})").message(),
              "expected a number > 0, got 0");
}

TEST(SceneLoaderIntegrator, MisIsRead) {
    EXPECT_FALSE(load_json(R"({"integrator": {"mis": false}})").integrator.mis);
    EXPECT_EQ(load_error(R"({"integrator": {"mis": 0}})").where().json_pointer, "/integrator/mis");
}

TEST(SceneLoaderIntegrator, RrIsAFixedSurvivalProbability) {
    EXPECT_EQ(load_json(R"({"integrator": {"rr": 0.8}})").integrator.rr_probability, 0.8f);
    EXPECT_EQ(load_json(R"({"integrator": {"rr": 1}})").integrator.rr_probability, 1.0f);
    EXPECT_EQ(load_error(R"({"integrator": {"rr": 0}})").message(), "expected a number in (0, 1], got 0");
    EXPECT_EQ(load_error(R"({"integrator": {"rr": 1.5}})").where().json_pointer, "/integrator/rr");
}

TEST(SceneLoaderIntegrator, LightSelectionIsRead) {
    EXPECT_EQ(load_json(R"({"integrator": {"light_selection": "uniform"}})").integrator.light_selection,
              LightSelection::kUniform);
    EXPECT_EQ(load_error(R"({"integrator": {"light_selection": "random"}})").message(),
              "unknown light selection \"random\"; expected one of: bvh, power, uniform");
}

// ---- sampler

TEST(SceneLoaderSampler, SppIsRead) {
    EXPECT_EQ(load_json(R"({"sampler": {"spp": 256}})").sampler.spp, 256);
    EXPECT_EQ(load_json(R"({"sampler": {"spp": 16777216}})").sampler.spp, 1 << 24);
    // A number with no fractional part is an integer, however it is written.
    EXPECT_EQ(load_json(R"({"sampler": {"spp": 6.4e1}})").sampler.spp, 64);
    EXPECT_EQ(load_error(R"({"sampler": {"spp": 16777217}})").message(),
              "expected an integer in [1, 16777216], got 16777217");
}

TEST(SceneLoaderSampler, SeedIsReadAsUnsigned64Bit) {
    EXPECT_EQ(load_json(R"({"sampler": {"seed": 42}})").sampler.seed, 42u);
    EXPECT_EQ(load_json(R"({"sampler": {"seed": 18446744073709551615}})").sampler.seed,
              18446744073709551615u);
    EXPECT_EQ(load_error(R"({"sampler": {"seed": 18446744073709551616}})").message(),
              "expected an integer in [0, 18446744073709551615], got 1.8446744073709552e+19");
    EXPECT_EQ(load_error(R"({"sampler": {"seed": 1.5}})").where().json_pointer, "/sampler/seed");
}

TEST(SceneLoaderSampler, AdaptiveIsReadWithDefaults) {
    EXPECT_FALSE(load_json(R"({"sampler": {}})").sampler.adaptive.has_value());
    EXPECT_EQ(load_json(R"({"sampler": {"adaptive": {}}})").sampler.adaptive, AdaptiveSettings({0.01f, 16}));
    EXPECT_EQ(load_json(R"({"sampler": {"adaptive": {"threshold": 0.05, "min_spp": 4}}})").sampler.adaptive,
              AdaptiveSettings({0.05f, 4}));
    EXPECT_EQ(load_error(R"({"sampler": {"adaptive": {"threshold": 0}}})").message(),
              "expected a number in (0, 1), got 0");
    EXPECT_EQ(load_error(R"({"sampler": {"adaptive": {"threshold": 1}}})").where().json_pointer,
              "/sampler/adaptive/threshold");
    EXPECT_EQ(load_error(R"({"sampler": {"adaptive": {"min_spp": 1}}})").message(),
              "expected an integer in [2, 16777216], got 1");
    EXPECT_EQ(load_error(R"({"sampler": {"adaptive": {"treshold": 0.1}}})").where().json_pointer,
              "/sampler/adaptive");
    EXPECT_EQ(load_error(R"({"sampler": {"adaptive": 0.01}})").where().json_pointer, "/sampler/adaptive");
}

// ---- camera

TEST(SceneLoaderCamera, PositionLookAtAndUpAreRead) {
    Scene s = load_json(R"({"camera": {"position": [1, 2, 3], "look_at": [4, 5, 6],
                                       "up": [0, 0, 1]}})");
    EXPECT_EQ(s.camera.position, Vec3f(1, 2, 3));
    EXPECT_EQ(s.camera.look_at, Vec3f(4, 5, 6));
    EXPECT_EQ(s.camera.up, Vec3f(0, 0, 1));
}

TEST(SceneLoaderCamera, FovIsRead) {
    EXPECT_EQ(load_json(R"({"camera": {"fov": 90}})").camera.fov_degrees, 90.0f);
    EXPECT_EQ(load_json(R"({"camera": {"fov": 179.5}})").camera.fov_degrees, 179.5f);
    EXPECT_EQ(load_error(R"({"camera": {"fov": 0}})").message(),
              "expected a number in (0, 180), got 0");
}

TEST(SceneLoaderCamera, ResolutionIsWidthThenHeight) {
    Scene s = load_json(R"({"camera": {"resolution": [640, 360]}})");
    EXPECT_EQ(s.camera.width, 640);
    EXPECT_EQ(s.camera.height, 360);
    SceneError e = load_error(R"({"camera": {"resolution": [0, 360]}})");
    EXPECT_EQ(e.where().json_pointer, "/camera/resolution/0");
    EXPECT_EQ(e.message(), "expected an integer in [1, 32768], got 0");
}

TEST(SceneLoaderCamera, NearIsRead) {
    EXPECT_EQ(load_json(R"({"camera": {"near": 140}})").camera.near, 140.0f);
    EXPECT_EQ(load_error(R"({"camera": {"near": -1}})").message(),
              "expected a number >= 0, got -1");
}

TEST(SceneLoaderCamera, DegenerateFrameIsReportedAtTheKeyGiven) {
    // look_at defaults to [0, 0, -1]: a position there leaves no view direction.
    SceneError same = load_error(R"({"camera": {"position": [0, 0, -1]}})");
    EXPECT_EQ(same.where().json_pointer, "/camera/position");
    EXPECT_NE(same.message().find("look_at equals position"), std::string::npos);
    // The default up [0, 1, 0] is parallel to a camera looking straight down.
    SceneError down = load_error(R"({"camera": {"position": [0, 5, 0], "look_at": [0, 0, 0]}})");
    EXPECT_EQ(down.where().json_pointer, "/camera/look_at");
    EXPECT_NE(down.message().find("is parallel to the view direction"), std::string::npos);
    EXPECT_EQ(load_error(R"({"camera": {"up": [0, 0, 0]}})").message(),
              "expected a nonzero up vector, got [0, 0, 0]");
    // Not parallel, though far from perpendicular: fine.
    EXPECT_EQ(load_json(R"({"camera": {"up": [0, 1, -100]}})").camera.up, Vec3f(0, 1, -100));
}

// ---- film

TEST(SceneLoaderFilm, FilterSelectsEachFilter) {
    for (std::string_view name : filter_type_names()) {
        Scene s = load_json(R"({"film": {"filter": ")" + std::string(name) + "\"}}");
        EXPECT_EQ(filter_type_name(s.film.filter.type), name);
    }
    EXPECT_EQ(load_json(R"({"film": {"filter": "tent"}})").film.filter, FilterType::kTent);
}

TEST(SceneLoaderFilm, TonemapSelectsEachToneMap) {
    for (std::string_view name : tonemap_names()) {
        Scene s = load_json(R"({"film": {"tonemap": ")" + std::string(name) + "\"}}");
        EXPECT_EQ(tonemap_name(s.film.tonemap), name);
    }
    EXPECT_EQ(load_json(R"({"film": {"tonemap": "aces"}})").film.tonemap, Tonemap::kAces);
}

TEST(SceneLoaderFilm, ExposureIsRead) {
    EXPECT_EQ(load_json(R"({"film": {"exposure": 0}})").film.exposure, 0.0f);
    EXPECT_EQ(load_json(R"({"film": {"exposure": 0.75}})").film.exposure, 0.75f);
    // Just below 1 as a double, but 1 as a float: the float is what is used, so it is refused.
    EXPECT_EQ(load_error(R"({"film": {"exposure": 0.99999999999}})").message(),
              "expected a number in [0, 1), got 0.99999999999 (which is 1 as a float)");
}

TEST(SceneLoaderFilm, TransferAndGammaAreRead) {
    Scene s = load_json(R"({"film": {"transfer": "gamma", "gamma": 1.8}})");
    EXPECT_EQ(s.film.transfer, Transfer::kGamma);
    EXPECT_EQ(s.film.gamma, 1.8f);
    EXPECT_EQ(load_json(R"({"film": {"transfer": "srgb"}})").film.transfer, Transfer::kSrgb);
    EXPECT_EQ(load_error(R"({"film": {"gamma": 0}})").message(), "expected a number > 0, got 0");
}

TEST(SceneLoaderFilm, IsoIsRead) {
    EXPECT_EQ(load_json(R"({"film": {"iso": 400}})").film.iso, 400.0f);
    EXPECT_EQ(imaging_ratio(load_json(R"({"film": {"iso": 400}})").film), 4.0f);
    EXPECT_EQ(load_error(R"({"film": {"iso": 0}})").message(), "expected a number > 0, got 0");
    EXPECT_EQ(load_error(R"({"film": {"iso": -100}})").message(), "expected a number > 0, got -100");
}

TEST(SceneLoaderFilm, ExposureTimeIsRead) {
    Scene s = load_json(R"({"film": {"exposure_time": 0.25, "iso": 200}})");
    EXPECT_EQ(s.film.exposure_time, 0.25f);
    EXPECT_EQ(imaging_ratio(s.film), 0.5f);
    EXPECT_EQ(load_error(R"({"film": {"exposure_time": 0}})").message(), "expected a number > 0, got 0");
}

TEST(SceneLoaderFilm, ImagingRatioMustStayAPositiveFloat) {
    SceneError e = load_error(R"({"film": {"iso": 1e38, "exposure_time": 1e10}})");
    EXPECT_EQ(e.message(), "the imaging ratio exposure_time * iso / 100 = 1e+10 * 1e+38 / 100 is beyond float range");
    EXPECT_EQ(e.where().json_pointer, "/film/exposure_time");
    EXPECT_EQ(load_error(R"({"film": {"iso": 1e-30, "exposure_time": 1e-30}})").message(),
              "the imaging ratio exposure_time * iso / 100 = 1e-30 * 1e-30 / 100 is below float range (0)");
}

TEST(SceneLoaderFilm, WhiteBalanceIsRead) {
    EXPECT_EQ(load_json(R"({"film": {"white_balance": 5000}})").film.white_balance, 5000.0f);
    EXPECT_EQ(load_json(R"({"film": {"white_balance": 1000}})").film.white_balance, 1000.0f);
    EXPECT_EQ(load_json(R"({"film": {"white_balance": 0}})").film.white_balance, 0.0f);
    EXPECT_EQ(load_error(R"({"film": {"white_balance": 999}})").message(),
              "expected 0 (no white balance) or a temperature >= 1000 (kelvin), got 999");
    EXPECT_EQ(load_error(R"({"film": {"white_balance": 999}})").where().json_pointer, "/film/white_balance");
    EXPECT_EQ(load_error(R"({"film": {"white_balance": -5000}})").message(), "expected a number >= 0, got -5000");
}

TEST(SceneLoaderFilm, SensorNamesTheResponses) {
    EXPECT_EQ(load_json(R"({})").film.camera_sensor, kCie1931Sensor);
    EXPECT_EQ(load_json(R"({"film": {"sensor": "cie1931"}})").film.camera_sensor, kCie1931Sensor);
    const Scene s = load_json(R"({"film": {"sensor": "sony_ilce_9"}})");
    EXPECT_EQ(s.film.camera_sensor, camera_response_index("sony_ilce_9"));
    EXPECT_EQ(sensor_name(s.film.camera_sensor), "sony_ilce_9");
    const SceneError e = load_error(R"({"film": {"sensor": "sony_ilce9"}})");
    EXPECT_EQ(e.where().json_pointer, "/film/sensor");
    EXPECT_TRUE(e.message().starts_with("unknown sensor \"sony_ilce9\"; expected one of: canon_eos_100d, "))
        << e.message();
    EXPECT_EQ(load_error(R"({"film": {"sensor": 3}})").where().json_pointer, "/film/sensor");
}

TEST(SceneLoaderFilm, AovNamesAndSpaceAreRead) {
    const Scene d = load_json(R"({})");
    EXPECT_EQ(d.film.aov_names, AovNames::kCandela);
    EXPECT_EQ(d.film.aov_space, AovSpace::kWorld);
    const Scene s = load_json(R"({"film": {"aovs": ["albedo"], "aov_names": "pbrt", "aov_space": "camera"}})");
    EXPECT_EQ(s.film.aov_names, AovNames::kPbrt);
    EXPECT_EQ(s.film.aov_space, AovSpace::kCamera);
    EXPECT_EQ(load_json(R"({"film": {"aov_names": "candela", "aov_space": "world"}})").film.aov_space,
              AovSpace::kWorld);
    EXPECT_EQ(load_error(R"({"film": {"aov_space": "screen"}})").message(),
              "unknown AOV space \"screen\"; expected one of: camera, world");
    EXPECT_EQ(load_error(R"({"film": {"aov_names": "mitsuba"}})").where().json_pointer, "/film/aov_names");
}

// ---- unknown keys

TEST(SceneLoader, UnknownKeysInEverySectionAreErrors) {
    EXPECT_EQ(load_error(R"({"integrator": {"maxdepth": 3}})").message(),
              "unknown key \"maxdepth\" (did you mean \"max_depth\"?)");
    EXPECT_EQ(load_error(R"({"sampler": {"sp": 3}})").message(),
              "unknown key \"sp\" (did you mean \"spp\"?)");
    EXPECT_EQ(load_error(R"({"camera": {"lookat": [0, 0, 1]}})").message(),
              "unknown key \"lookat\" (did you mean \"look_at\"?)");
    EXPECT_EQ(load_error(R"({"film": {"tone_map": "aces"}})").message(),
              "unknown key \"tone_map\" (did you mean \"tonemap\"?)");
    EXPECT_EQ(
        load_error(R"({"film": {"pixelbounds": [0, 8, 0, 8]}})").message(),
        "unknown key \"pixelbounds\"; expected one of: aov_names, aov_space, aovs, crop_window, exposure, "
        "exposure_time, filename, filter, gamma, iso, max_component_value, sensor, tonemap, transfer, white_balance");
    // A misspelt section is reported before anything that depends on it.
    SceneError e = load_error(R"({"shapes": [{"type": "sphere", "center": [0, 0, 0],
                                              "radius": 1, "material": "m"}],
                                  "material": {"m": {"type": "diffuse"}}})");
    EXPECT_EQ(e.message(), "unknown key \"material\" (did you mean \"materials\"?)");
}

// ---- files

TEST(SceneLoader, LoadsEverySectionFromAFile) {
    const std::filesystem::path file = test::scenes_dir() / "all_features.json";
    Scene s = load_scene(file);
    EXPECT_EQ(s.file, file);
    EXPECT_EQ(s.integrator.type, IntegratorType::kAlbedo);
    EXPECT_EQ(s.integrator.max_depth, 8);
    EXPECT_EQ(s.sampler.spp, 4);
    EXPECT_EQ(s.sampler.seed, 7u);
    EXPECT_EQ(s.camera.width, 32);
    EXPECT_EQ(s.camera.height, 24);
    EXPECT_EQ(s.film.filter, FilterType::kTent);
    EXPECT_EQ(s.film.transfer, Transfer::kGamma);
    EXPECT_EQ(s.film.iso, 200.0f);
    EXPECT_EQ(s.film.exposure_time, 0.5f);
    EXPECT_EQ(s.film.white_balance, 5500.0f);
    ASSERT_EQ(s.material_names, (std::vector<std::string>{"white", "mirror", "glass", "gold", "foil",
                                                          "frosted", "pane", "copper"}));
    // Inputs first: picture before checks, the inline constant before worn.
    EXPECT_EQ(s.texture_names, (std::vector<std::string>{"picture", "checks", "", "worn", "dim"}));
    EXPECT_EQ(s.texture_files.size(), 1u);
    EXPECT_TRUE(s.materials[1].textured);
    EXPECT_EQ(s.materials[0].surface.normal_map_convention, NormalMapConvention::kDirectX);
    EXPECT_TRUE(s.materials[1].surface.bump_map);
    EXPECT_TRUE(s.materials[2].surface.alpha.is_textured());
    ASSERT_EQ(s.shapes.size(), 4u);
    EXPECT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.spheres.size(), 1u);
    ASSERT_EQ(s.disks.size(), 1u);
    EXPECT_EQ(s.disks[0].center.y, 3.5);
    ASSERT_TRUE(s.environment);
    EXPECT_EQ(s.environment->radiance.width, 2);
    EXPECT_EQ(s.environment->scale, 0.5f);
    EXPECT_EQ(s.environment->mapping, EnvironmentMapping::kEquirectangular);
    EXPECT_EQ(s.environment->filter, EnvironmentFilter::kPoint);
    ASSERT_EQ(s.delta_lights.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<PointLight>(s.delta_lights[0].light));
    EXPECT_TRUE(std::holds_alternative<SpotLight>(s.delta_lights[1].light));
    EXPECT_EQ(s.delta_lights[2].directional_power, 10.0f);
}

TEST(SceneLoader, EveryExampleSceneLoads) {
    const std::filesystem::path scenes = std::filesystem::path(CANDELA_SOURCE_DIR) / "scenes";
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        const std::filesystem::path file = entry.path() / "scene.json";
        if (!std::filesystem::exists(file)) continue;
        Scene s = load_scene(file);
        EXPECT_FALSE(s.shapes.empty()) << file;
        ++loaded;
    }
    EXPECT_GE(loaded, 1);
}

TEST(SceneLoader, MissingSceneFileIsNamed) {
    const std::filesystem::path file = test::scenes_dir() / "no_such_scene.json";
    try {
        load_scene(file);
        FAIL() << "loaded a missing file";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, file.string());
        EXPECT_EQ(e.where().line, 0);
        EXPECT_EQ(std::string(e.what()), file.string() + ": scene file not found");
    }
}

TEST(SceneLoader, FolderIsNotASceneFile) {
    try {
        load_scene(test::scenes_dir());
        FAIL() << "loaded a folder";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file, test::scenes_dir().string());
        EXPECT_EQ(e.message(), "is a folder, not a scene file");
    }
}

TEST(SceneLoader, ErrorsNameTheFileAsGiven) {
    SceneError e = [] {
        try {
            load_scene_from_string("{\"sampler\": {\"spp\": 0}}", "some/where/scene.json");
        } catch (const SceneError& err) {
            return err;
        }
        return SceneError(SourceLocation{}, "no error");
    }();
    EXPECT_EQ(std::string(e.what()),
              "some/where/scene.json:1:21: /sampler/spp: expected an integer in [1, 16777216], got 0");
}

}  // namespace
}  // namespace candela
