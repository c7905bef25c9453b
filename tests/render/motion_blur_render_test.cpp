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
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "candela/camera/camera_frame.h"
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

}  // namespace
}  // namespace candela
