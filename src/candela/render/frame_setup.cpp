#include "candela/render/frame_setup.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "candela/film/pixel_filter.h"
#include "candela/geometry/accelerator.h"
#include "candela/lights/light_set.h"
#include "candela/scene/scene.h"

namespace candela {

AlphaCutouts alpha_cutouts(const Scene& scene) {
    AlphaCutouts cutouts;
    cutouts.textures = &scene.textures;
    bool any = false;
    for (const Shape& shape : scene.shapes) {
        const SurfaceParams& surface = scene.materials[shape.material].surface;
        cutouts.shape_alpha.push_back(surface.alpha);
        any = any || surface.cuts_out();
    }
    if (!any) cutouts.shape_alpha.clear();
    return cutouts;
}

LightSet build_light_set(const Scene& scene, const Accelerator& accel) {
    std::optional<EnvironmentLight> environment;
    if (const auto& env = scene.environment)
        environment.emplace(env->radiance, env->scale, env->to_world, env->sampling, env->mapping, env->filter);
    // The environment's and the directional lights' power need the scene's size: its bounding
    // sphere (pbrt-v4's Bounds3::BoundingSphere: centre and half diagonal).
    Bounds3f bounds = accel.bounds();
    float scene_radius = bounds.empty() ? 1.0f : std::max(0.5f * length(bounds.diagonal()), 1e-6f);
    std::vector<DeltaLight> delta_lights;
    std::vector<SpectralColor> delta_spectra;
    for (const DeltaLightSettings& settings : scene.delta_lights) {
        DeltaLight light = settings.light;
        float power_scale = 1.0f;
        if (auto* directional = get_if<DirectionalLight>(&light); directional && settings.directional_power) {
            power_scale = *settings.directional_power / DirectionalLight::power_per_irradiance(scene_radius);
            directional->irradiance *= power_scale;
        }
        delta_lights.push_back(light);
        if (settings.spectrum != kNoSpectrum)
            delta_spectra.push_back(
                SpectralColor{{}, &scene.textures.spectrum(settings.spectrum), settings.spectrum_scale * power_scale});
        else
            delta_spectra.push_back(SpectralColor{rgb_illuminant_spectrum(to_rgb(delta_light_color(light))), nullptr, 1.0f});
    }
    LightSet lights(scene.meshes, scene.spheres, scene.disks, scene.shapes, delta_lights,
                    scene.integrator.light_selection, std::move(environment), scene_radius, scene.quadrics);
    if (scene.integrator.spectral) {
        std::vector<SpectralColor> shape_spectra(scene.shapes.size());
        for (size_t i = 0; i < scene.shapes.size(); ++i) {
            const Shape& shape = scene.shapes[i];
            if (shape.emission_spectrum != kNoSpectrum)
                shape_spectra[i] = SpectralColor{{}, &scene.textures.spectrum(shape.emission_spectrum), 1.0f};
            else
                shape_spectra[i].rgb = rgb_illuminant_spectrum(shape.emission);
        }
        lights.set_spectra(shape_spectra, delta_spectra);
    }
    return lights;
}

PixelBounds render_pixel_bounds(const Scene& scene) {
    return crop_pixel_bounds(scene.camera.width, scene.camera.height, scene.film.crop_window);
}

Film make_film(const Scene& scene, bool statistics) {
    const PixelBounds bounds = render_pixel_bounds(scene);
    return Film(bounds.width(), bounds.height(), is_tabulated(scene.film.filter.type), scene.film.aovs,
                statistics || scene.sampler.adaptive.has_value() || film_needs_statistics(scene.film.aovs));
}

}  // namespace candela
