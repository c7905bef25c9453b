// The `media` section's bounded kinds: uniformgrid, rgbgrid and cloud (scene_media_grids.cpp).
// Each documented key changes the loaded medium; each defect is a located error.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "candela/media/medium.h"
#include "candela/scene/memory_budget.h"
#include "scene_test_util.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::load_error;
using test::load_json;

Scene load_medium(const std::string& medium) { return load_json(R"({"media": {"fog": )" + medium + "}}"); }

template <class T>
const T& only_medium(const Scene& s) {
    EXPECT_EQ(s.media.size(), 1u);
    const T* m = std::get_if<T>(&s.media.at(0));
    EXPECT_NE(m, nullptr);
    return *m;
}

// ---- uniformgrid

TEST(SceneMediaGrids, UniformGridReadsItsGridBoxAndCoefficients) {
    const Scene s = load_medium(R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [0.5, 2],
        "p0": [1, 0, 0], "p1": [3, 1, 1], "sigma_a": 2, "sigma_s": [1, 2, 3], "scale": 3, "g": 0.5})");
    const GridMedium& m = only_medium<GridMedium>(s);
    EXPECT_EQ(m.density.lattice.nx, 2);
    EXPECT_EQ(m.density.lattice.values[1], 2.0f);
    EXPECT_EQ(m.box.bounds.lo.x, 1.0f);
    EXPECT_EQ(m.box.bounds.hi.x, 3.0f);
    EXPECT_FLOAT_EQ(m.sigma_a.rgb.r, 6.0f);
    EXPECT_FLOAT_EQ(m.sigma_s.rgb.b, 9.0f);
    EXPECT_EQ(m.g, 0.5f);
    EXPECT_FALSE(m.emissive);
    // The second voxel's centre, x = 2.5 in the world: density 2.
    EXPECT_NEAR(m.at(Vec3f(2.5f, 0.5f, 0.5f), MediumChannels{}).sigma_a[0], 12.0f, 1e-4f);
}

TEST(SceneMediaGrids, UniformGridDefaultsArePbrtV4s) {
    const GridMedium m = only_medium<GridMedium>(load_medium(R"({"type": "uniformgrid", "size": [1, 1, 1], "density": [1]})"));
    EXPECT_EQ(m.box.bounds.lo.x, 0.0f);
    EXPECT_EQ(m.box.bounds.hi.z, 1.0f);
    EXPECT_FLOAT_EQ(m.sigma_a.rgb.g, 1.0f);
    EXPECT_FLOAT_EQ(m.sigma_s.rgb.g, 1.0f);
    EXPECT_EQ(m.g, 0.0f);
}

TEST(SceneMediaGrids, TransformPlacesTheGrid) {
    const GridMedium m = only_medium<GridMedium>(load_medium(R"({"type": "uniformgrid", "size": [1, 1, 1],
        "density": [1], "transform": [{"scale": 2}, {"translate": [10, 0, 0]}]})"));
    EXPECT_NEAR(m.box.to_medium(Vec3f(11.0f, 1.0f, 2.0f)).x, 0.5f, 1e-6f);
    EXPECT_NEAR(m.box.to_medium(Vec3f(11.0f, 1.0f, 2.0f)).z, 1.0f, 1e-6f);
}

TEST(SceneMediaGrids, TemperatureGridAndItsParameters) {
    const GridMedium m = only_medium<GridMedium>(load_medium(R"({"type": "uniformgrid", "size": [2, 1, 1],
        "density": [1, 1], "temperature": [1000, 2000], "temperature_cutoff": 300, "temperature_scale": 2,
        "Le_scale": 4})"));
    EXPECT_TRUE(m.emissive);
    EXPECT_EQ(m.temperature.lattice.values[1], 2000.0f);
    EXPECT_EQ(m.temperature_offset, 300.0f);  // the cutoff, as pbrt-v4's default offset
    EXPECT_EQ(m.temperature_scale, 2.0f);
    EXPECT_EQ(m.Le_scale.lattice.values.size(), 1u);  // a number: pbrt-v4's 1x1x1 grid, scaled
    EXPECT_EQ(m.Le_scale.lattice.values[0], 4.0f);
    const GridMedium o = only_medium<GridMedium>(load_medium(R"({"type": "uniformgrid", "size": [1, 1, 1],
        "density": [1], "temperature": [1000], "temperature_cutoff": 300, "temperature_offset": 100})"));
    EXPECT_EQ(o.temperature_offset, 100.0f);
}

