#include "candela/render/integrator.h"

#include "candela/render/debug_integrators.h"
#include "candela/render/transport_integrators.h"
#include "candela/scene/scene.h"

namespace candela {

std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Accelerator& accel, const LightSet& lights) {
    const IntegratorSettings& s = scene.integrator;
    switch (s.type) {
        case IntegratorType::kPath: return std::make_unique<PathIntegrator>(scene, accel, lights);
        case IntegratorType::kBsdf: return std::make_unique<BsdfIntegrator>(scene, accel, lights);
        case IntegratorType::kWhitted: return std::make_unique<WhittedIntegrator>(scene, accel, lights);
        case IntegratorType::kNormals: return std::make_unique<NormalsIntegrator>(accel);
        case IntegratorType::kDepth: return std::make_unique<DepthIntegrator>(accel, scene.camera.near);
        case IntegratorType::kAlbedo: return std::make_unique<AlbedoIntegrator>(scene, accel);
        case IntegratorType::kAo: return std::make_unique<AoIntegrator>(accel, s.max_distance);
    }
    return nullptr;
}

}  // namespace candela
