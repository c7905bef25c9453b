// The volumetric path tracer (integrators/volpath_integrator.h) against closed forms and against
// itself with another estimator, each with a control that must fail:
//   - Beer-Lambert: a diffuse floor under an absorbing slab, lit by a directional light: the camera
//     ray (delta tracking) and the shadow ray (ratio tracking, through an `interface`) each cross
//     the slab once, so the floor's radiance is a/pi E exp(-2 sigma_a d);
//   - emission: an emitting, absorbing slab seen straight through gives Le (1 - exp(-sigma_a d)),
//     optically thin (0.05) and thick (3);
//   - white furnace: a sphere of a scattering, non-absorbing medium (albedo 1, chromatic sigma_s,
//     anisotropic) under an environment of 1 is invisible: 1 in every pixel, in both colour modes,
//     with the camera outside it and inside it;
//   - NEE + phase/BSDF sampling (MIS), NEE alone, and phase/BSDF sampling alone (the bsdf
//     integrator on a scene with media) agree on a fog-filled room with coloured glass and
//     chromatic smoke;
//   - grey media render the same in RGB and spectral mode;
//   - `path` crosses `interface` shapes without counting a bounce, as pbrt-v4's path does.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/render/renderer.h"
#include "support/render_moments.h"

namespace candela {
namespace CANDELA_UNITY_ID {

Scene scene_of(const std::string& json) {
    return load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
}

std::string integrator_json(bool spectral, bool mis, int max_depth = 1000) {
    return R"("integrator": {"type": "volpath", "max_depth": )" + std::to_string(max_depth) +
           R"(, "mis": )" + (mis ? "true" : "false") + R"(, "spectral": )" + (spectral ? "true" : "false") + "}";
}

std::array<double, 3> scaled(std::array<double, 3> v, double s) {
    for (double& x : v) x *= s;
    return v;
}

// An orthographic camera looking straight down (-z) from z = 3 at a 0.5 x 0.5 patch.
constexpr const char* kCameraDown = R"("camera": {"type": "orthographic", "position": [0, 0, 3], "look_at": [0, 0, 0],
               "up": [0, 1, 0], "height": 0.5, "resolution": [16, 16])";

// The floor z = 0 (albedo 0.5) under the slab 0 < z < 1 of medium "m", whose top is an
// interface; a directional light of irradiance 1 shines straight down.
std::string beer_lambert_scene(const std::string& sigma_a, bool spectral) {
    return R"({)" + integrator_json(spectral, true) + R"(,
      "sampler": {"type": "independent", "spp": 2048, "seed": 3},
      "media": {"m": {"type": "homogeneous", "sigma_a": )" + sigma_a + R"(, "sigma_s": 0}},
      )" + kCameraDown + R"(},
      "materials": {"floor": {"type": "diffuse", "albedo": 0.5}, "boundary": {"type": "interface"}},
      "shapes": [
        {"type": "quad", "corner": [-2, -2, 0], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "floor", "exterior": "m"},
        {"type": "quad", "corner": [-2, -2, 1], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "interior": "m"}],
      "lights": [{"type": "directional", "direction": [0, 0, -1], "irradiance": 1}]})";
}

TEST(VolPath, BeerLambertSlabRgb) {
    const test::RenderMoments m = test::render_moments(scene_of(beer_lambert_scene("[0.2, 0.5, 1.0]", false)));
    const double k = 0.5 / M_PI;
    const std::array<double, 3> expected = {k * std::exp(-0.4), k * std::exp(-1.0), k * std::exp(-2.0)};
    const test::ZTestFamily family = test::test_against(m, expected, 4);
    EXPECT_TRUE(family.passed()) << family.summary();
    // Control: the slab crossed once instead of twice is far outside the noise.
    const test::ZTestFamily once = test::test_against(m, {k * std::exp(-0.2), k * std::exp(-0.5), k * std::exp(-1.0)}, 4);
    EXPECT_FALSE(once.passed()) << once.summary();
    const test::ZTestFamily off = test::test_against(m, scaled(expected, 1.03), 4);
    EXPECT_FALSE(off.passed()) << off.summary();
}

