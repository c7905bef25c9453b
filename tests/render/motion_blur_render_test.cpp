// Motion blur through the whole renderer: a camera that pans during the shutter sees, in each
// pixel, the time average of what the still camera sees along the way.
//
// The scene is an emitting half plane (x < 0 on the plane z = -1, facing the camera) in the dark.
// The camera sits at the origin and turns about +y from yaw -phi to +phi (yaw: the view
// direction's angle from -z towards +x). A ray at horizontal tangent tx in the camera's image
// has yaw psi(t) + atan(tx) and sees the plane's lit half exactly when that is negative. With
// pbrt-v4's interpolation psi(t) = -phi + 2 phi t (slerp: the angle is linear in time), so over a
// uniform shutter time the ray sees light for the fraction f(tx) = (phi - atan(tx)) / (2 phi), and
// the pixel's value is f averaged over the tangents its box filter covers. A blend of the two
// frames' matrices turns the camera at a varying rate and misses this by up to several percent.
//
// Moving shapes (geometry/instance_motion.h): a still camera sees a black quad slide across an
// emitting background; each pixel's value is 1 minus the fraction of the shutter (and of the
// pixel) the quad covers it, the same closed form for a moving quad and a moving instance of it.
// The controls: the moving render against the still quad's closed form, and the still quad's
// render against the moving closed form, each fail on more than 8 of the 128 pixels (asserted).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "candela/camera/camera_frame.h"
#include "candela/formats/json/scene_loader.h"
#include "candela/render/renderer.h"
#include "support/render_moments.h"
#include "support/test_scenes.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kWidth = 32, kHeight = 4;
constexpr double kHalfFovX = 20.0;  // degrees
constexpr double kPhi = 60.0;       // degrees: the camera turns from -kPhi to +kPhi

Vec3f view_at_yaw(double degrees) {
    const double a = degrees * kPiD / 180.0;
    return Vec3f(float(std::sin(a)), 0.0f, float(-std::cos(a)));
}

Scene panning_camera_scene(int spp, std::array<double, 2> shutter) {
    Scene s;
    s.materials = {make_diffuse(Rgb(0.0f))};
    s.material_names = {"black"};
    test::set_camera(s, Vec3f(0, 0, 0), view_at_yaw(-kPhi), float(2.0 * kHalfFovX), kWidth, kHeight);
    s.camera.fov_axis = FovAxis::kX;
    CameraSettings end = s.camera;
    end.look_at = view_at_yaw(kPhi);
    const CameraFrame f(end);
    s.camera.motion = CameraMotion{CameraBasis{f.position, f.right, f.up, f.forward}, 0.0, 1.0};
    s.camera.shutter = shutter;
    const uint32_t half_plane = test::add_quad(s, Vec3f(-1000, -1000, -1), Vec3f(1000, 0, 0), Vec3f(0, 2000, 0), 0);
    test::set_emission(s, half_plane, Rgb(1.0f));
    s.integrator.max_depth = 1;
    s.sampler.type = SamplerType::kIndependent;
    s.sampler.spp = spp;
    s.sampler.seed = 5;
    s.film.filter = FilterType::kBox;
    return s;
}

// The lit fraction of pixel column x over shutter times [t0, t1] of the [0, 1] motion: psi(t) < -atan(tx)
// for t < t* = (phi - atan(tx)) / (2 phi), averaged over the pixel's tangents (Simpson's rule).
double expected_fraction(int x, double t0, double t1) {
    const double tan_half = std::tan(kHalfFovX * kPiD / 180.0), phi = kPhi * kPiD / 180.0;
    auto f = [&](double film_x) {
        const double tx = (2.0 * film_x / kWidth - 1.0) * tan_half;
        const double t_star = (phi - std::atan(tx)) / (2.0 * phi);
        return std::clamp((t_star - t0) / (t1 - t0), 0.0, 1.0);
    };
    constexpr int n = 1000;
    double sum = f(x) + f(x + 1.0);
    for (int i = 1; i < n; ++i) sum += f(x + double(i) / n) * (i % 2 ? 4.0 : 2.0);
    return sum / (3.0 * n);
}

// How many pixels fail a z-test at family-wise level 0.01 (Sidak over the pixels) against `expected`.
int failing_pixels(const test::RenderMoments& m, double t0, double t1) {
    const double z = test::sidak_critical_z(0.01, long(kWidth) * kHeight);
    int failing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double e = expected_fraction(x, t0, t1);
            // The variance of a mean of Bernoulli(e) samples: from the expectation, not the sample,
            // so a pixel whose samples all agree is tested too.
            const double sd = std::sqrt(std::max(e * (1.0 - e), 1e-12) / double(m.spp));
            if (std::abs(m.mean(x, y, 0) - e) > z * sd) ++failing;
        }
    return failing;
}

TEST(MotionBlurRender, PanningCameraAveragesOverTheShutter) {
    const test::RenderMoments m = test::render_moments(panning_camera_scene(4096, {0.0, 1.0}));
    EXPECT_EQ(failing_pixels(m, 0.0, 1.0), 0);
    // The control: the same image is not the average over half the shutter.
    EXPECT_GT(failing_pixels(m, 0.0, 0.5), kWidth * kHeight / 2);
}

TEST(MotionBlurRender, ShutterChoosesTheTimes) {
    // Shutter [0.25, 0.75] of the motion's [0, 1]: the fraction is of that window only.
    const test::RenderMoments m = test::render_moments(panning_camera_scene(4096, {0.25, 0.75}));
    EXPECT_EQ(failing_pixels(m, 0.25, 0.75), 0);
    EXPECT_GT(failing_pixels(m, 0.0, 1.0), kWidth * kHeight / 4);
}

