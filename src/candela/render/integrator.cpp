#include "candela/render/integrator.h"

#include "candela/render/debug_integrators.h"
#include "candela/scene/scene.h"

namespace candela {

std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Accelerator& accel) {
    const IntegratorSettings& s = scene.integrator;
    switch (s.type) {
        case IntegratorType::kNormals: return std::make_unique<NormalsIntegrator>(accel);
        case IntegratorType::kDepth: return std::make_unique<DepthIntegrator>(accel, scene.camera.near);
        case IntegratorType::kAlbedo: return std::make_unique<AlbedoIntegrator>(scene, accel);
        case IntegratorType::kAo: return std::make_unique<AoIntegrator>(accel, s.max_distance);
    }
    return nullptr;
}

}  // namespace candela
