// Depth of field through the whole renderer (issue 13, "thin lens: a point in the focus plane
// lands in one pixel, and the blur circle of a point off it has the thin-lens diameter"), and the
// determinism and resume guarantees for cameras with a lens.
//
// The scenes are a small emitting square facing the camera, in the dark, seen with the box filter
// and independent samples: a camera sample either hits the square (radiance L) or sees nothing, so
// L / spp times a pixel's value counts the hits in it, exactly. For a lens point l the square's
// image is a square of its own apparent size, moved by l (1/f - 1/d) from its pinhole position
// (thin_lens_camera.h): over the lens disk of radius R the hits spread over a disk of radius
// rho = R |1/f - 1/d| (tangent units; times the pixels per tangent unit), convolved with the
// square's image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "candela/camera/camera_frame.h"
#include "candela/render/renderer.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kSize = 48;
constexpr float kFov = 30.0f;
constexpr float kFocus = 4.0f;
constexpr float kRadiance = 1.0f;

// Pixels per unit of tangent on the film (fov spans the height).
double pixels_per_tangent() { return kSize / (2.0 * std::tan(0.5 * double(radians(kFov)))); }

// A camera at the origin looking down -z (right = +x, up = +y) with a lens of radius `aperture`
// focused at kFocus, and a square of `side_pixels` apparent size centred on the pinhole ray of
// film position `centre` at depth `depth`, facing the camera, emitting kRadiance.
Scene square_in_the_dark(Vec2f centre, float depth, float side_pixels, float aperture, int spp) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.0f))};
    s.material_names = {"black"};
    test::set_camera(s, Vec3f(0, 0, 0), Vec3f(0, 0, -1), kFov, kSize, kSize);
    s.camera.aperture_radius = aperture;
    s.camera.focus_distance = kFocus;
    const Vec2f tangent = FilmToScreen(s.camera, perspective_half_extents(s.camera))(centre);
    const float side = side_pixels / float(pixels_per_tangent()) * depth;
    const Vec3f middle(tangent.x * depth, tangent.y * depth, -depth);
    // Edges along +x and +y: cross(e1, e2) = +z, towards the camera.
    const uint32_t square = test::add_quad(s, middle - Vec3f(0.5f * side, 0.5f * side, 0.0f), Vec3f(side, 0, 0),
                                           Vec3f(0, side, 0), 0);
    test::set_emission(s, square, Rgb(kRadiance));
    s.integrator.max_depth = 1;
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.spp = spp;
    s.sampler.seed = 11;
    s.film.filter = FilterType::kBox;
    return s;
}

// The hits of each pixel: value * spp / L, which must be a whole number (each sample adds L or 0).
std::vector<double> hit_counts(const RenderResult& result, int spp) {
    EXPECT_EQ(result.stats.dropped_samples, 0u);
    std::vector<double> hits;
    for (const Rgb& p : result.image.pixels) {
        const double h = double(p.r) * spp / double(kRadiance);
        EXPECT_NEAR(h, std::round(h), 1e-3);
        EXPECT_EQ(p.r, p.g);
        EXPECT_EQ(p.r, p.b);
        hits.push_back(std::round(h));
    }
    return hits;
}

TEST(ThinLensRender, SquareInTheFocusPlaneLandsInOnePixel) {
    // Half a pixel wide, centred on pixel (30, 12): every lens point sees it there.
    constexpr int kSpp = 256;
    const Scene scene = square_in_the_dark({30.5f, 12.5f}, kFocus, 0.5f, 0.6f, kSpp);
    const std::vector<double> hits = hit_counts(render(scene, {.threads = 2}), kSpp);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (x != 30 || y != 12) {
                EXPECT_EQ(hits[size_t(y * kSize + x)], 0.0) << "pixel " << x << ", " << y;
            }
        }
    }
    // It covers a quarter of the pixel: hits ~ Binomial(spp, 1/4).
    const double expected = 0.25 * kSpp, sigma = std::sqrt(kSpp * 0.25 * 0.75);
    EXPECT_NEAR(hits[size_t(12 * kSize + 30)], expected, 4.0 * sigma);
}

