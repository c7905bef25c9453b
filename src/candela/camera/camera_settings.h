#pragma once
// The camera of the scene file (DESIGN.md: right-handed, image y downward; docs/SCENE_FORMAT.md).
#include <array>
#include <optional>

#include "candela/math/vec.h"

namespace candela {

// perspective: rays from the eye (or, with a lens, through it) spread by the field of view.
// orthographic: parallel rays along the view direction from a film `ortho_height` tall.
enum class CameraType { kPerspective, kOrthographic };

// Which extent of the image `fov` spans (Mitsuba 3's fov_axis): its width, its height, its
// diagonal, or the smaller or larger of width and height (pbrt's fov spans the smaller).
enum class FovAxis { kX, kY, kDiagonal, kSmaller, kLarger };

// The camera frame in world space, given directly (the scene file's camera `transform`) rather than
// by position, look_at and up: unit axes, right and up across the image, forward the view
// direction. Their handedness is whatever the transform's is (pbrt-v4's camera space is
// left-handed: x right, y up, z forward).
struct CameraBasis {
    Vec3f position, right, up, forward;
};

// pbrt-v4's default focaldistance, the default focus_distance of a camera given by a transform
// (which has no look_at to focus on).
inline constexpr float kDefaultTransformFocusDistance = 1e6f;

// A moving camera (pbrt-v4's animated CameraTransform): the frame above is the camera's at
// start_time, `end` its frame at end_time; in between the two are interpolated as
// AnimatedTransform does (math/animated_transform.h), before start_time and after end_time they
// hold still. Both frames have the same handedness (the loader checks).
struct CameraMotion {
    CameraBasis end;
    double start_time = 0.0, end_time = 1.0;
};

struct CameraSettings {
    CameraType type = CameraType::kPerspective;
    Vec3f position{0, 0, 0};
    Vec3f look_at{0, 0, -1};
    Vec3f up{0, 1, 0};
    float fov_degrees = 40.0f;       // perspective: the angle across fov_axis
    FovAxis fov_axis = FovAxis::kY;  // vertical: the scene format's choice since version 1
    float ortho_height = 2.0f;       // orthographic: the film's height in scene units
    int width = 512;
    int height = 512;
    float near = 0.0f;  // camera rays start this far along their direction
    // Thin lens (pbrt's lensradius, focaldistance): the radius of the lens disk in scene units (0:
    // a pinhole), and the distance from the lens to the plane in focus, along the view direction.
    // focus_distance 0 stands for the distance from position to look_at.
    float aperture_radius = 0.0f;
    float focus_distance = 0.0f;
    // When set, the frame (position, look_at and up are then not used).
    std::optional<CameraBasis> basis;
    // pbrt-v4's screenwindow: [xmin, xmax, ymin, ymax] on the screen, y up. Perspective: in units
    // of tan(fov / 2) (fov_axis is then not used); orthographic: in scene units (ortho_height is
    // then not used). Unset: centred, from fov and fov_axis or ortho_height.
    std::optional<std::array<float, 4>> screen_window;
    // The shutter [open, close] (pbrt-v4's shutteropen, shutterclose): each camera sample's time is
    // drawn uniformly in it, but only when something moves (then one 1D request, after the pixel
    // filter's and before the lens's, in pbrt-v4's order).
    std::array<double, 2> shutter{0.0, 1.0};
    std::optional<CameraMotion> motion;
};

}  // namespace candela
