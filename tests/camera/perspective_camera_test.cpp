// The camera conventions of DESIGN.md: vertical fov, right-handed, image x right, y down.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/camera/perspective_camera.h"

namespace candela {
namespace CANDELA_UNITY_ID {

CameraSettings looking_down_minus_z(int w, int h, float fov) {
    CameraSettings s;
    s.position = {1, 2, 3};
    s.look_at = {1, 2, -10};
    s.up = {0, 1, 0};
    s.fov_degrees = fov;
    s.width = w;
    s.height = h;
    return s;
}

TEST(PerspectiveCamera, CentreRayLooksAtTarget) {
    PerspectiveCamera cam(looking_down_minus_z(64, 32, 60));
    Ray r = cam.generate_ray({32, 16});
    EXPECT_NEAR(r.d.x, 0.0f, 1e-6f);
    EXPECT_NEAR(r.d.y, 0.0f, 1e-6f);
    EXPECT_NEAR(r.d.z, -1.0f, 1e-6f);
    EXPECT_EQ(r.o, Vec3f(1, 2, 3));
}

TEST(PerspectiveCamera, FovIsVerticalAndImageYPointsDown) {
    // Top edge centre: 30 degrees above the axis for a 60 degree vertical fov.
    PerspectiveCamera cam(looking_down_minus_z(200, 100, 60));
    Ray top = cam.generate_ray({100, 0});
    EXPECT_NEAR(std::atan2(top.d.y, -top.d.z), radians(30.0f), 1e-5f);
    Ray bottom = cam.generate_ray({100, 100});
    EXPECT_NEAR(std::atan2(bottom.d.y, -bottom.d.z), -radians(30.0f), 1e-5f);
    // Horizontal extent follows the 2:1 aspect: tan(half width) = 2 tan(30).
    Ray right = cam.generate_ray({200, 50});
    EXPECT_NEAR(right.d.x / -right.d.z, 2.0f * std::tan(radians(30.0f)), 1e-5f);
}

TEST(PerspectiveCamera, ImageRightIsCrossOfForwardAndUp) {
    // Looking along +z with +y up, right = cross(+z, +y) = -x (the Cornell box's camera).
    CameraSettings s = looking_down_minus_z(16, 16, 40);
    s.look_at = {1, 2, 10};
    PerspectiveCamera cam(s);
    Ray r = cam.generate_ray({16, 8});  // right edge, middle row
    EXPECT_LT(r.d.x, 0.0f);
    EXPECT_NEAR(r.d.y, 0.0f, 1e-6f);
}

TEST(PerspectiveCamera, NearMovesTheOriginAlongTheRay) {
    CameraSettings s = looking_down_minus_z(16, 16, 40);
    s.near = 140.0f;
    PerspectiveCamera cam(s);
    Ray r = cam.generate_ray({3.5f, 12.25f});
    Vec3f expected = Vec3f(1, 2, 3) + r.d * 140.0f;
    EXPECT_NEAR(length(r.o - expected), 0.0f, 1e-4f);
    EXPECT_NEAR(length(r.d), 1.0f, 1e-6f);
}

// The half angle of the ray through film position `film`, measured from the view axis in the
// plane of the axis and that position (looking down -z).
float half_angle(const PerspectiveCamera& cam, Vec2f film) {
    Ray r = cam.generate_ray(film);
    return std::atan2(std::sqrt(r.d.x * r.d.x + r.d.y * r.d.y), -r.d.z);
}

// fov_axis (Mitsuba 3's): which extent of the image fov spans, for a wide and a tall image.
TEST(PerspectiveCamera, FovAxisPicksTheExtentTheFovSpans) {
    const float half = radians(30.0f);  // fov 60
    struct Case {
        FovAxis axis;
        int w, h;
        Vec2f edge;  // the film position at the middle of the spanned edge, or a corner
    };
    const Case cases[] = {
        {FovAxis::kY, 200, 100, {100, 0}},       {FovAxis::kY, 100, 200, {50, 0}},
        {FovAxis::kX, 200, 100, {200, 50}},      {FovAxis::kX, 100, 200, {100, 100}},
        {FovAxis::kSmaller, 200, 100, {100, 0}}, {FovAxis::kSmaller, 100, 200, {100, 100}},
        {FovAxis::kLarger, 200, 100, {200, 50}}, {FovAxis::kLarger, 100, 200, {50, 0}},
        {FovAxis::kDiagonal, 200, 100, {200, 0}}, {FovAxis::kDiagonal, 100, 200, {0, 200}},
        {FovAxis::kSmaller, 64, 64, {64, 32}},   {FovAxis::kLarger, 64, 64, {32, 0}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(int(c.axis)) + " " + std::to_string(c.w) + "x" + std::to_string(c.h));
        CameraSettings s = looking_down_minus_z(c.w, c.h, 60);
        s.fov_axis = c.axis;
        PerspectiveCamera cam(s);
        EXPECT_NEAR(half_angle(cam, c.edge), half, 1e-5f);
        // Square pixels: the other extent follows the aspect ratio, tangents in proportion.
        const float tan_x = std::tan(half_angle(cam, {float(c.w), 0.5f * float(c.h)}));
        const float tan_y = std::tan(half_angle(cam, {0.5f * float(c.w), 0.0f}));
        EXPECT_NEAR(tan_x / tan_y, float(c.w) / float(c.h), 1e-5f);
    }
}

// fov_axis y is version 1's camera, to the bit: the same rays, so the same images.
TEST(PerspectiveCamera, FovAxisYIsTheDefaultAndVersion1sRays) {
    CameraSettings s = looking_down_minus_z(37, 23, 41);
    EXPECT_EQ(s.fov_axis, FovAxis::kY);
    PerspectiveCamera cam(s);
    const float half_height = std::tan(0.5f * radians(41.0f));
    const float half_width = half_height * 37.0f / 23.0f;
    const Vec3f forward = normalize(s.look_at - s.position), right = normalize(cross(forward, s.up));
    const Vec3f up = cross(right, forward);
    for (Vec2f film : {Vec2f(0, 0), Vec2f(3.25f, 17.5f), Vec2f(36.9f, 22.1f)}) {
        float sx = (2.0f * film.x * (1.0f / 37.0f) - 1.0f) * half_width;
        float sy = (1.0f - 2.0f * film.y * (1.0f / 23.0f)) * half_height;
        EXPECT_EQ(cam.generate_ray(film).d, normalize(forward + right * sx + up * sy));
    }
}

}  // namespace
}  // namespace candela
