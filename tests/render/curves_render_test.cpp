// Curves in a render (geometry/curves.h): a diffuse curve of albedo a under a constant environment
// of 1 reflects a in every pixel it covers, whatever its normal (flat ones face away from the
// camera, as pbrt-v4's; cylinder ones turn across the width; ribbons follow their normals), as
// long as the rays it spawns never hit it again: the closed form checks both the shading and the
// offset of spawned rays. A control 3% off must fail.
#include <gtest/gtest.h>

#include <string>

#include "candela/formats/json/scene_loader.h"
#include "support/render_moments.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// A curve 4 wide along x, seen from z = 5 through a narrow field of view that it fills.
Scene curve_scene(const std::string& curve_type, bool spectral) {
    const std::string normals = curve_type == "ribbon" ? R"(, "normals": [[0, 0.3, 1], [0, -0.3, 1]])" : "";
    return load_scene_from_string(
        R"({"integrator": {"type": "path", "spectral": )" + std::string(spectral ? "true" : "false") + R"(},
          "sampler": {"type": "independent", "spp": 256, "seed": 7},
          "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 8, "resolution": [16, 16]},
          "materials": {"m": {"type": "diffuse", "albedo": 0.5}},
          "shapes": [{"type": "curves", "material": "m", "curve_type": ")" +
            curve_type + R"(", "width": 4, "points": [[-4, 0, 0], [-1, 0.2, 0], [1, -0.2, 0], [4, 0, 0]])" + normals +
            R"(}],
          "lights": [{"type": "environment", "color": 1}]})",
        std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
}

class CurvesFurnace : public ::testing::TestWithParam<std::string> {};

TEST_P(CurvesFurnace, ADiffuseCurveReflectsItsAlbedoInBothModes) {
    for (bool spectral : {false, true}) {
        const test::RenderMoments m = test::render_moments(curve_scene(GetParam(), spectral));
        const test::ZTestFamily family = test::test_against(m, {0.5, 0.5, 0.5}, 4);
        EXPECT_TRUE(family.passed()) << GetParam() << (spectral ? " spectral: " : " rgb: ") << family.summary();
        const test::ZTestFamily off = test::test_against(m, {0.515, 0.515, 0.515}, 4);
        EXPECT_FALSE(off.passed()) << off.summary();
    }
}

INSTANTIATE_TEST_SUITE_P(Kinds, CurvesFurnace, ::testing::Values("flat", "cylinder", "ribbon"));

}  // namespace
}  // namespace candela
