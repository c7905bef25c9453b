// The volumetric path tracer through pbrt-v4's bounded media (uniformgrid, rgbgrid, cloud) against
// closed forms, each with a control that must fail:
//   - Beer-Lambert through a uniformgrid slab whose density is a ramp in z (piecewise linear
//     between the samples, falling to half the end samples on the box's faces), placed by a
//     transform that stretches z: the floor under it, lit straight down, has radiance
//     a/pi E exp(-2 tau), tau the integral of sigma_a times the density across the slab (delta
//     tracking on the camera ray, ratio tracking on the shadow ray, both through the DDA);
//   - emission of a uniformgrid slab with an Le_scale grid, seen straight through: the integral
//     of sigma_a(z) Le(z) exp(-tau(z)) over the slab, by quadrature of the piecewise-linear grids;
//   - white furnace: a sphere holding each bounded kind with sigma_a = 0 (albedo 1) is invisible.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "candela/formats/json/scene_loader.h"
#include "candela/formats/vdb/nanovdb_reader.h"
#include "candela/scene/memory_budget.h"
#include "formats/vdb/nvdb_fixtures.h"
#include "support/render_moments.h"

namespace candela {
namespace CANDELA_UNITY_ID {

Scene scene_of(const std::string& json) {
    return load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
}

std::string integrator_json(bool spectral) {
    return R"("integrator": {"type": "volpath", "max_depth": 1000, "spectral": )" + std::string(spectral ? "true" : "false") + "}";
}

std::array<double, 3> grey(double v) { return {v, v, v}; }

// The column's samples in z (3 x 3 in x and y, the same in each: the camera's patch lies between
// the x and y samples' centres, where the grid is constant in x and y).
const std::vector<double> kRamp = {0.2, 0.9, 1.6, 0.4};
const std::vector<double> kLeScale = {1.0, 0.0, 2.0, 3.0};

// A uniformgrid sample column as the lookup interpolates it, at z in [0, 1] of the box.
double column(const std::vector<double>& v, double z) {
    const double q = z * double(v.size()) - 0.5;
    const int i = int(std::floor(q));
    const double t = q - i;
    auto at = [&](int k) { return k < 0 || k >= int(v.size()) ? 0.0 : v[size_t(k)]; };
    return (1 - t) * at(i) + t * at(i + 1);
}

std::string grid_json(const std::vector<double>& column_values) {
    std::string s;
    for (double v : column_values)
        for (int i = 0; i < 9; ++i) s += (s.empty() ? "" : ", ") + std::to_string(v);
    return "[" + s + "]";
}

// The slab 0 < z < 2 in the world: a uniformgrid over [0, 1]^3 scaled by (4, 4, 2) and moved by
// (-2, -2, 0), its top an interface; the camera looks down at a 0.5 x 0.5 patch at the centre.
constexpr const char* kSlabCamera = R"("camera": {"type": "orthographic", "position": [0, 0, 3], "look_at": [0, 0, 0],
               "up": [0, 1, 0], "height": 0.5, "resolution": [16, 16]})";
constexpr const char* kSlabTransform = R"("transform": [{"scale": [4, 4, 2]}, {"translate": [-2, -2, 0]}])";

std::string beer_lambert_grid_scene(bool spectral) {
    return R"({)" + integrator_json(spectral) + R"(,
      "sampler": {"type": "independent", "spp": 2048, "seed": 3},
      "media": {"m": {"type": "uniformgrid", "size": [3, 3, 4], "density": )" + grid_json(kRamp) + R"(,
                      "sigma_a": 0.5, "sigma_s": 0, )" + kSlabTransform + R"(}},
      )" + kSlabCamera + R"(,
      "materials": {"floor": {"type": "diffuse", "albedo": 0.5}, "boundary": {"type": "interface"}},
      "shapes": [
        {"type": "quad", "corner": [-2, -2, 0], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "floor", "exterior": "m"},
        {"type": "quad", "corner": [-2, -2, 2], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "interior": "m"}],
      "lights": [{"type": "directional", "direction": [0, 0, -1], "irradiance": 1}]})";
}

