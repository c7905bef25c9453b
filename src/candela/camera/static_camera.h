#pragma once
// The cameras that stand still, a closed set dispatched by visit (STYLE.md). The renderer visits
// once per tile, not per sample, so each kind's sample loop is compiled for it and a pinhole scene
// runs the same code as before there were others.
#include "candela/camera/orthographic_camera.h"
#include "candela/camera/perspective_camera.h"
#include "candela/camera/thin_lens_camera.h"
#include "candela/core/variant.h"

namespace candela {

using StaticCamera = Variant<PerspectiveCamera, ThinLensCamera, OrthographicCamera>;

// The camera the settings describe, at its start frame: perspective with aperture_radius > 0 is a
// ThinLensCamera, without it a PerspectiveCamera (the pinhole).
StaticCamera make_static_camera(const CameraSettings& settings);

}  // namespace candela