TEST(MotionBlurRender, SameBitsForAnyThreadCount) {
    Scene s = panning_camera_scene(64, {0.0, 1.0});
    s.sampler.type = SamplerType::kSobol;
    const Image one = render(s, {.threads = 1}).image;
    const Image two = render(s, {.threads = 2}).image;
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(Rgb)), 0);
}

// The sliding quad: an orthographic camera (image x in [-4, 4] over 32 pixels, 4 rows) sees an
// emitting background at z = -1 and a black quad of width 2 at z = -0.5, its centre moving from
// x = -2 to x = +2 over the shutter [0, 1] (or standing at -2: the control). `form`: how the motion
// is written (a moving quad, a moving instance of an object holding the quad).
enum class SlideForm { kShape, kInstance, kStill };

Scene sliding_quad_scene(SlideForm form, int spp) {
    const std::string quad =
        R"("type": "quad", "corner": [-1, -10, -0.5], "edge1": [2, 0, 0], "edge2": [0, 20, 0], "material": "black")";
    const std::string start = R"("transform": [{"translate": [-2, 0, 0]}])";
    const std::string motion = R"("motion": {"transform": [{"translate": [2, 0, 0]}]})";
    std::string objects, moving;
    switch (form) {
        case SlideForm::kShape: moving = fmt::format("{{{}, {}, {}}}", quad, start, motion); break;
        case SlideForm::kInstance:
            objects = fmt::format(R"("objects": {{"slider": {{"shapes": [{{{}}}]}}}},)", quad);
            moving = fmt::format(R"({{"type": "instance", "object": "slider", {}, {}}})", start, motion);
            break;
        case SlideForm::kStill: moving = fmt::format("{{{}, {}}}", quad, start); break;
    }
    const std::string json = fmt::format(R"({{
        "integrator": {{"type": "path", "max_depth": 1}},
        "sampler": {{"type": "independent", "spp": {}, "seed": 9}},
        "camera": {{"type": "orthographic", "position": [0, 0, 1], "look_at": [0, 0, 0], "up": [0, 1, 0],
                    "height": 1, "resolution": [32, 4]}},
        "film": {{"filter": "box"}},
        "materials": {{"black": {{"type": "diffuse", "albedo": 0}}}},
        {}
        "shapes": [
            {{"type": "quad", "corner": [-10, -10, -1], "edge1": [20, 0, 0], "edge2": [0, 20, 0],
              "material": "black", "emission": 1}},
            {}
        ]}})",
                                         spp, objects, moving);
    return load_scene_from_string(json, "sliding_quad.json");
}

// The background's share of pixel column x: at image x_w = -4 + film_x / 4 the quad covers the
// point for t in [(x_w + 1) / 4, (x_w + 3) / 4] of [0, 1] (still: never when x_w > -1), averaged
// over the pixel (Simpson's rule).
double expected_background(int x, bool moving) {
    auto covered = [&](double film_x) {
        const double xw = -4.0 + film_x / 4.0;
        if (!moving) return xw >= -3.0 && xw <= -1.0 ? 1.0 : 0.0;
        return std::clamp((xw + 3.0) / 4.0, 0.0, 1.0) - std::clamp((xw + 1.0) / 4.0, 0.0, 1.0);
    };
    constexpr int n = 1000;
    double sum = covered(x) + covered(x + 1.0);
    for (int i = 1; i < n; ++i) sum += covered(x + double(i) / n) * (i % 2 ? 4.0 : 2.0);
    return 1.0 - sum / (3.0 * n);
}

// Pixels that fail the z-test (family-wise 0.01, Sidak) against the sliding quad's closed form.
int failing_slide_pixels(const test::RenderMoments& m, bool moving) {
    const double z = test::sidak_critical_z(0.01, long(kWidth) * kHeight);
    int failing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double e = expected_background(x, moving);
            const double sd = std::sqrt(std::max(e * (1.0 - e), 1e-12) / double(m.spp));
            if (std::abs(m.mean(x, y, 0) - e) > z * sd) ++failing;
        }
    return failing;
}

TEST(MotionBlurRender, MovingShapeCoversEachPixelForItsShareOfTheShutter) {
    const test::RenderMoments m = test::render_moments(sliding_quad_scene(SlideForm::kShape, 4096));
    EXPECT_EQ(failing_slide_pixels(m, true), 0);
    // The control: the quad where it starts. Its own render fits the still closed form, and the
    // moving render does not.
    EXPECT_GT(failing_slide_pixels(m, false), 8);
    const test::RenderMoments still = test::render_moments(sliding_quad_scene(SlideForm::kStill, 1024));
    EXPECT_EQ(failing_slide_pixels(still, false), 0);
    EXPECT_GT(failing_slide_pixels(still, true), 8);
}

TEST(MotionBlurRender, MovingInstanceCoversEachPixelForItsShareOfTheShutter) {
    const test::RenderMoments m = test::render_moments(sliding_quad_scene(SlideForm::kInstance, 4096));
    EXPECT_EQ(failing_slide_pixels(m, true), 0);
    EXPECT_GT(failing_slide_pixels(m, false), 8);
}

TEST(MotionBlurRender, MovingShapesGiveTheSameBitsForAnyThreadCount) {
    Scene s = sliding_quad_scene(SlideForm::kShape, 64);
    s.sampler.type = SamplerType::kSobol;
    const Image one = render(s, {.threads = 1}).image;
    const Image two = render(s, {.threads = 2}).image;
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(Rgb)), 0);
}

}  // namespace
}  // namespace candela
