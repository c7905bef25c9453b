#include "candela/render/job/render_overrides.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "candela/core/error.h"
#include "candela/render/job/checkpoint.h"
#include "candela/scene/enum_names.h"
#include "candela/scene/media_warning.h"
#include "candela/scene/scene.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

// The film's sensor flags, checked as the scene file's film keys are (formats/json/scene_loader.cpp).
void apply_sensor(const RenderOverrides& o, FilmSettings& film) {
    auto positive_float = [](const char* flag, double v) {
        if (!(v > 0) || !(v <= double(std::numeric_limits<float>::max())))
            bad_flag(fmt::format("{}: expected a number > 0 within float range, got {}", flag, v));
        return float(v);
    };
    if (o.iso) film.iso = positive_float("--iso", *o.iso);
    if (o.exposure_time) film.exposure_time = positive_float("--exposure-time", *o.exposure_time);
    const float ratio = imaging_ratio(film);
    if (!(ratio > 0.0f && std::isfinite(ratio)))
        bad_flag(fmt::format("--iso, --exposure-time: the imaging ratio exposure_time * iso / 100 = {:g} * {:g} / 100 is {}",
                             film.exposure_time, film.iso, ratio > 0.0f ? "beyond float range" : "below float range (0)"));
    if (o.white_balance) {
        const double t = *o.white_balance;
        if (!(t == 0 || (t >= double(kMinWhiteBalanceKelvin) && t <= double(std::numeric_limits<float>::max()))))
            bad_flag(fmt::format("--white-balance: expected 0 (no white balance) or a temperature >= {} (kelvin), got {}",
                                 kMinWhiteBalanceKelvin, t));
        film.white_balance = float(t);
    }
}

// --noise-threshold and --min-spp, checked as the scene's sampler.adaptive is.
void apply_adaptive(const RenderOverrides& o, SamplerSettings& sampler) {
    if (o.noise_threshold) {
        const double t = *o.noise_threshold;
        if (!(t >= 0.0 && t < 1.0))
            bad_flag(fmt::format("--noise-threshold: expected a number in [0, 1) (0: no adaptive sampling), got {}", t));
        if (t == 0.0)
            sampler.adaptive.reset();
        else
            sampler.adaptive = AdaptiveSettings{float(t), sampler.adaptive.value_or(AdaptiveSettings{}).min_spp};
    }
    if (o.min_spp) {
        if (*o.min_spp < 2 || *o.min_spp > kMaxSpp)
            bad_flag(fmt::format("--min-spp: expected an integer in [2, {}], got {}", kMaxSpp, *o.min_spp));
        if (!sampler.adaptive)
            bad_flag("--min-spp: adaptive sampling is off; turn it on with --noise-threshold or sampler.adaptive");
        sampler.adaptive->min_spp = *o.min_spp;
    }
}

// "albedo, depth" (or with another separator), or "none".
std::string aov_names(uint32_t mask, const char* separator = ", ") {
    std::string names;
    for (int l = 0; l < kAovLayerCount; ++l)
        if ((mask >> l) & 1u) names += (names.empty() ? "" : separator) + std::string(kAovLayerInfo[size_t(l)].name);
    return names.empty() ? "none" : names;
}

std::string describe(const std::optional<AdaptiveSettings>& a) {
    return a ? fmt::format("adaptive sampling with threshold {:g} and min_spp {}", a->threshold, a->min_spp)
             : std::string("no adaptive sampling");
}

// The camera resolution whose film (the crop window's pixels) is the checkpoint's: the scene's
// own when it gives that film, else the one resolution that does; nullopt when several do.
std::optional<Resolution> resolution_of_film(const Scene& scene, int width, int height) {
    const auto& crop = scene.film.crop_window;
    const PixelBounds own = crop_pixel_bounds(scene.camera.width, scene.camera.height, crop);
    if (own.width() == width && own.height() == height) return Resolution{scene.camera.width, scene.camera.height};
    // One side at a time: crop_pixel_bounds treats them alike.
    auto side = [&](int film_side, float c0, float c1) -> std::optional<int> {
        std::optional<int> found;
        for (int n = 1; n <= kMaxResolution; ++n) {
            const PixelBounds b = crop_pixel_bounds(n, 1, {c0, c1, 0.0f, 1.0f});
            if (b.width() != film_side) continue;
            if (found) return std::nullopt;
            found = n;
        }
        return found;
    };
    const std::optional<int> w = side(width, crop[0], crop[1]), h = side(height, crop[2], crop[3]);
    if (!w || !h) return std::nullopt;
    return Resolution{*w, *h};
}

}  // namespace