TEST(VolPath, BeerLambertSlabSpectral) {
    const test::RenderMoments m = test::render_moments(scene_of(beer_lambert_scene("0.5", true)));
    const double v = 0.5 / M_PI * std::exp(-1.0);
    const test::ZTestFamily family = test::test_against(m, {v, v, v}, 4);
    EXPECT_TRUE(family.passed()) << family.summary();
    const test::ZTestFamily off = test::test_against(m, {1.03 * v, 1.03 * v, 1.03 * v}, 4);
    EXPECT_FALSE(off.passed()) << off.summary();
}

// The slab 0 < z < 1 of an absorbing medium that emits Le = 1, both faces interfaces, seen from
// above against black: each ray crosses it once.
std::string emitting_slab_scene(double sigma_a, bool spectral) {
    return R"({)" + integrator_json(spectral, true) + R"(,
      "sampler": {"type": "independent", "spp": 4096, "seed": 5},
      "media": {"e": {"type": "homogeneous", "sigma_a": )" + std::to_string(sigma_a) + R"(, "sigma_s": 0, "Le": 1}},
      )" + kCameraDown + R"(},
      "materials": {"boundary": {"type": "interface"}},
      "shapes": [
        {"type": "quad", "corner": [-2, -2, 0], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "exterior": "e"},
        {"type": "quad", "corner": [-2, -2, 1], "edge1": [4, 0, 0], "edge2": [0, 4, 0], "material": "boundary", "interior": "e"}]})";
}

TEST(VolPath, EmissionOfThinAndThickSlabs) {
    for (bool spectral : {false, true}) {
        for (double sigma_a : {0.05, 3.0}) {
            SCOPED_TRACE(fmt::format("sigma_a {} spectral {}", sigma_a, spectral));
            const test::RenderMoments m = test::render_moments(scene_of(emitting_slab_scene(sigma_a, spectral)));
            const double v = 1.0 - std::exp(-sigma_a);
            const test::ZTestFamily family = test::test_against(m, {v, v, v}, 4);
            EXPECT_TRUE(family.passed()) << family.summary();
            // Control: the thin slab's emission without its self-absorption (Le sigma_a d), the
            // thick one's 2% low.
            const double wrong = sigma_a < 1.0 ? sigma_a : 0.98 * v;
            const test::ZTestFamily off = test::test_against(m, {wrong, wrong, wrong}, 4);
            EXPECT_FALSE(off.passed()) << off.summary();
        }
    }
}

// A sphere of radius 1 of medium "s" (no absorption) under a constant environment of 1.
std::string furnace_scene(bool spectral, bool mis, bool camera_inside) {
    const std::string sigma_s = spectral ? R"({"spectrum": [360, 0.5, 600, 1.5, 830, 3.0]})" : "[0.5, 1.0, 2.0]";
    const std::string camera = camera_inside
                                   ? R"("position": [0.2, -0.1, -0.5], "look_at": [0, 0, 1], "medium": "s")"
                                   : R"("position": [0, 0, -3.5], "look_at": [0, 0, 0])";
    return R"({)" + integrator_json(spectral, mis) + R"(,
      "sampler": {"type": "independent", "spp": 512, "seed": 9},
      "media": {"s": {"type": "homogeneous", "sigma_a": 0, "sigma_s": )" + sigma_s + R"(, "g": 0.6}},
      "camera": {)" + camera + R"(, "up": [0, 1, 0], "fov": 50, "resolution": [16, 16]},
      "materials": {"boundary": {"type": "interface"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "boundary", "interior": "s"}],
      "lights": [{"type": "environment", "color": 1}]})";
}

TEST(VolPath, AlbedoOneMediumIsInvisibleInAWhiteFurnace) {
    for (bool spectral : {false, true})
        for (bool mis : {true, false})
            for (bool inside : {false, true}) {
                SCOPED_TRACE(fmt::format("spectral {} mis {} camera inside {}", spectral, mis, inside));
                const test::RenderMoments m = test::render_moments(scene_of(furnace_scene(spectral, mis, inside)));
                EXPECT_EQ(m.dropped, 0u);
                const test::ZTestFamily family = test::test_against(m, {1.0, 1.0, 1.0}, 4);
                EXPECT_TRUE(family.passed()) << family.summary();
                const test::ZTestFamily off = test::test_against(m, {1.03, 1.03, 1.03}, 4);
                EXPECT_FALSE(off.passed()) << off.summary();
            }
}

