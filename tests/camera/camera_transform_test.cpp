// The camera frame given as a transform (CameraSettings::basis, pbrt-v4's camera space) and the
// screen window (pbrt-v4's screenwindow), for every camera kind.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/camera/camera.h"
#include "candela/camera/camera_frame.h"

namespace candela {
namespace CANDELA_UNITY_ID {

CameraSettings look_at_camera(CameraType type = CameraType::kPerspective, float aperture = 0.0f) {
    CameraSettings s;
    s.type = type;
    s.position = {1, 2, 3};
    s.look_at = {-2, 0.5f, -4};
    s.up = {0.1f, 1, 0.2f};
    s.fov_degrees = 50;
    s.width = 48;
    s.height = 32;
    s.ortho_height = 3;
    s.aperture_radius = aperture;
    s.focus_distance = 5;
    return s;
}

// The same camera, its frame given as a basis.
CameraSettings as_basis(const CameraSettings& s) {
    const CameraFrame f(s);
    CameraSettings b = s;
    b.position = {0, 0, 0};
    b.look_at = {0, 0, 1};  // ignored: nonsense on purpose
    b.up = {1, 0, 0};
    b.basis = CameraBasis{f.position, f.right, f.up, f.forward};
    return b;
}

// The camera's ray of `film`, with the same lens sample for every camera.
Ray ray_of(const Camera& camera, Vec2f film) {
    return visit(
        [&](const auto& c) {
            Sampler sampler(SamplerType::kIndependent, 7, 3, 11);
            return c.generate_ray(film, sampler);
        },
        camera);
}

void expect_near(Vec3f a, Vec3f b, float eps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

constexpr Vec2f kFilmPoints[] = {{0, 0}, {48, 32}, {10.5f, 3.25f}, {24, 16}, {47, 1}};

TEST(CameraTransform, BasisOfALookAtFrameGivesIdenticalRays) {
    for (CameraSettings s : {look_at_camera(), look_at_camera(CameraType::kPerspective, 0.2f),
                             look_at_camera(CameraType::kOrthographic), look_at_camera(CameraType::kOrthographic, 0.1f)}) {
        const Camera a = make_camera(s), b = make_camera(as_basis(s));
        for (Vec2f p : kFilmPoints) {
            const Ray ra = ray_of(a, p), rb = ray_of(b, p);
            EXPECT_EQ(ra.o, rb.o);
            EXPECT_EQ(ra.d, rb.d);
        }
    }
}

TEST(CameraTransform, MirroredBasisGivesMirroredRays) {
    // pbrt-v4's camera space is left-handed: its right axis is the negation of candela's
    // cross(forward, up). The image from a basis with right negated is the mirror image: the ray of
    // film x is the original's ray of width - x.
    for (CameraType type : {CameraType::kPerspective, CameraType::kOrthographic}) {
        const CameraSettings s = look_at_camera(type);
        CameraSettings m = as_basis(s);
        m.basis->right = -m.basis->right;
        const Camera a = make_camera(s), b = make_camera(m);
        for (Vec2f p : kFilmPoints) {
            const Ray ra = ray_of(a, {48.0f - p.x, p.y}), rb = ray_of(b, p);
            expect_near(ra.o, rb.o, 1e-5f);
            expect_near(ra.d, rb.d, 1e-6f);
        }
    }
}

TEST(CameraTransform, FocusDistanceDefaultsToPbrtsWithABasis) {
    CameraSettings s = as_basis(look_at_camera(CameraType::kPerspective, 0.2f));
    s.focus_distance = 0.0f;
    EXPECT_EQ(resolved_focus_distance(s), 1e6f);
    EXPECT_EQ(resolved_focus_distance(look_at_camera()), 5.0f);
}

TEST(ScreenWindow, PbrtsDefaultWindowIsFovAxisSmaller) {
    // pbrt-v4: the shorter axis spans [-1, 1], the longer the aspect ratio, in units of tan(fov/2).
    for (auto [w, h] : {std::pair{48, 32}, std::pair{20, 50}}) {
        CameraSettings s = look_at_camera();
        s.width = w;
        s.height = h;
        s.fov_axis = FovAxis::kSmaller;
        CameraSettings windowed = s;
        const float a = float(w) / float(h);
        windowed.screen_window = w > h ? std::array<float, 4>{-a, a, -1, 1} : std::array<float, 4>{-1, 1, -1 / a, 1 / a};
        const Camera c = make_camera(s), cw = make_camera(windowed);
        for (Vec2f p : kFilmPoints) expect_near(ray_of(c, p).d, ray_of(cw, p).d, 1e-6f);
    }
}

TEST(ScreenWindow, HalfTheWindowOnHalfTheFilmIsHalfTheImage) {
    // The right half of the window on a film half as wide: its pixel x is the full image's x + 24.
    for (CameraType type : {CameraType::kPerspective, CameraType::kOrthographic}) {
        CameraSettings full = look_at_camera(type);
        full.screen_window = std::array<float, 4>{-1.5f, 1.5f, -1, 1};
        CameraSettings half = full;
        half.width = 24;
        half.screen_window = std::array<float, 4>{0, 1.5f, -1, 1};
        const Camera a = make_camera(full), b = make_camera(half);
        for (Vec2f p : {Vec2f(0, 0), Vec2f(3.5f, 7), Vec2f(24, 32)}) {
            expect_near(ray_of(a, {p.x + 24, p.y}).o, ray_of(b, p).o, 1e-5f);
            expect_near(ray_of(a, {p.x + 24, p.y}).d, ray_of(b, p).d, 1e-6f);
        }
        // And the bottom half, on a film half as high.
        CameraSettings bottom = full;
        bottom.height = 16;
        bottom.screen_window = std::array<float, 4>{-1.5f, 1.5f, -1, 0};
        const Camera c = make_camera(bottom);
        for (Vec2f p : {Vec2f(0, 0), Vec2f(30, 9)}) {
            expect_near(ray_of(a, {p.x, p.y + 16}).o, ray_of(c, p).o, 1e-5f);
            expect_near(ray_of(a, {p.x, p.y + 16}).d, ray_of(c, p).d, 1e-6f);
        }
    }
}

TEST(ScreenWindow, OrthographicWindowIsInSceneUnits) {
    // pbrt-v4's default orthographic window at 3:2 is [-1.5, 1.5] x [-1, 1]: a film 2 units high.
    CameraSettings s = look_at_camera(CameraType::kOrthographic);
    s.ortho_height = 2;
    CameraSettings w = s;
    w.screen_window = std::array<float, 4>{-1.5f, 1.5f, -1, 1};
    const Camera a = make_camera(s), b = make_camera(w);
    for (Vec2f p : kFilmPoints) {
        expect_near(ray_of(a, p).o, ray_of(b, p).o, 1e-6f);
        EXPECT_EQ(ray_of(a, p).d, ray_of(b, p).d);
    }
}

TEST(ScreenWindow, PerspectiveWindowIsInUnitsOfTheHalfFovTangent) {
    CameraSettings s = look_at_camera();
    s.screen_window = std::array<float, 4>{-1, 1, -1, 1};
    s.fov_degrees = 90;  // tan 45 = 1: the window's corner (1, 1) is 45 degrees off axis per axis
    const PerspectiveCamera c(s);
    const CameraFrame f(s);
    const Ray r = c.generate_ray({48, 0});  // top right corner
    EXPECT_NEAR(dot(r.d, f.right) / dot(r.d, f.forward), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(r.d, f.up) / dot(r.d, f.forward), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace candela
