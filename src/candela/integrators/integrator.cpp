#include "candela/integrators/integrator.h"

#include <algorithm>

#include "candela/core/error.h"
#include "candela/lights/light_set.h"
#include "candela/integrators/debug_integrators.h"
#include "candela/integrators/transport_integrators.h"
#include "candela/integrators/volpath_integrator.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

// Whether some material is `interface`: a boundary between media that path skips and volpath
// crosses.
bool has_interface_material(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.interface; });
}

}  // namespace

TransportIntegrator::TransportIntegrator(const Scene& scene, const Accelerator& accel, const LightSet& lights)
    : scene_(scene),
      accel_(accel),
      lights_(lights),
      any_material_uses_choice_(std::any_of(scene.materials.begin(), scene.materials.end(),
                                            [](const Material& m) { return m.bsdf.uses_choice(); })),
      any_interface_(has_interface_material(scene)),
      spectral_(scene.integrator.spectral),
      sensor_(make_sensor(scene.film)) {}

namespace {

// Whether a scene has anything only volpath's loop handles: media, `interface` surfaces or the
// tabulated BSSRDF of subsurface materials.
bool needs_volume_transport(const Scene& scene) {
    return !scene.media.empty() || has_interface_material(scene) || has_tabulated_subsurface(scene);
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Accelerator& accel, const LightSet& lights) {
    const IntegratorSettings& s = scene.integrator;
    switch (s.type) {
        case IntegratorType::kPath: return std::make_unique<PathIntegrator>(scene, accel, lights);
        case IntegratorType::kBsdf:
            // It finds light only by hitting it, and no ray hits a point, spot or directional
            // light: refused rather than rendered without them (the scene loader and the CLI
            // refuse such scenes first, with their own messages).
            if (lights.has_delta_lights())
                throw RenderError("the bsdf integrator cannot see point, spot or directional lights");
            // With media: volpath's estimator without light sampling.
            if (needs_volume_transport(scene)) return std::make_unique<VolPathIntegrator>(scene, accel, lights, false);
            return std::make_unique<BsdfIntegrator>(scene, accel, lights);
        case IntegratorType::kWhitted: return std::make_unique<WhittedIntegrator>(scene, accel, lights);
        case IntegratorType::kVolPath:
            // Without media or interfaces volpath's estimate is path's: path renders it, with
            // path's bits and speed (pbrt-v4's volpath differs only in its MIS heuristic there).
            if (!needs_volume_transport(scene)) return std::make_unique<PathIntegrator>(scene, accel, lights);
            return std::make_unique<VolPathIntegrator>(scene, accel, lights);
        case IntegratorType::kNormals: return std::make_unique<NormalsIntegrator>(accel);
        case IntegratorType::kDepth: return std::make_unique<DepthIntegrator>(accel, scene.camera.near);
        case IntegratorType::kAlbedo: return std::make_unique<AlbedoIntegrator>(scene, accel);
        case IntegratorType::kAo: return std::make_unique<AoIntegrator>(accel, s.max_distance);
    }
    return nullptr;
}

}  // namespace candela