// A room of fog (the camera in it) lit by a quad light and a spot light: a glass sphere with an
// amber interior, a box of chromatic smoke with an interface boundary.
std::string fog_room_scene(bool spectral, bool mis, bool grey, const std::string& type = "volpath",
                           bool spot = true, int spp_mis = 1536, int spp_nee = 2048) {
    const std::string amber = grey ? "0.4" : "[0.1, 0.5, 1.5]";
    const std::string smoke = grey ? "1.0" : "[2.0, 1.0, 0.3]";
    std::string integrator = integrator_json(spectral, mis, 40);
    integrator.replace(integrator.find("volpath"), 7, type);
    const std::string spot_light = R"([{"type": "spot", "position": [-2, 3, -2], "look_at": [0, 0, 1], "intensity": 6,
                                       "cone_angle": 25, "cone_delta": 5}])";
    return R"({)" + integrator + R"(,
      "sampler": {"type": "independent", "spp": )" + std::to_string(mis ? spp_mis : spp_nee) + R"(, "seed": )" +
           (mis ? "21" : "22") + R"(},
      "media": {"fog": {"type": "homogeneous", "sigma_a": 0.02, "sigma_s": 0.15, "g": 0.3},
                "amber": {"type": "homogeneous", "sigma_a": )" + amber + R"(, "sigma_s": 0.2},
                "smoke": {"type": "homogeneous", "sigma_a": 0.1, "sigma_s": )" + smoke + R"(, "g": -0.3}},
      "camera": {"position": [0, 1, -4], "look_at": [0, 1, 0], "up": [0, 1, 0], "fov": 60, "resolution": [16, 16],
                 "medium": "fog"},
      "materials": {"white": {"type": "diffuse", "albedo": 0.7}, "glass": {"type": "dielectric", "ior": 1.5},
                    "boundary": {"type": "interface"}, "lamp": {"type": "diffuse", "albedo": 0}},
      "shapes": [
        {"type": "quad", "corner": [-3, 0, -5], "edge1": [0, 0, 8], "edge2": [6, 0, 0], "material": "white"},
        {"type": "quad", "corner": [-3, 0, 3], "edge1": [0, 4, 0], "edge2": [6, 0, 0], "material": "white"},
        {"type": "sphere", "center": [-0.8, 0.7, 0.5], "radius": 0.7, "material": "glass", "interior": "amber", "exterior": "fog"},
        {"type": "sphere", "center": [1.0, 0.8, 0.8], "radius": 0.8, "material": "boundary", "interior": "smoke", "exterior": "fog"},
        {"type": "quad", "corner": [-0.5, 3.5, -0.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "material": "lamp",
         "emission": 8}],
      "lights": )" + (spot ? spot_light : "[]") + "}";
}

TEST(VolPath, NeeAloneAndMisAgreeInAFogRoom) {
    for (bool spectral : {false, true}) {
        SCOPED_TRACE(fmt::format("spectral {}", spectral));
        const test::RenderMoments with_mis = test::render_moments(scene_of(fog_room_scene(spectral, true, false)));
        const test::RenderMoments nee = test::render_moments(scene_of(fog_room_scene(spectral, false, false)));
        const test::ZTestFamily family = test::compare_blocks_and_whole(with_mis, nee, 4);
        EXPECT_TRUE(family.passed()) << family.summary();
        const test::ZTestFamily off = test::compare_blocks_and_whole(with_mis, nee, 4, 1.1);
        EXPECT_FALSE(off.passed()) << off.summary();
    }
}

// Without light sampling (the bsdf integrator on a scene with media) light is found only where
// scattering leads: it checks NEE's transmittance through media and interfaces, the MIS weights
// and the spectral MIS of both. Only the quad light, which both can find.
TEST(VolPath, WithAndWithoutLightSamplingAgreeInAFogRoom) {
    for (bool spectral : {false, true}) {
        SCOPED_TRACE(fmt::format("spectral {}", spectral));
        const test::RenderMoments with_nee =
            test::render_moments(scene_of(fog_room_scene(spectral, true, false, "volpath", false, 1024)));
        const test::RenderMoments without =
            test::render_moments(scene_of(fog_room_scene(spectral, false, false, "bsdf", false, 0, 4096)));
        const test::ZTestFamily family = test::compare_blocks_and_whole(with_nee, without, 4);
        EXPECT_TRUE(family.passed()) << family.summary();
        const test::ZTestFamily off = test::compare_blocks_and_whole(with_nee, without, 4, 1.1);
        EXPECT_FALSE(off.passed()) << off.summary();
    }
}

