// The camera conventions of DESIGN.md: vertical fov, right-handed, image x right, y down.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/camera/perspective_camera.h"

namespace candela {
namespace {

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

}  // namespace
}  // namespace candela
