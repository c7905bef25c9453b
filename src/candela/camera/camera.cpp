#include "candela/camera/camera.h"

namespace candela {

Camera make_camera(const CameraSettings& settings) {
    if (settings.type == CameraType::kOrthographic) return OrthographicCamera(settings);
    if (settings.aperture_radius > 0.0f) return ThinLensCamera(settings);
    return PerspectiveCamera(settings);
}

}  // namespace candela