void bad_flag(const std::string& message) { throw SceneError({}, message); }

IntegratorType integrator_override(std::string_view flag, const std::string& name) {
    const std::optional<IntegratorType> type = parse_integrator_type(name);
    if (!type)
        bad_flag(fmt::format("{}: unknown integrator \"{}\"; expected one of: {}", flag, name,
                             names_list(integrator_type_names())));
    return *type;
}

SamplerType sampler_override(std::string_view flag, const std::string& name) {
    const std::optional<SamplerType> type = parse_sampler_type(name);
    if (!type)
        bad_flag(fmt::format("{}: unknown sampler \"{}\"; expected one of: {}", flag, name,
                             names_list(sampler_type_names())));
    return *type;
}

AovLayers aov_layers_override(std::string_view flag, const std::vector<std::string>& names) {
    AovLayers layers;
    for (const std::string& name : names) {
        const std::optional<AovLayer> layer = parse_aov_layer(name);
        if (!layer)
            bad_flag(fmt::format("{}: unknown AOV layer \"{}\"; expected one of: {}", flag, name, kAovLayerNames));
        if (layers.has(*layer)) bad_flag(fmt::format("{}: AOV layer \"{}\" is listed twice", flag, name));
        layers.add(*layer);
    }
    return layers;
}

void apply_overrides(const RenderOverrides& o, Scene& scene) {
    if (o.spp) {
        if (*o.spp < 1) bad_flag(fmt::format("--spp: expected an integer >= 1, got {}", *o.spp));
        scene.sampler.spp = *o.spp;
    }
    if (o.seed) scene.sampler.seed = *o.seed;
    if (o.resolution) {
        const auto [w, h] = *o.resolution;
        if (w < 1 || h < 1 || w > kMaxResolution || h > kMaxResolution)
            bad_flag(fmt::format("--resolution: each side must be in 1..{}, got {}x{}", kMaxResolution, w, h));
        scene.camera.width = w;
        scene.camera.height = h;
    }
    if (o.integrator) {
        scene.integrator.type = *o.integrator;
        // The scene loader refuses the same in a scene file (scene_lights.cpp).
        if (*o.integrator == IntegratorType::kBsdf && !scene.delta_lights.empty())
            bad_flag("--integrator bsdf: the bsdf integrator finds light only by hitting it, so it cannot see the "
                     "scene's point, spot or directional lights (they have no area); use path or whitted");
        // The scene loader warns the same for a scene file's own integrator (scene_loader.cpp);
        // that warning no longer holds once the integrator is another.
        std::erase_if(scene.warnings, [](const std::string& w) {
            return w.find(kMediaIgnoredWarning) != std::string::npos ||
                   w.find(kSubsurfaceIgnoredWarning) != std::string::npos;
        });
        const bool sees_media = *o.integrator == IntegratorType::kVolPath || *o.integrator == IntegratorType::kBsdf;
        if (!sees_media && places_media(scene))
            scene.warnings.push_back(fmt::format("--integrator {}: the scene has participating media, which the {} "
                                                 "integrator ignores (it renders them as vacuum); use volpath",
                                                 integrator_type_name(*o.integrator), integrator_type_name(*o.integrator)));
        if (!sees_media && has_tabulated_subsurface(scene)) {
            const auto name = integrator_type_name(*o.integrator);
            scene.warnings.push_back(fmt::format("--integrator {}: the scene has subsurface materials, of which the {} "
                                                 "integrator renders only the dielectric boundary; use volpath",
                                                 name, name));
        }
    }
    if (o.spectral) scene.integrator.spectral = *o.spectral;
    if (o.sampler) scene.sampler.type = *o.sampler;
    apply_sensor(o, scene.film);
    if (o.aovs) scene.film.aovs = *o.aovs;
    apply_adaptive(o, scene.sampler);
    if (o.target_error && !(*o.target_error > 0.0 && std::isfinite(*o.target_error)))
        bad_flag(fmt::format("--target-error: expected a relMSE > 0, got {}", *o.target_error));
}