// The integral of f over [0, 1] by the midpoint rule (the grids are piecewise linear: 2^16 steps
// leave errors far below the renders' noise).
template <class F>
double integrate01(F&& f) {
    constexpr int n = 1 << 16;
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += f((i + 0.5) / n);
    return s / n;
}

TEST(VolPathGrids, BeerLambertThroughADensityRamp) {
    // tau across the slab: sigma_a times the density integrated over the world's 2 units of z.
    const double tau = 0.5 * 2.0 * integrate01([](double z) { return column(kRamp, z); });
    const double expected = 0.5 / M_PI * std::exp(-2.0 * tau);
    for (bool spectral : {false, true}) {
        SCOPED_TRACE(spectral ? "spectral" : "rgb");
        const test::RenderMoments m = test::render_moments(scene_of(beer_lambert_grid_scene(spectral)));
        const test::ZTestFamily family = test::test_against(m, grey(expected), 4);
        EXPECT_TRUE(family.passed()) << family.summary();
        // Controls: the density taken as constant at its mean sample, and 3% off.
        const double flat_tau = 0.5 * 2.0 * (0.2 + 0.9 + 1.6 + 0.4) / 4;
        const test::ZTestFamily flat = test::test_against(m, grey(0.5 / M_PI * std::exp(-2.0 * flat_tau)), 4);
        EXPECT_FALSE(flat.passed()) << flat.summary();
        const test::ZTestFamily off = test::test_against(m, grey(1.03 * expected), 4);
        EXPECT_FALSE(off.passed()) << off.summary();
    }
}

std::string emitting_grid_scene(bool spectral) {
    return R"({)" + integrator_json(spectral) + R"(,
      "sampler": {"type": "independent", "spp": 4096, "seed": 5},
      "media": {"e": {"type": "uniformgrid", "size": [3, 3, 4], "density": )" + grid_json(kRamp) + R"(,
                      "sigma_a": 0.7, "sigma_s": 0, "Le": 1, "Le_scale": )" + grid_json(kLeScale) + ", " + kSlabTransform + R"(}},
      )" + kSlabCamera + R"(,
      "materials": {"boundary": {"type": "interface"}},
      "shapes": [
        {"type": "quad", "corner": [-2, -2, 0], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "exterior": "e"},
        {"type": "quad", "corner": [-2, -2, 2], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "interior": "e"}]})";
}

TEST(VolPathGrids, EmissionOfAGridSlabWithAnLeScaleGrid) {
    // Seen from above (z = 1 of the box at the top): L = integral over the world's z of
    // sigma_a(z) Le(z) exp(-tau(z, top)), with dz_world = 2 dz_box.
    const double sigma_a = 0.7;
    constexpr int n = 1 << 16;
    double L = 0.0, tau = 0.0;
    for (int i = n - 1; i >= 0; --i) {  // from the top down, accumulating tau
        const double z = (i + 0.5) / n, dz = 2.0 / n;
        const double sa = sigma_a * column(kRamp, z);
        L += sa * column(kLeScale, z) * std::exp(-(tau + 0.5 * sa * dz)) * dz;
        tau += sa * dz;
    }
    for (bool spectral : {false, true}) {
        SCOPED_TRACE(spectral ? "spectral" : "rgb");
        const test::RenderMoments m = test::render_moments(scene_of(emitting_grid_scene(spectral)));
        const test::ZTestFamily family = test::test_against(m, grey(L), 4);
        EXPECT_TRUE(family.passed()) << family.summary();
        // Control: emission not weighted by the density (sigma_a alone).
        double wrong = 0.0;
        for (int i = 0; i < n; ++i) wrong += sigma_a * column(kLeScale, (i + 0.5) / n) * 2.0 / n;
        const test::ZTestFamily off = test::test_against(m, grey(wrong), 4);
        EXPECT_FALSE(off.passed()) << off.summary();
    }
}

