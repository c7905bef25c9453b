// Textured materials end to end: a quad textured with a 2x2 image (tests/data/scenes/textures/
// rgb_2x2.png: top row red, green; bottom row blue, white) fills the view of a camera facing it.
// The rendered image shows the texture the right way up, through the albedo view and through the
// path tracer, whose BSDF at each hit is built from the texture there.
#include <gtest/gtest.h>

#include <string>

#include "candela/render/renderer.h"
#include "candela/formats/json/scene_loader.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The quad [-1, 1]^2 in the z = 0 plane (u along +x, v along +y), seen from +z with +y up,
// filling a view of [-0.8, 0.8]^2 (tan(21.8 degrees) 2 = 0.8) in 8x8 pixels.
Scene textured_quad(const std::string& integrator) {
    const std::string json = R"({
      "integrator": {"type": ")" + integrator + R"("},
      "sampler": {"spp": 4, "seed": 3},
      "camera": {"position": [0, 0, 2], "look_at": [0, 0, 0], "up": [0, 1, 0],
                 "fov": 43.6028, "resolution": [8, 8]},
      "textures": {"picture": {"type": "image", "file": "textures/rgb_2x2.png", "filter": "point"}},
      "materials": {"m": {"type": "diffuse", "albedo": {"texture": "picture"}}},
      "shapes": [{"type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0], "edge2": [0, 2, 0],
                  "material": "m"}],
      "lights": [{"type": "environment", "color": 1}]})";
    return load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json");
}

// Pixels well inside each quarter of the image see one texel (u, v within 0.2..0.3 or 0.7..0.8).
void expect_texture_quarters(const Image& image, float tolerance) {
    struct Quarter {
        int x, y;
        Rgb colour;
    };
    const Quarter quarters[] = {{1, 1, Rgb(1, 0, 0)}, {6, 1, Rgb(0, 1, 0)}, {1, 6, Rgb(0, 0, 1)}, {6, 6, Rgb(1, 1, 1)}};
    for (const Quarter& q : quarters)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(image.at(q.x, q.y)[c], q.colour[c], tolerance) << q.x << ", " << q.y << " channel " << c;
}

TEST(TextureRender, AlbedoViewShowsTheTextureTheRightWayUp) {
    const Image image = render(textured_quad("albedo"), {.threads = 2}).image;
    expect_texture_quarters(image, 0.0f);
}

TEST(TextureRender, PathTracerShadesWithTheTextureAtEachHit) {
    // Under a constant environment of 1, with nothing else in view, a diffuse surface reflects
    // its albedo exactly: BSDF sampling's f cos / pdf is the albedo and every bounce escapes.
    const Image image = render(textured_quad("bsdf"), {.threads = 2}).image;
    expect_texture_quarters(image, 1e-5f);
}

// The quad of textured_quad (normal +z, x from -1 to 1 across the image) with the albedo
// texture `albedo` (JSON), seen by the albedo view.
Image albedo_view(const std::string& albedo) {
    const std::string json = R"({
      "integrator": {"type": "albedo"},
      "sampler": {"spp": 1, "seed": 3},
      "camera": {"position": [0, 0, 2], "look_at": [0, 0, 0], "up": [0, 1, 0],
                 "fov": 43.6028, "resolution": [8, 8]},
      "materials": {"m": {"type": "diffuse", "albedo": )" + albedo + R"(}},
      "shapes": [{"type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0], "edge2": [0, 2, 0],
                  "material": "m"}],
      "lights": [{"type": "environment", "color": 1}]})";
    return render(load_scene_from_string(json, std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes" / "inline.json"),
                  {.threads = 2})
        .image;
}

TEST(TextureRender, DirectionMixSeesTheHitsNormal) {
    // The quad's normal is +z: w = |n . dir| is 1 for dir +z (tex1 everywhere), 0 for dir +x.
    const Image facing = albedo_view(R"({"type": "directionmix", "tex1": 0.2, "tex2": 0.8, "dir": [0, 0, 1]})");
    const Image across = albedo_view(R"({"type": "directionmix", "tex1": 0.2, "tex2": 0.8, "dir": [1, 0, 0]})");
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(facing.at(x, y)[0], 0.2f);
            EXPECT_EQ(across.at(x, y)[0], 0.8f);
        }
}

TEST(TextureRender, SolidCheckerboardSeesTheHitPoint) {
    // Texture space into the world: (x, y, z) -> (2x, 4y, 4z - 1/2), so a hit (x, y, 0) is at
    // texture (x/2, y/4, 1/8): cells change at x = 0 and y = 0. Pixel column 2 covers x in
    // [-0.4, -0.2] (cell -1), column 5 x in [0.2, 0.4] (cell 0); row 2 covers y in [0.2, 0.4]
    // (cell 0), row 5 y in [-0.4, -0.2] (cell -1); z is in cell 0. color0 where the sum is even.
    const Image image = albedo_view(R"({"type": "checkerboard", "dimension": 3, "color0": 0.2, "color1": 0.8,
                                         "transform": [{"scale": [2, 4, 4]}, {"translate": [0, 0, -0.5]}]})");
    EXPECT_EQ(image.at(2, 5)[0], 0.2f);
    EXPECT_EQ(image.at(5, 5)[0], 0.8f);
    EXPECT_EQ(image.at(2, 2)[0], 0.8f);
    EXPECT_EQ(image.at(5, 2)[0], 0.2f);
}

}  // namespace
}  // namespace candela