void take_checkpoint_settings(const fs::path& file, const RenderIdentity& checkpoint, uint32_t target_spp,
                              const Scene& scene, RenderOverrides& o) {
    // Another version's names may mean other things: check_checkpoint_matches refuses it by name.
    if (checkpoint.candela_version != CANDELA_VERSION) return;
    // `given`: the flags as given ("--seed 9"), which make the render differ as `what` says.
    auto refuse = [&](const std::string& given, const std::string& what) {
        throw SceneError(SourceLocation{file.string(), 0, 0, ""},
                         fmt::format("cannot resume: {} ({}; without {} the render takes the checkpoint's)", what,
                                     given, given.find(" and ") == std::string::npos ? "it" : "them"));
    };
    if (o.resolution) {
        const PixelBounds film = crop_pixel_bounds(o.resolution->width, o.resolution->height, scene.film.crop_window);
        if (film.width() != checkpoint.width || film.height() != checkpoint.height)
            refuse(fmt::format("--resolution {}x{}", o.resolution->width, o.resolution->height),
                   fmt::format("the checkpoint is {}x{}, this render {}x{}", checkpoint.width, checkpoint.height,
                               film.width(), film.height()));
    } else if (std::optional<Resolution> r = resolution_of_film(scene, checkpoint.width, checkpoint.height)) {
        o.resolution = *r;
    } else {
        throw SceneError(SourceLocation{file.string(), 0, 0, ""},
                         fmt::format("cannot resume: the checkpoint's film is {}x{}, the part of the image the scene's "
                                     "crop window takes at several resolutions: give the --resolution it was "
                                     "rendered at",
                                     checkpoint.width, checkpoint.height));
    }
    if (o.seed && *o.seed != checkpoint.seed)
        refuse(fmt::format("--seed {}", *o.seed),
               fmt::format("the checkpoint has seed {}, this render seed {}", checkpoint.seed, *o.seed));
    o.seed = checkpoint.seed;
    if (o.sampler && sampler_type_name(*o.sampler) != checkpoint.sampler)
        refuse(fmt::format("--sampler {}", sampler_type_name(*o.sampler)),
               fmt::format("the checkpoint used sampler {}, this render {}", checkpoint.sampler,
                           sampler_type_name(*o.sampler)));
    if (!o.sampler) o.sampler = parse_sampler_type(checkpoint.sampler);
    if (o.integrator && integrator_type_name(*o.integrator) != checkpoint.integrator)
        refuse(fmt::format("--integrator {}", integrator_type_name(*o.integrator)),
               fmt::format("the checkpoint used integrator {}, this render {}", checkpoint.integrator,
                           integrator_type_name(*o.integrator)));
    // Taken only when it is not the scene's own: an override is checked (bsdf and delta lights).
    const std::optional<IntegratorType> integrator = parse_integrator_type(checkpoint.integrator);
    if (!o.integrator && integrator != scene.integrator.type) o.integrator = integrator;
    if (o.aovs && o.aovs->mask() != checkpoint.aov_layers)
        refuse(fmt::format("--aov {}", aov_names(o.aovs->mask(), ",")),
               fmt::format("the checkpoint has the AOV layers {}, this render {}", aov_names(checkpoint.aov_layers),
                           aov_names(o.aovs->mask())));
    if (!o.aovs) {
        AovLayers layers;
        for (int l = 0; l < kAovLayerCount; ++l)
            if ((checkpoint.aov_layers >> l) & 1u) layers.add(AovLayer(l));
        o.aovs = layers;
    }
    // Adaptive sampling: what the given flags make of the checkpoint's (or the scene's) settings.
    std::string flags;
    if (o.noise_threshold) flags = fmt::format("--noise-threshold {:g}", *o.noise_threshold);
    if (o.min_spp) flags += fmt::format("{}--min-spp {}", flags.empty() ? "" : " and ", *o.min_spp);
    if (!o.noise_threshold) o.noise_threshold = checkpoint.adaptive ? double(checkpoint.adaptive->threshold) : 0.0;
    if (!o.min_spp && checkpoint.adaptive) o.min_spp = checkpoint.adaptive->min_spp;
    std::optional<AdaptiveSettings> adaptive;
    if (*o.noise_threshold != 0.0)
        adaptive = AdaptiveSettings{float(*o.noise_threshold),
                                    o.min_spp.value_or(scene.sampler.adaptive.value_or(AdaptiveSettings{}).min_spp)};
    if (!flags.empty() && (adaptive != checkpoint.adaptive || (!adaptive && o.min_spp)))
        refuse(flags, fmt::format("the checkpoint used {}, this render {}", describe(checkpoint.adaptive),
                                  adaptive || !o.min_spp ? describe(adaptive)
                                                          : fmt::format("min_spp {}", *o.min_spp)));
    // A part file knows the samples its render asks for (merging refuses parts that differ).
    if (target_spp > 0 && !o.spp) o.spp = int(target_spp);
}

}  // namespace candela