// A sphere of radius 1 holding `medium` (which must not absorb) under an environment of 1.
std::string furnace_scene(const std::string& medium, bool spectral) {
    return R"({)" + integrator_json(spectral) + R"(,
      "sampler": {"type": "independent", "spp": 512, "seed": 9},
      "media": {"s": )" + medium + R"(},
      "camera": {"position": [0, 0, -3.5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 50, "resolution": [16, 16]},
      "materials": {"boundary": {"type": "interface"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "boundary", "interior": "s"}],
      "lights": [{"type": "environment", "color": 1}]})";
}

TEST(VolPathGrids, AlbedoOneBoundedMediaAreInvisibleInAWhiteFurnace) {
    const std::string place = R"("p0": [-1, -1, -1], "p1": [1, 1, 1])";
    const std::vector<std::string> media = {
        R"({"type": "uniformgrid", "size": [2, 2, 2], "density": [0, 1, 4, 2, 3, 0.5, 1, 6], "sigma_a": 0,
            "sigma_s": [1, 2, 0.5], "g": 0.5, )" + place + "}",
        R"({"type": "rgbgrid", "size": [1, 2, 1], "sigma_a": [0, 0, 0, 0, 0, 0], "sigma_s": [1, 3, 0.2, 4, 0.5, 2],
            "scale": 2, )" + place + "}",
        R"({"type": "cloud", "sigma_a": 0, "sigma_s": 8, "g": -0.3, "transform": [{"translate": [-0.5, -0.5, -0.5]}], )" +
            place + "}"};
    for (const std::string& medium : media)
        for (bool spectral : {false, true}) {
            SCOPED_TRACE(medium + (spectral ? " spectral" : " rgb"));
            const test::RenderMoments m = test::render_moments(scene_of(furnace_scene(medium, spectral)));
            const test::ZTestFamily family = test::test_against(m, grey(1.0), 4);
            EXPECT_TRUE(family.passed()) << family.summary();
            const test::ZTestFamily off = test::test_against(m, grey(1.03), 4);
            EXPECT_FALSE(off.passed()) << off.summary();
        }
}

// The same through grids read from NanoVDB files (the `nanovdb` medium): a grid under a scaled and
// translated map, and one converted from OpenVDB with tiles and a rotated map, each moved and
// scaled into the sphere by the medium's transform. A majorant that misses part of the grid's
// density (a wrong inverse of the file's map, a wrong block origin) shows as a bias.
TEST(VolPathGrids, AlbedoOneNanoVdbMediaAreInvisibleInAWhiteFurnace) {
    for (const char* name : {"scaled_translated.nvdb", "tiles.nvdb"}) {
        const std::filesystem::path file = test::nvdb_fixture(name);
        MemoryBudget budget(MemoryLimit::of_this_process());
        const VolumeGrid g = read_nanovdb_grid(file, "density", budget);
        float densest = 0.0f;
        for (float v : g.values) densest = std::max(densest, v);
        const Vec3d centre = (g.world_min + g.world_max) * 0.5;
        const double half = length(g.world_max - g.world_min) * 0.5;
        const std::string medium = fmt::format(
            R"({{"type": "nanovdb", "file": "{}", "sigma_a": 0, "sigma_s": [{}, {}, {}], "g": 0.3,
                 "transform": [{{"translate": [{}, {}, {}]}}, {{"scale": {}}}]}})",
            file.string(), 2.0 / double(densest), 4.0 / double(densest), 1.0 / double(densest), -centre.x, -centre.y, -centre.z, 0.95 / half);
        for (bool spectral : {false, true}) {
            SCOPED_TRACE(std::string(name) + (spectral ? " spectral" : " rgb"));
            const test::RenderMoments m = test::render_moments(scene_of(furnace_scene(medium, spectral)));
            const test::ZTestFamily family = test::test_against(m, grey(1.0), 4);
            EXPECT_TRUE(family.passed()) << family.summary();
            const test::ZTestFamily off = test::test_against(m, grey(1.03), 4);
            EXPECT_FALSE(off.passed()) << off.summary();
        }
    }
}

}  // namespace
}  // namespace candela
