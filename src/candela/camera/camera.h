#pragma once
// The cameras, a closed set dispatched by visit (STYLE.md): the still ones and the moving one.
#include "candela/camera/camera_settings.h"
#include "candela/camera/moving_camera.h"
#include "candela/camera/static_camera.h"
#include "candela/core/variant.h"

namespace candela {

using Camera = Variant<PerspectiveCamera, ThinLensCamera, OrthographicCamera, MovingCamera>;

// The camera the settings describe: a MovingCamera when settings.motion is set or shapes move
// (its samples then draw times), else the still camera of make_static_camera.
Camera make_camera(const CameraSettings& settings, bool shapes_move = false);

}  // namespace candela
