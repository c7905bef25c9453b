// The film's max_component_value (pbrt-v4's RGBFilm maxcomponentvalue): a camera that sees only an
// emitter of RGB (10, 10, 10). Unclamped, every pixel is 10. Clamped to 2, every sample's sensor
// values (XYZ, film/sensor.h) are scaled so that the largest is 2: in RGB mode each sample is the
// same, so each pixel is exactly 10 x 2 / max(XYZ of (10, 10, 10)); in spectral mode each sample
// has its own XYZ estimate, each scaled to a largest component of 2, so each pixel's XYZ has no
// component above 2 and components summing to at least 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/render/renderer.h"
#include "candela/spectrum/color_space.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr double kEps = double(FLT_EPSILON);

Scene emitter_scene(bool spectral, const std::string& film) {
    const std::string json = R"({
      "integrator": {"type": "path", "max_depth": 1, "spectral": )" +
                             std::string(spectral ? "true" : "false") + R"(},
      "sampler": {"spp": 8, "seed": 1},
      "camera": {"position": [0, 0, -1], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40,
                 "resolution": [6, 4]},
      "film": {"filter": "box")" + film + R"(},
      "materials": {"black": {"type": "diffuse", "albedo": 0}},
      "shapes": [{"type": "quad", "corner": [-5, -5, 0], "edge1": [0, 10, 0], "edge2": [10, 0, 0],
                  "material": "black", "emission": [10, 10, 10]}]
    })";
    return load_scene_from_string(json, "film_clamp.json");
}

Vec3d xyz_of(const Rgb& c) { return srgb_color_space().xyz_from_rgb * Vec3d(c.r, c.g, c.b); }

TEST(FilmClamp, RgbModeClampsEverySampleToTheSameValue) {
    const Image free = render(emitter_scene(false, ""), {.threads = 2}).image;
    const Image clamped = render(emitter_scene(false, R"(, "max_component_value": 2)"), {.threads = 2}).image;
    const Vec3d white = xyz_of(Rgb(10.0f));
    const double expected = 10.0 * 2.0 / std::max({white.x, white.y, white.z});  // about 1.837
    ASSERT_EQ(clamped.pixels.size(), 24u);
    for (size_t i = 0; i < clamped.pixels.size(); ++i) {
        EXPECT_EQ(free.pixels[i], Rgb(10.0f)) << i;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(clamped.pixels[i][c], expected, expected * 32 * kEps) << i;
    }
}

TEST(FilmClamp, SpectralModeBoundsEveryPixelsSensorValues) {
    const Image free = render(emitter_scene(true, ""), {.threads = 2}).image;
    const Image clamped = render(emitter_scene(true, R"(, "max_component_value": 2)"), {.threads = 2}).image;
    for (size_t i = 0; i < clamped.pixels.size(); ++i) {
        const Vec3d a = xyz_of(free.pixels[i]), b = xyz_of(clamped.pixels[i]);
        EXPECT_GT(std::max({a.x, a.y, a.z}), 5.0) << i;  // unclamped: near (9.5, 10, 10.9)
        EXPECT_LE(std::max({b.x, b.y, b.z}), 2.0 * (1 + 64 * kEps)) << i;
        EXPECT_GE(b.x + b.y + b.z, 2.0 * (1 - 64 * kEps)) << i;
    }
}

}  // namespace
}  // namespace candela
