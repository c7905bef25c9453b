// The orthographic camera (orthographic_camera.h): parallel rays from a film `height` scene units
// high, and its optional thin lens.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "camera/camera_test_util.h"
#include "candela/camera/camera.h"

namespace candela {
namespace CANDELA_UNITY_ID {

constexpr int kWidth = 120, kHeight = 80;
constexpr float kFilmHeight = 3.0f;

CameraSettings ortho_settings() {
    CameraSettings s;
    s.type = CameraType::kOrthographic;
    s.position = {1, 2, 3};
    s.look_at = {-2, 0, -4};
    s.up = {0, 1, 0};
    s.ortho_height = kFilmHeight;
    s.width = kWidth;
    s.height = kHeight;
    return s;
}

TEST(OrthographicCamera, MakeCameraChoosesItForItsType) {
    CameraSettings s = ortho_settings();
    EXPECT_TRUE(holds_alternative<OrthographicCamera>(make_camera(s)));
    s.aperture_radius = 0.1f;  // with a lens it is still the orthographic camera
    EXPECT_TRUE(holds_alternative<OrthographicCamera>(make_camera(s)));
}

TEST(OrthographicCamera, OriginsSpanTheFilmAndDirectionsAreAllTheViewDirection) {
    const CameraSettings s = ortho_settings();
    const OrthographicCamera camera(s);
    const CameraFrame frame(s);
    Sampler sampler(SamplerType::kIndependent, 0, 0, 0);
    const Ray top_left = camera.generate_ray({0, 0}, sampler);
    const Ray bottom_right = camera.generate_ray({float(kWidth), float(kHeight)}, sampler);
    const Ray centre = camera.generate_ray({0.5f * kWidth, 0.5f * kHeight}, sampler);
    for (const Ray& r : {top_left, bottom_right, centre, camera.generate_ray({17.25f, 63.5f}, sampler)})
        EXPECT_EQ(r.d, frame.forward);
    EXPECT_NEAR(length(centre.o - s.position), 0.0f, 1e-6f);
    // Height in scene units along up; width by the aspect ratio along right; y down on the film.
    const Vec3f span = top_left.o - bottom_right.o;
    EXPECT_NEAR(dot(span, frame.up), kFilmHeight, 1e-5f);
    EXPECT_NEAR(dot(span, frame.right), -kFilmHeight * kWidth / kHeight, 1e-5f);
    EXPECT_NEAR(dot(span, frame.forward), 0.0f, 1e-5f);
    // Equal film steps are equal steps on the film plane.
    const Vec3f step = camera.generate_ray({1, 0}, sampler).o - camera.generate_ray({0, 0}, sampler).o;
    EXPECT_NEAR(length(step), kFilmHeight / kHeight, 1e-6f);
}

TEST(OrthographicCamera, WithoutALensTheSamplerIsNotAsked) {
    const OrthographicCamera camera(ortho_settings());
    Sampler used(SamplerType::kSobol, 3, 9, 1), fresh(SamplerType::kSobol, 3, 9, 1);
    camera.generate_ray({5, 5}, used);
    EXPECT_EQ(used.next_vec2f(), fresh.next_vec2f());
}

TEST(OrthographicCamera, NearMovesTheOriginAlongTheView) {
    CameraSettings s = ortho_settings();
    s.near = 4.0f;
    const Ray r = OrthographicCamera(s).generate_ray(Vec2f(7, 9));
    const Ray without = OrthographicCamera(ortho_settings()).generate_ray(Vec2f(7, 9));
    EXPECT_NEAR(length(r.o - (without.o + CameraFrame(s).forward * 4.0f)), 0.0f, 1e-5f);
}

// With a lens: the focus plane is sharp, and a point at depth d blurs into a disk of radius
// R |d - f| / f scene units on the film (parallel projection: the rays from the lens disk around
// a film point through the point cross the focus plane in that disk).
TEST(OrthographicCamera, ThinLensFocusesItsPlaneAndBlursTheRest) {
    constexpr float kAperture = 0.15f, kFocus = 5.0f;
    CameraSettings s = ortho_settings();
    s.aperture_radius = kAperture;
    s.focus_distance = kFocus;
    const OrthographicCamera camera(s);
    const CameraFrame frame(s);
    const Vec2f film(30.5f, 20.25f);
    const double pixels_per_unit = kHeight / double(kFilmHeight);
    Sampler one_request(SamplerType::kIndependent, 1, 2, 3), reference(SamplerType::kIndependent, 1, 2, 3);
    const Ray drawn = camera.generate_ray(film, one_request);
    EXPECT_EQ(drawn.d, camera.generate_ray(film, reference.next_vec2f()).d);
    EXPECT_EQ(one_request.next_float(), reference.next_float());

    for (double depth : {1.0, 5.0, 8.0}) {
        SCOPED_TRACE("depth " + std::to_string(depth));
        const Vec3d p = test::hit_at_depth(camera.generate_ray(film), frame, depth);
        const double radius = double(kAperture) * std::abs(depth - double(kFocus)) / double(kFocus) * pixels_per_unit;
        double largest = 0.0;
        for (int i = 0; i < 21; ++i) {
            for (int j = 0; j < 21; ++j) {
                const Vec2f u(float(i) / 20.0f, float(j) / 20.0f);
                const Vec2f seen = test::film_position_seeing(camera, frame, p, u, kWidth, kHeight);
                EXPECT_LT(length(test::hit_at_depth(camera.generate_ray(seen, u), frame, depth) - p), 1e-4);
                largest = std::max(largest, length(Vec3d(double(seen.x - film.x), double(seen.y - film.y), 0.0)));
            }
        }
        EXPECT_NEAR(largest, radius, 1e-3 * radius + 2e-3);
    }
}

}  // namespace
}  // namespace candela
