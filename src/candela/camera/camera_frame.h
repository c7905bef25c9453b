#pragma once
// What every camera shares: its frame in world space and the map from film positions (pixels, y
// down) to the screen (y up). Camera space is x = right, y = up, z = forward (the view direction).
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/vec.h"

namespace candela {

// From position, look_at and up, right-handed: right = normalize(cross(forward, up)), and up is
// re-made perpendicular to both. The settings must have a view direction and an up not parallel to
// it (the loader checks). From settings.basis when set, as it is.
struct CameraFrame {
    Vec3f position, forward, right, up;

    explicit CameraFrame(const CameraSettings& s);
    // The world-space vector of camera-space (x, y, z).
    CANDELA_HD Vec3f to_world(float x, float y, float z) const { return right * x + up * y + forward * z; }
};

// A screen window, y up: centre +- half.
struct ScreenWindow {
    Vec2f centre{0.0f, 0.0f};
    Vec2f half;
};

// Film position in pixels ((0, 0) the top-left corner) to the screen window
// centre + [-half.x, half.x] x [-half.y, half.y], y up.
struct FilmToScreen {
    float inv_width, inv_height;
    float half_width, half_height;
    float centre_x, centre_y;

    FilmToScreen(const CameraSettings& s, ScreenWindow window)
        : inv_width(1.0f / float(s.width)), inv_height(1.0f / float(s.height)), half_width(window.half.x),
          half_height(window.half.y), centre_x(window.centre.x), centre_y(window.centre.y) {}
    FilmToScreen(const CameraSettings& s, Vec2f half_extents) : FilmToScreen(s, ScreenWindow{{0.0f, 0.0f}, half_extents}) {}
    // A centre of 0 adds exactly 0: centred windows map as they did before windows had centres.
    CANDELA_HD Vec2f operator()(const Vec2f& film) const {
        return {(2.0f * film.x * inv_width - 1.0f) * half_width + centre_x,
                (1.0f - 2.0f * film.y * inv_height) * half_height + centre_y};
    }
};

// The perspective screen window on the plane at distance 1: the tangents of the half angles,
// width by height. `fov` spans the extent fov_axis names; square pixels give the other.
Vec2f perspective_half_extents(const CameraSettings& s);

// The orthographic screen window in scene units: ortho_height / 2 high, wide by the aspect ratio.
Vec2f orthographic_half_extents(const CameraSettings& s);

// The screen windows of the cameras: perspective on the plane at distance 1 (tangents), and
// orthographic in scene units; from screen_window when set, else centred with the half extents
// above.
ScreenWindow perspective_screen_window(const CameraSettings& s);
ScreenWindow orthographic_screen_window(const CameraSettings& s);

// focus_distance, or the distance from position to look_at where it is 0 (the default).
float resolved_focus_distance(const CameraSettings& s);

}  // namespace candela