TEST(ThinLensRender, SquareOffTheFocusPlaneBlursOverTheThinLensCircle) {
    // At depth 2 with focus 4 and R = 0.6: rho = 0.6 (1/2 - 1/4) tangent units, 13.4 pixels.
    constexpr int kSpp = 512;
    constexpr float kDepth = 2.0f, kAperture = 0.6f, kSide = 3.0f;  // the square: 3 x 3 pixels
    const Vec2f centre(24.0f, 24.0f);
    const double rho = double(kAperture) * (1.0 / double(kDepth) - 1.0 / double(kFocus)) * pixels_per_tangent();
    const Scene scene = square_in_the_dark(centre, kDepth, kSide, kAperture, kSpp);
    const std::vector<double> hits = hit_counts(render(scene, {.threads = 2}), kSpp);

    double n = 0.0, sum_r2 = 0.0, sum_r4 = 0.0, farthest = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const double h = hits[size_t(y * kSize + x)];
            if (h == 0.0) continue;
            const double dx = x + 0.5 - double(centre.x), dy = y + 0.5 - double(centre.y), r2 = dx * dx + dy * dy;
            n += h;
            sum_r2 += h * r2;
            sum_r4 += h * r2 * r2;
            farthest = std::max(farthest, std::sqrt(r2));
        }
    }
    // Support: no hit beyond the circle grown by the square's half diagonal and a pixel's; and
    // hits reach the circle's rim less those.
    const double margin = 0.5 * std::sqrt(2.0) * (double(kSide) + 1.0);
    EXPECT_LE(farthest, rho + margin);
    EXPECT_GE(farthest, rho - margin);
    // Energy: every lens point sees the whole square, so the hits over the image are those of a
    // pinhole: spp x (its area in pixels), a sum of many rare Bernoulli hits (Poisson variance).
    const double expected_hits = kSpp * double(kSide) * double(kSide);
    EXPECT_NEAR(n, expected_hits, 4.0 * std::sqrt(expected_hits));
    // Spread: the second moment about the centre of the pixel centres that were hit is the disk's
    // rho^2 / 2, plus the square's side^2 / 6, plus the pixel grid's 2 x 1/12 (Sheppard's
    // correction; 0.01 off here, by a 2e8-sample simulation, far below the bound). Its standard
    // error comes from the hits' own spread of r^2.
    const double m2 = sum_r2 / n;
    const double var_r2 = (sum_r4 / n - m2 * m2) * n / (n - 1.0);
    const double predicted = rho * rho / 2.0 + double(kSide * kSide) / 6.0 + 2.0 / 12.0;
    EXPECT_NEAR(m2, predicted, 4.0 * std::sqrt(var_r2 / n)) << "rho " << rho << ", measured radius "
                                                          << std::sqrt(2.0 * (m2 - predicted + rho * rho / 2.0));
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb)) == 0;
}

// The lit box (light, mirror, indirect light) seen through a lens, perspective or orthographic.
Scene lens_box(CameraType type, SamplerType sampler) {
    Scene s = test::lit_small_box_scene(37, 23, 12);
    s.sampler.type = sampler;
    s.camera.type = type;
    s.camera.ortho_height = 2.5f;
    s.camera.aperture_radius = 0.15f;
    s.camera.focus_distance = 3.5f;
    return s;
}

TEST(ThinLensRender, LensImagesAreDeterministicAndResumable) {
    for (CameraType type : {CameraType::kPerspective, CameraType::kOrthographic}) {
        for (SamplerType sampler : {SamplerType::kIndependent, SamplerType::kSobol}) {
            SCOPED_TRACE(std::string(type == CameraType::kPerspective ? "perspective" : "orthographic") +
                         (sampler == SamplerType::kSobol ? " sobol" : " independent"));
            const Scene scene = lens_box(type, sampler);
            const RenderResult one = render(scene, {.threads = 1, .tile_size = 16});
            EXPECT_TRUE(same_bits(one.image, render(scene, {.threads = 2, .tile_size = 5}).image));
            // Stopped after 2 passes of 3 samples, resumed with another thread count.
            int passes = 0;
            RenderOptions first{.threads = 2};
            first.pass_spp = 3;
            first.on_pass = [&passes](const RenderState&) { ++passes; };
            first.stop = [&passes] { return passes >= 2; };
            RenderResult part = render(scene, first);
            ASSERT_EQ(part.state.samples_done, 6u);
            RenderResult rest = render(scene, {.threads = 3}, std::move(part.state));
            EXPECT_TRUE(same_bits(rest.image, one.image));
            // render_moments replays the renderer's loop, the lens included.
            EXPECT_TRUE(same_bits(test::render_moments(scene, /*for_variance=*/false).image(), one.image));
            // The lens is used: without it the image differs.
            Scene pinhole = scene;
            pinhole.camera.aperture_radius = 0.0f;
            EXPECT_FALSE(same_bits(render(pinhole, {.threads = 2}).image, one.image));
        }
    }
}

}  // namespace
}  // namespace candela
