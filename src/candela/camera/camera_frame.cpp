#include "candela/camera/camera_frame.h"

#include <cmath>

#include "candela/math/constants.h"

namespace candela {

CameraFrame::CameraFrame(const CameraSettings& s)
    : position(s.position),
      forward(normalize(s.look_at - s.position)),
      right(normalize(cross(forward, s.up))),
      up(cross(right, forward)) {
    if (s.basis) {
        position = s.basis->position;
        right = s.basis->right;
        up = s.basis->up;
        forward = s.basis->forward;
    }
}

namespace {

// screen_window's [xmin, xmax, ymin, ymax] times `scale`, as centre and half extents.
ScreenWindow scaled_window(const std::array<float, 4>& w, float scale) {
    return {{0.5f * (w[0] + w[1]) * scale, 0.5f * (w[2] + w[3]) * scale},
            {0.5f * (w[1] - w[0]) * scale, 0.5f * (w[3] - w[2]) * scale}};
}

}  // namespace

ScreenWindow perspective_screen_window(const CameraSettings& s) {
    // pbrt-v4's perspective screen space is the tangent plane scaled by 1 / tan(fov / 2).
    if (s.screen_window) return scaled_window(*s.screen_window, std::tan(0.5f * radians(s.fov_degrees)));
    return {{0.0f, 0.0f}, perspective_half_extents(s)};
}

ScreenWindow orthographic_screen_window(const CameraSettings& s) {
    if (s.screen_window) return scaled_window(*s.screen_window, 1.0f);
    return {{0.0f, 0.0f}, orthographic_half_extents(s)};
}

Vec2f perspective_half_extents(const CameraSettings& s) {
    const float t = std::tan(0.5f * radians(s.fov_degrees));
    const float w = float(s.width), h = float(s.height);
    FovAxis axis = s.fov_axis;
    // Mitsuba 3's parse_fov: "smaller" is y for a wide image and x for a tall one, "larger" the
    // other way round; a square image has the same window either way.
    if (axis == FovAxis::kSmaller) axis = w > h ? FovAxis::kY : FovAxis::kX;
    if (axis == FovAxis::kLarger) axis = w > h ? FovAxis::kX : FovAxis::kY;
    switch (axis) {
        case FovAxis::kX:
            return {t, t * h / w};
        case FovAxis::kDiagonal: {
            // The half diagonal is t; width and height keep the aspect ratio.
            const double diagonal = std::sqrt(double(s.width) * double(s.width) + double(s.height) * double(s.height));
            return {float(double(t) * double(s.width) / diagonal), float(double(t) * double(s.height) / diagonal)};
        }
        default:  // kY: the rounding of version 1 (t * w / h), so its images stay bit-identical
            return {t * w / h, t};
    }
}

Vec2f orthographic_half_extents(const CameraSettings& s) {
    const float half_height = 0.5f * s.ortho_height;
    return {half_height * float(s.width) / float(s.height), half_height};
}

float resolved_focus_distance(const CameraSettings& s) {
    if (s.focus_distance > 0.0f) return s.focus_distance;
    return s.basis ? kDefaultTransformFocusDistance : length(s.look_at - s.position);
}

}  // namespace candela
