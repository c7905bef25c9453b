// The thin lens (thin_lens_camera.h): the focus plane is sharp, and a point off it blurs into a
// disk of the thin-lens diameter. Measured through generate_ray only, by finding for each lens
// point the film position that sees a given scene point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "camera/camera_test_util.h"
#include "candela/camera/camera.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kWidth = 160, kHeight = 120;
constexpr float kFov = 50.0f, kAperture = 0.2f, kFocus = 6.0f;

// A camera in general position (no axis-aligned frame) with a lens.
CameraSettings lens_settings() {
    CameraSettings s;
    s.position = {1, 2, 3};
    s.look_at = {4, 1, -5};
    s.up = {0, 1, 0};
    s.fov_degrees = kFov;
    s.width = kWidth;
    s.height = kHeight;
    s.aperture_radius = kAperture;
    s.focus_distance = kFocus;
    return s;
}

// Lens samples on an n x n grid over [0, 1]^2, edges included (they map to the lens's rim).
template <class F>
void for_lens_grid(int n, F&& f) {
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) f(Vec2f(float(i) / float(n - 1), float(j) / float(n - 1)), i == 0 || j == 0 || i == n - 1 || j == n - 1);
}

// The scene point the pinhole ray of `film` reaches at `depth` along the view.
Vec3d pinhole_point(const CameraSettings& s, Vec2f film, double depth) {
    const CameraFrame frame(s);
    return test::hit_at_depth(PerspectiveCamera(s).generate_ray(film), frame, depth);
}

TEST(ThinLensCamera, MakeCameraChoosesItForAnAperture) {
    CameraSettings s = lens_settings();
    EXPECT_TRUE(holds_alternative<ThinLensCamera>(make_camera(s)));
    s.aperture_radius = 0.0f;
    EXPECT_TRUE(holds_alternative<PerspectiveCamera>(make_camera(s)));
}

TEST(ThinLensCamera, RaysOfOneFilmPositionMeetInTheFocusPlane) {
    const CameraSettings s = lens_settings();
    const ThinLensCamera camera(s);
    const CameraFrame frame(s);
    for (Vec2f film : {Vec2f(80, 60), Vec2f(0.25f, 3.5f), Vec2f(159.5f, 119.75f), Vec2f(12, 101)}) {
        const Vec3d expected = pinhole_point(s, film, double(kFocus));
        double worst = 0.0;
        for_lens_grid(17, [&](Vec2f u, bool) {
            const Ray r = camera.generate_ray(film, u);
            EXPECT_NEAR(length(Vec3d(r.d)), 1.0, 1e-6);
            worst = std::max(worst, length(test::hit_at_depth(r, frame, double(kFocus)) - expected));
        });
        // Float rays from points ~10 units from the origin: a few ulps of that.
        EXPECT_LT(worst, 1e-5) << "film " << film.x << ", " << film.y;
    }
}

TEST(ThinLensCamera, PointInTheFocusPlaneMapsToOneFilmPosition) {
    const CameraSettings s = lens_settings();
    const ThinLensCamera camera(s);
    const CameraFrame frame(s);
    const Vec2f film(37.3f, 88.6f);
    const Vec3d p = pinhole_point(s, film, double(kFocus));
    for_lens_grid(17, [&](Vec2f u, bool) {
        const Vec2f seen = test::film_position_seeing(camera, frame, p, u, kWidth, kHeight);
        EXPECT_NEAR(seen.x, film.x, 1e-3f);
        EXPECT_NEAR(seen.y, film.y, 1e-3f);
    });
}

// A point at depth d seen through lens point l lands at film offset l (1/f - 1/d) (tangent units)
// from its pinhole position: the rays from the lens disk through the point cross the focus plane
// in a disk of radius R |d - f| / d, which the film sees at angular radius R |d - f| / (d f).
TEST(ThinLensCamera, BlurCircleHasTheThinLensDiameter) {
    const CameraSettings s = lens_settings();
    const ThinLensCamera camera(s);
    const CameraFrame frame(s);
    const double pixels_per_tangent = kHeight / (2.0 * std::tan(0.5 * double(radians(kFov))));
    for (double depth : {2.0, 4.5, 9.0, 40.0}) {
        SCOPED_TRACE("depth " + std::to_string(depth));
        const Vec2f centre(101.5f, 40.25f);
        const Vec3d p = pinhole_point(s, centre, depth);
        const double radius = double(kAperture) * std::abs(depth - double(kFocus)) / (depth * double(kFocus)) * pixels_per_tangent;
        double largest = 0.0, smallest_on_rim = 1e30;
        for_lens_grid(33, [&](Vec2f u, bool on_rim) {
            const Vec2f seen = test::film_position_seeing(camera, frame, p, u, kWidth, kHeight);
            // The film position found must see p (film_position_seeing's affine model holds).
            const Vec3d q = test::hit_at_depth(camera.generate_ray(seen, u), frame, depth);
            EXPECT_LT(length(q - p), 1e-4 * depth);
            const double r = length(Vec3d(double(seen.x - centre.x), double(seen.y - centre.y), 0.0));
            largest = std::max(largest, r);
            if (on_rim) smallest_on_rim = std::min(smallest_on_rim, r);
        });
        // The lens's rim (the grid's edge, by the concentric map) lands on the circle itself.
        EXPECT_NEAR(largest, radius, 1e-3 * radius + 1e-3);
        EXPECT_NEAR(smallest_on_rim, radius, 1e-3 * radius + 1e-3);
    }
}