TEST(VolPath, GreyMediaRenderAlikeInBothModes) {
    const test::RenderMoments rgb = test::render_moments(scene_of(fog_room_scene(false, true, true)));
    const test::RenderMoments spectral = test::render_moments(scene_of(fog_room_scene(true, false, true)));
    const test::ZTestFamily family = test::compare_blocks_and_whole(rgb, spectral, 4);
    EXPECT_TRUE(family.passed()) << family.summary();
    const test::ZTestFamily off = test::compare_blocks_and_whole(rgb, spectral, 4, 1.1);
    EXPECT_FALSE(off.passed()) << off.summary();
}

// A medium far denser than any real one (albedo 1, or absorbing) renders in bounded time: the
// path scatters at most max_depth times, and its shadow rays end at their first collision.
TEST(VolPath, ExtremelyDenseMediaDoNotHang) {
    for (const char* coefficients : {R"("sigma_a": 0, "sigma_s": 1e30)", R"("sigma_a": 1e30, "sigma_s": 0)",
                                     R"("sigma_a": 1e20, "sigma_s": 1e25, "Le": 1)"}) {
        SCOPED_TRACE(coefficients);
        const Scene scene = scene_of(R"({"integrator": {"type": "volpath", "max_depth": 200},
          "sampler": {"spp": 4},
          "media": {"dense": {"type": "homogeneous", )" + std::string(coefficients) + R"(}},
          "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40, "resolution": [16, 16]},
          "materials": {"boundary": {"type": "interface"}},
          "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "boundary", "interior": "dense"}],
          "lights": [{"type": "environment", "color": 1}]})");
        const auto start = std::chrono::steady_clock::now();
        const RenderResult r = render(scene, {.threads = 2});
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 10.0);
        EXPECT_EQ(r.stats.dropped_samples, 0u);
        for (const Rgb& p : r.image.pixels) EXPECT_TRUE(p.is_finite());
    }
}

// pbrt-v4's `path` on a scene with `interface` shapes: a crossing is no bounce (SkipIntersection),
// shadow rays stop at the boundary, and light found straight through one counts in full. So
// direct light alone (max_depth 1) through an interface between the camera and the floor and
// another between the floor and the light is the direct light of the scene without them; it
// reaches the floor by BSDF sampling only, hence the spp. (Counting a crossing as a bounce leaves
// the floor black: its own control. The 1.1 scale is the usual one.)
std::string interface_room_scene(bool with_interfaces, int spp) {
    const std::string boundaries = with_interfaces ? R"(,
        {"type": "quad", "corner": [-3, 2, -5], "edge1": [0, 0, 10], "edge2": [6, 0, 0], "material": "boundary"},
        {"type": "quad", "corner": [-3, -3, -1], "edge1": [6, 0, 0], "edge2": [0, 6, 0], "material": "boundary"})"
                                                   : "";
    return R"({"integrator": {"type": "path", "max_depth": 1},
      "sampler": {"type": "independent", "spp": )" + std::to_string(spp) + R"(, "seed": )" + (with_interfaces ? "5" : "6") + R"(},
      "camera": {"position": [0, 1, -4], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 50, "resolution": [16, 16]},
      "materials": {"white": {"type": "diffuse", "albedo": 0.7}, "boundary": {"type": "interface"},
                    "lamp": {"type": "diffuse", "albedo": 0}},
      "shapes": [
        {"type": "quad", "corner": [-3, 0, -5], "edge1": [0, 0, 10], "edge2": [6, 0, 0], "material": "white"},
        {"type": "quad", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "material": "lamp", "emission": 4})" +
           boundaries + "]}";
}

TEST(PathWithInterfaces, ACrossingIsNoBounceAsInPbrtV4sPath) {
    const test::RenderMoments through = test::render_moments(scene_of(interface_room_scene(true, 2048)));
    const test::RenderMoments open = test::render_moments(scene_of(interface_room_scene(false, 256)));
    const test::ZTestFamily family = test::compare_blocks_and_whole(through, open, 4);
    EXPECT_TRUE(family.passed()) << family.summary();
    const test::ZTestFamily off = test::compare_blocks_and_whole(through, open, 4, 1.1);
    EXPECT_FALSE(off.passed()) << off.summary();
}

}  // namespace
}  // namespace candela
