#include "candela/camera/camera_frame.h"

#include <cmath>

#include "candela/math/constants.h"

namespace candela {

CameraFrame::CameraFrame(const CameraSettings& s)
    : position(s.position),
      forward(normalize(s.look_at - s.position)),
      right(normalize(cross(forward, s.up))),
      up(cross(right, forward)) {}

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
    return s.focus_distance > 0.0f ? s.focus_distance : length(s.look_at - s.position);
}

}  // namespace candela