TEST(SceneMediaGrids, LeWithAnLeScaleGrid) {
    const GridMedium m = only_medium<GridMedium>(load_medium(R"({"type": "uniformgrid", "size": [2, 1, 1],
        "density": [1, 1], "Le": [1, 0.5, 0.25], "Le_scale": [0, 3]})"));
    EXPECT_TRUE(m.emissive);
    EXPECT_EQ(m.Le_scale.lattice.values[1], 3.0f);
    EXPECT_FLOAT_EQ(m.Le.rgb.g, 0.5f);
    EXPECT_TRUE(m.at(Vec3f(0.25f, 0.5f, 0.5f), MediumChannels{}).Le.is_black());
    EXPECT_NEAR(m.at(Vec3f(0.75f, 0.5f, 0.5f), MediumChannels{}).Le[1], 1.5f, 1e-4f);
}

// ---- rgbgrid

TEST(SceneMediaGrids, RgbGridReadsItsVoxels) {
    const RgbGridMedium m = only_medium<RgbGridMedium>(load_medium(R"({"type": "rgbgrid", "size": [1, 1, 2],
        "sigma_a": [1, 2, 3, 4, 5, 6], "Le": [0, 0, 0, 1, 1, 1], "Le_scale": 2, "scale": 0.5, "g": -0.3,
        "p1": [1, 1, 4]})"));
    EXPECT_EQ(m.sigma_a.rgb.values[1].g, 5.0f);
    EXPECT_TRUE(m.sigma_s.empty());
    EXPECT_EQ(m.Le_scale, 2.0f);
    EXPECT_EQ(m.scale, 0.5f);
    EXPECT_EQ(m.g, -0.3f);
    EXPECT_TRUE(m.emissive);
    EXPECT_EQ(m.box.bounds.hi.z, 4.0f);
}

// ---- cloud

TEST(SceneMediaGrids, CloudReadsItsParameters) {
    const CloudMedium d = only_medium<CloudMedium>(load_medium(R"({"type": "cloud"})"));
    EXPECT_EQ(d.density, 1.0f);
    EXPECT_EQ(d.wispiness, 1.0f);
    EXPECT_EQ(d.frequency, 5.0f);
    const CloudMedium c = only_medium<CloudMedium>(load_medium(R"({"type": "cloud", "density": 2,
        "wispiness": 0.5, "frequency": 3, "sigma_s": 4, "p0": [-1, 0, 0]})"));
    EXPECT_EQ(c.density, 2.0f);
    EXPECT_EQ(c.wispiness, 0.5f);
    EXPECT_EQ(c.frequency, 3.0f);
    EXPECT_FLOAT_EQ(c.sigma_s.rgb.r, 4.0f);
    EXPECT_EQ(c.box.bounds.lo.x, -1.0f);
}

// ---- errors

// A medium, and the pointer and message of the error it gives (errors about a key, such as two
// keys given together, are located at the key but point at the medium).
struct BadMedium {
    std::string medium, pointer, message;
};
void PrintTo(const BadMedium& b, std::ostream* os) { *os << b.medium; }

class SceneMediaGridErrors : public ::testing::TestWithParam<BadMedium> {};

TEST_P(SceneMediaGridErrors, AreLocated) {
    const BadMedium& c = GetParam();
    const SceneError e = load_error(R"({"media": {"fog": )" + c.medium + "}}");
    EXPECT_EQ(e.where().json_pointer, c.pointer) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
}