TEST(ThinLensCamera, DefaultFocusIsTheDistanceToLookAt) {
    CameraSettings s = lens_settings();
    s.focus_distance = 0.0f;  // the loader's default: not given
    const ThinLensCamera camera(s);
    EXPECT_FLOAT_EQ(camera.focus_distance(), length(s.look_at - s.position));
    // So look_at itself is sharp: it maps to the image centre through every lens point.
    const CameraFrame frame(s);
    for_lens_grid(5, [&](Vec2f u, bool) {
        const Vec2f seen = test::film_position_seeing(camera, frame, Vec3d(s.look_at), u, kWidth, kHeight);
        EXPECT_NEAR(seen.x, 0.5f * kWidth, 1e-3f);
        EXPECT_NEAR(seen.y, 0.5f * kHeight, 1e-3f);
    });
}

TEST(ThinLensCamera, RaysLeaveTheLensDisk) {
    const CameraSettings s = lens_settings();
    const ThinLensCamera camera(s);
    const CameraFrame frame(s);
    float largest = 0.0f;
    for_lens_grid(9, [&](Vec2f u, bool) {
        const Vec3f offset = camera.generate_ray({10, 20}, u).o - s.position;
        EXPECT_NEAR(dot(offset, frame.forward), 0.0f, 2e-6f);  // on the lens plane
        largest = std::max(largest, length(offset));
    });
    EXPECT_NEAR(largest, kAperture, 2e-6f);
    // The lens centre gives the pinhole ray.
    const Ray centre = camera.generate_ray({10, 20}, Vec2f(0.5f, 0.5f));
    const Ray pinhole = PerspectiveCamera(s).generate_ray({10, 20});
    EXPECT_EQ(centre.o, pinhole.o);
    EXPECT_NEAR(length(centre.d - pinhole.d), 0.0f, 1e-6f);
}

TEST(ThinLensCamera, NearMovesTheOriginAlongTheRay) {
    CameraSettings s = lens_settings();
    const Ray without = ThinLensCamera(s).generate_ray({3, 4}, Vec2f(0.2f, 0.9f));
    s.near = 2.5f;
    const Ray with = ThinLensCamera(s).generate_ray({3, 4}, Vec2f(0.2f, 0.9f));
    EXPECT_EQ(with.d, without.d);
    EXPECT_NEAR(length(with.o - (without.o + without.d * 2.5f)), 0.0f, 1e-5f);
}

// The sampler order (sampling/sampler.h): the lens point is one 2D request; a pinhole asks none.
TEST(ThinLensCamera, LensPointIsOneSamplerRequestAndPinholeTakesNone) {
    for (SamplerType type : {SamplerType::kIndependent, SamplerType::kSobol}) {
        const CameraSettings s = lens_settings();
        Sampler used(type, 17, 3, 5), reference(type, 17, 3, 5);
        const Ray r = ThinLensCamera(s).generate_ray({50, 50}, used);
        const Ray expected = ThinLensCamera(s).generate_ray({50, 50}, reference.next_vec2f());
        EXPECT_EQ(r.o, expected.o);
        EXPECT_EQ(r.d, expected.d);
        EXPECT_EQ(used.next_float(), reference.next_float());  // both moved on by one request

        CameraSettings pinhole = s;
        pinhole.aperture_radius = 0.0f;
        Sampler untouched(type, 17, 3, 5), fresh(type, 17, 3, 5);
        const Ray p = PerspectiveCamera(pinhole).generate_ray({50, 50}, untouched);
        EXPECT_EQ(p.d, PerspectiveCamera(pinhole).generate_ray({50, 50}).d);
        EXPECT_EQ(untouched.next_float(), fresh.next_float());
    }
}

}  // namespace
}  // namespace candela
