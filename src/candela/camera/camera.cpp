#include "candela/camera/camera.h"

namespace candela {

StaticCamera make_static_camera(const CameraSettings& settings) {
    if (settings.type == CameraType::kOrthographic) return OrthographicCamera(settings);
    if (settings.aperture_radius > 0.0f) return ThinLensCamera(settings);
    return PerspectiveCamera(settings);
}

Camera make_camera(const CameraSettings& settings, bool shapes_move) {
    if (settings.motion || shapes_move) return MovingCamera(settings);
    return visit([](const auto& camera) -> Camera { return camera; }, make_static_camera(settings));
}

}  // namespace candela