INSTANTIATE_TEST_SUITE_P(
    Each, SceneMediaGridErrors,
    ::testing::Values(
        BadMedium{R"({"type": "uniformgrid", "size": [2, 2, 2], "density": [1, 2, 3, 4, 5]})", "/media/fog/density",
                  "\"density\" has 5 numbers; size 2 x 2 x 2 needs 8"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, -2]})", "/media/fog/density/1",
                  "expected a number >= 0"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, 1e39]})", "/media/fog/density/1",
                  "within float range"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, "x"]})", "/media/fog/density/1",
                  "expected a number"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 0, 1], "density": []})", "/media/fog/size/1", ">= 1"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1], "density": [1, 1]})", "/media/fog/size", "[nx, ny, nz]"},
        BadMedium{R"({"type": "uniformgrid", "size": [2000000000, 2000000000, 2000000000], "density": [1]})",
                  "/media/fog/size", "a grid of 2000000000 x 2000000000 x 2000000000 voxels is beyond any memory"},
        BadMedium{R"({"type": "uniformgrid", "size": [1, 1, 1]})", "/media/fog", "density"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, 1], "temperature": [1]})",
                  "/media/fog/temperature", "\"temperature\" has 1 numbers; size 2 x 1 x 1 needs 2"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, 1], "temperature": [1, -1]})",
                  "/media/fog/temperature/1", ">= 0"},
        BadMedium{R"({"type": "uniformgrid", "size": [2, 1, 1], "density": [1, 1], "Le": 1, "Le_scale": [1, 2, 3]})",
                  "/media/fog/Le_scale", "\"Le_scale\" has 3 numbers"},
        BadMedium{R"({"type": "uniformgrid", "size": [1, 1, 1], "density": [1], "Le": 1, "temperature": [900]})",
                  "/media/fog", "give \"Le\" or \"temperature\", not both"},
        BadMedium{R"({"type": "uniformgrid", "size": [1, 1, 1], "density": [1], "p0": [0, 1, 0], "p1": [1, 1, 1]})",
                  "/media/fog/p1", "flat in y"},
        BadMedium{R"({"type": "uniformgrid", "size": [1, 1, 1], "density": [1], "denisty": [1]})", "/media/fog",
                  "unknown key \"denisty\""},
        BadMedium{R"({"type": "rgbgrid", "size": [2, 1, 1], "sigma_a": [1, 1, 1]})", "/media/fog/sigma_a",
                  "\"sigma_a\" has 3 numbers; size 2 x 1 x 1 needs 6 (three per voxel: r, g, b)"},
        BadMedium{R"({"type": "rgbgrid", "size": [1, 1, 1]})", "/media/fog", "needs \"sigma_a\", \"sigma_s\" or both"},
        BadMedium{R"({"type": "rgbgrid", "size": [1, 1, 1], "sigma_s": [1, 1, 1], "Le": [1, 1, 1]})", "/media/fog",
                  "needs \"sigma_a\" too"},
        BadMedium{R"({"type": "rgbgrid", "size": [1, 1, 1], "sigma_a": [1, 1, -1]})", "/media/fog/sigma_a/2", ">= 0"},
        BadMedium{R"({"type": "cloud", "density": -1})", "/media/fog/density", ">= 0"},
        BadMedium{R"({"type": "cloud", "wispiness": -1})", "/media/fog/wispiness", ">= 0"},
        BadMedium{R"({"type": "cloud", "g": 2})", "/media/fog/g", "[-1, 1]"}));

TEST(SceneMediaGrids, GridsAreChargedToTheMemoryBudgetBeforeTheyAreRead) {
    std::string density;
    for (int i = 0; i < 1000; ++i) density += i ? ", 1" : "1";
    const std::string json = R"({"camera": {"resolution": [1, 1]}, "media": {"smoke": {"type": "uniformgrid",
        "size": [10, 10, 10], "density": [)" + density + R"(], "temperature": [)" + density + "]}}}";
    const Scene s = load_json(json);
    const uint64_t grid = grid_medium_memory_bytes(1000, 3, 0, true);  // density, temperature, Le_scale (1 voxel)
    EXPECT_GE(scene_memory_bytes(s), film_memory_bytes(1, 1) + grid_medium_memory_bytes(1000, 2, 0, true));
    EXPECT_LE(scene_memory_bytes(s), film_memory_bytes(1, 1) + grid);
    LoadOptions tight;
    tight.memory_limit = MemoryLimit{film_memory_bytes(1, 1) + 20000, "the test's limit is"};
    try {
        load_scene_from_string(json, test::scenes_dir() / "inline.json", tight);
        ADD_FAILURE() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().json_pointer, "/media/smoke/density");
        EXPECT_NE(e.message().find("a uniformgrid medium of 10 x 10 x 10 voxels needs about"), std::string::npos)
            << e.message();
    }
}

}  // namespace
}  // namespace candela
