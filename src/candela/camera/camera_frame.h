#pragma once
// What every camera shares: its frame in world space and the map from film positions (pixels, y
// down) to the screen (y up). Camera space is x = right, y = up, z = forward (the view direction).
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/vec.h"

namespace candela {

// Right-handed: right = normalize(cross(forward, up)), and up is re-made perpendicular to both.
// The settings must have a view direction and an up not parallel to it (the loader checks).
struct CameraFrame {
    Vec3f position, forward, right, up;

    explicit CameraFrame(const CameraSettings& s);
    // The world-space vector of camera-space (x, y, z).
    CANDELA_HD Vec3f to_world(float x, float y, float z) const { return right * x + up * y + forward * z; }
};

// Film position in pixels ((0, 0) the top-left corner) to the screen window
// [-half_width, half_width] x [-half_height, half_height], y up.
struct FilmToScreen {
    float inv_width, inv_height;
    float half_width, half_height;

    FilmToScreen(const CameraSettings& s, Vec2f half_extents)
        : inv_width(1.0f / float(s.width)), inv_height(1.0f / float(s.height)),
          half_width(half_extents.x), half_height(half_extents.y) {}
    CANDELA_HD Vec2f operator()(const Vec2f& film) const {
        return {(2.0f * film.x * inv_width - 1.0f) * half_width, (1.0f - 2.0f * film.y * inv_height) * half_height};
    }
};

// The perspective screen window on the plane at distance 1: the tangents of the half angles,
// width by height. `fov` spans the extent fov_axis names; square pixels give the other.
Vec2f perspective_half_extents(const CameraSettings& s);

// The orthographic screen window in scene units: ortho_height / 2 high, wide by the aspect ratio.
Vec2f orthographic_half_extents(const CameraSettings& s);

// focus_distance, or the distance from position to look_at where it is 0 (the default).
float resolved_focus_distance(const CameraSettings& s);

}  // namespace candela
