// The `lights` part of a scene file. Area lights are shapes with `emission`; this part holds the
// lights that are not shapes: the environment, and the point, spot and directional lights.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "candela/image/image_io.h"
#include "candela/formats/json/scene_sections.h"
#include "candela/formats/json/scene_spectra.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 4> kLightTypes = {"environment", "point", "spot", "directional"};
constexpr std::array<std::string_view, 2> kEnvironmentSamplingNames = {"importance", "uniform"};
constexpr std::array<std::string_view, 2> kEnvironmentMappingNames = {"equal_area", "equirectangular"};
constexpr std::array<std::string_view, 2> kEnvironmentFilterNames = {"bilinear", "point"};

Image read_environment_image(const JsonCursor& file, const std::filesystem::path& folder,
                             EnvironmentMapping mapping, std::vector<std::string>& warnings,
                             MemoryBudget& budget) {
    std::string extension = std::filesystem::path(file.string()).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (extension != ".hdr" && extension != ".exr")
        file.fail(fmt::format("expected an .hdr or .exr image (linear radiance), got {}",
                              json_quoted(file.string())));
    std::filesystem::path path = referenced_file(file, folder, "environment image");
    Image image = load_referenced(file, [&] { return read_image(path); });
    if (image.width <= 0 || image.height <= 0)
        file.fail(fmt::format("environment image {} is empty", json_quoted(file.string())));
    // The image readers cap the size (image_formats.h); what the light builds from it is charged.
    if (auto refused = budget.charge(environment_memory_bytes(image.width, image.height),
                                     fmt::format("environment image {} ({}x{})", json_quoted(file.string()),
                                                 image.width, image.height)))
        file.fail(*refused);
    if (mapping == EnvironmentMapping::kEqualArea) {
        if (image.width != image.height)
            file.fail(fmt::format("environment image {} is {}x{}; an equal_area map must be square",
                                  json_quoted(file.string()), image.width, image.height));
        return image;
    }
    // Any size maps onto the sphere, but one that is not 2:1 stretches its texels (and is often
    // not an equirectangular map at all, e.g. a cube cross): worth a word, not a failure.
    if (image.width != 2 * image.height) {
        SourceLocation where = file.document().locate(file.pointer());
        warnings.push_back(SceneError(where, fmt::format("environment image {} is {}x{}, not 2:1 "
                                                         "(width twice the height); it is stretched "
                                                         "over the sphere as it is",
                                                         json_quoted(file.string()), image.width,
                                                         image.height))
                               .formatted());
    }
    return image;
}

EnvironmentSettings read_environment(JsonCursor c, const std::filesystem::path& folder,
                                     std::vector<std::string>& warnings, MemoryBudget& budget) {
    // Either an image or one colour: both at once would leave one silently ignored.
    bool has_file = c.has("file"), has_color = c.has("color");
    if (has_file && has_color) c.get("color")->fail("give \"file\" or \"color\", not both");
    if (!has_file && !has_color)
        c.fail("an environment needs \"file\" (an .hdr or .exr image) or \"color\"");
    EnvironmentSettings env;
    if (auto v = c.get("scale")) env.scale = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("transform")) env.to_world = read_transform(*v, MatrixRows::kProjective);
    if (auto v = c.get("sampling")) {
        env.sampling = v->choice("environment sampling", kEnvironmentSamplingNames) == "uniform"
                           ? EnvironmentSampling::kUniform
                           : EnvironmentSampling::kImportance;
    }
    if (auto v = c.get("mapping")) {
        env.mapping = v->choice("environment mapping", kEnvironmentMappingNames) == "equal_area"
                          ? EnvironmentMapping::kEqualArea
                          : EnvironmentMapping::kEquirectangular;
    }
    if (auto v = c.get("filter")) {
        env.filter = v->choice("environment filter", kEnvironmentFilterNames) == "point" ? EnvironmentFilter::kPoint
                                                                                        : EnvironmentFilter::kBilinear;
    }
    std::optional<JsonCursor> illuminance = c.get("illuminance");
    std::optional<float> target;
    if (illuminance) target = illuminance->number_f(Bounds::above(0));
    std::optional<JsonCursor> file = c.get("file");
    if (!file) {
        env.radiance = Image(1, 1);
        env.radiance.at(0, 0) = c.get("color")->colour(Bounds::at_least(0));
    }
    c.reject_unknown_keys();
    if (file) env.radiance = read_environment_image(*file, folder, env.mapping, warnings, budget);
    if (target) {
        // pbrt-v4's infinite-light `illuminance`: the map is scaled so that a surface facing the
        // light frame's up direction receives that illuminance (on top of `scale`).
        double up = environment_up_illuminance(env.radiance, env.mapping, env.filter);
        if (!(up > 0.0))
            illuminance->fail(fmt::format("the environment gives no light to a surface facing its up direction "
                                          "({}), so no scale can make its illuminance {}",
                                          env.mapping == EnvironmentMapping::kEqualArea ? "+z" : "+y",
                                          static_cast<double>(*target)));
        double scale = static_cast<double>(env.scale) * static_cast<double>(*target) / up;
        if (!(scale <= static_cast<double>(std::numeric_limits<float>::max())))
            illuminance->fail(fmt::format("the scale for illuminance {} is {:g}, beyond a 32-bit float",
                                          static_cast<double>(*target), scale));
        env.scale = static_cast<float>(scale);
    }
    return env;
}

// Why an environment gives no light, or nothing when it does.
std::optional<std::string> why_dark(const EnvironmentSettings& env, bool from_file) {
    if (env.scale == 0.0f) return "its scale is 0";
    for (const Rgb& p : env.radiance.pixels)
        if (!p.is_black()) return std::nullopt;
    return from_file ? "its image is black" : "its color is 0";
}

// The colour and power keys every delta light shares: the colour `key` (default 1, white; RGB
// or a spectrum, normalized to luminance 1 as pbrt-v4 does), `scale` and `power`. The colour
// comes back multiplied by `scale`; `power` (W) is read as is. A spectrum comes back normalized,
// its factor in spectrum_scale (so far `scale`): spectral mode multiplies it by the same factors
// as RGB mode's colour, so both modes emit the same luminance.
struct DeltaEmission {
    Color color{1.0f};
    std::optional<float> power;
    std::string why_dark;  // empty when the light emits; else what makes it dark
    std::optional<DenseSpectrum> spectrum;
    float spectrum_scale = 1.0f;
};

DeltaEmission read_delta_emission(JsonCursor& c, std::string_view key, const Scene& scene) {
    DeltaEmission e;
    std::optional<JsonCursor> color = c.get(key);
    if (color) {
        if (std::optional<LightSpectrum> s = read_light_spectrum(*color, scene.file.parent_path())) {
            e.color = from_rgb(s->rgb);
            e.spectrum = s->normalized;
        } else {
            e.color = from_rgb(color->colour(Bounds::at_least(0)));
        }
    }
    float scale = 1.0f;
    if (auto v = c.get("scale")) scale = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("power")) e.power = v->number_f(Bounds::at_least(0));
    e.color *= scale;
    e.spectrum_scale = scale;
    if (e.power && *e.power == 0.0f)
        e.why_dark = "its power is 0";
    else if (scale == 0.0f)
        e.why_dark = "its scale is 0";
    else if (e.color.is_black())
        e.why_dark = fmt::format("its {} is 0", key);
    return e;
}

// pbrt-v4's `power` normalization (lights.cpp, PointLight::Create and SpotLight::Create): the
// colour (times scale) is multiplied by power / k_e, k_e the power of a light of unit intensity.
// As in pbrt-v4, an RGB colour is not divided by its own luminance: a white [1, 1, 1] light
// emits exactly `power` watts, a coloured one that times its colour; a spectrum, already at
// luminance 1, emits `power` watts of light whatever its colour.
Color intensity_for(DeltaEmission& e, float power_per_intensity, JsonCursor& c) {
    if (!e.color.is_finite()) c.get("scale")->fail("the light's intensity overflows float range");
    Color intensity = e.color;
    if (e.power) {
        const float factor = *e.power / power_per_intensity;
        intensity = e.color * factor;
        e.spectrum_scale *= factor;
    }
    if (!intensity.is_finite()) c.get("power")->fail("the light's intensity overflows float range");
    return intensity;
}

PointLight read_point(JsonCursor& c, DeltaEmission& e, const Scene& scene) {
    PointLight light;
    light.position = c.require("position").vec3f();
    e = read_delta_emission(c, "intensity", scene);
    light.intensity = intensity_for(e, PointLight::power_per_intensity(), c);
    return light;
}

// cone_angle (the half-angle where the light ends) in (0, 180], default 30; cone_delta (the width
// of the falloff inside it) in [0, cone_angle], default 5 or cone_angle if smaller: pbrt-v4's
// coneangle and conedeltaangle, whose light starts to fall off at coneangle - conedeltaangle. A
// cone_delta beyond cone_angle would start the falloff at a negative angle, which pbrt-v4 reads
// as the same positive one: refused instead.
SpotLight read_spot(JsonCursor& c, DeltaEmission& e, const Scene& scene) {
    SpotLight light;
    JsonCursor position = c.require("position"), look_at = c.require("look_at");
    light.position = position.vec3f();
    Vec3f target = look_at.vec3f();
    Vec3d axis = Vec3d(target) - Vec3d(light.position);
    if (axis == Vec3d(0.0))
        look_at.fail(fmt::format("look_at equals position [{}, {}, {}]; the spot light has no direction",
                                 light.position.x, light.position.y, light.position.z));
    light.axis = Vec3f(normalize(axis));
    float cone_angle = 30.0f;
    if (auto v = c.get("cone_angle")) cone_angle = v->number_f(Bounds{0.0, 180.0, true, false});
    float cone_delta = std::min(5.0f, cone_angle);
    if (auto v = c.get("cone_delta")) {
        cone_delta = v->number_f(Bounds::at_least(0));
        if (cone_delta > cone_angle)
            v->fail(fmt::format("cone_delta {} is larger than cone_angle {}: the falloff must lie inside "
                                "the cone (expected a number in [0, {}])",
                                cone_delta, cone_angle, cone_angle));
    }
    light.cos_falloff_end = std::cos(radians(cone_angle));
    light.cos_falloff_start = std::cos(radians(cone_angle - cone_delta));
    e = read_delta_emission(c, "intensity", scene);
    light.intensity =
        intensity_for(e, SpotLight::power_per_intensity(light.cos_falloff_start, light.cos_falloff_end), c);
    return light;
}

DirectionalLight read_directional(JsonCursor& c, DeltaEmission& e, const Scene& scene) {
    DirectionalLight light;
    JsonCursor direction = c.require("direction");
    Vec3d d = direction.vec3();
    if (!is_finite(normalize(d))) direction.fail_expected("a nonzero direction");
    light.direction = Vec3f(normalize(d));
    e = read_delta_emission(c, "irradiance", scene);
    // With `power`, the irradiance waits for the scene's size (DeltaLightSettings).
    light.irradiance = e.color;
    if (!light.irradiance.is_finite()) c.get("scale")->fail("the light's irradiance overflows float range");
    return light;
}

// A point, spot or directional light, `type` already read; nothing when it emits nothing.
std::optional<DeltaLightSettings> read_delta_light(JsonCursor& c, std::string_view type, Scene& scene) {
    DeltaEmission e;
    DeltaLightSettings settings;
    if (type == "point") {
        settings.light = read_point(c, e, scene);
    } else if (type == "spot") {
        settings.light = read_spot(c, e, scene);
    } else {
        settings.light = read_directional(c, e, scene);
        settings.directional_power = e.power;
    }
    c.reject_unknown_keys();
    if (!e.why_dark.empty()) {
        add_warning(scene, c, fmt::format("the {} light emits nothing ({}); it is ignored", type, e.why_dark));
        return std::nullopt;
    }
    if (e.spectrum) {
        settings.spectrum = scene.textures.add_spectrum(*e.spectrum);
        settings.spectrum_scale = e.spectrum_scale;
    }
    // BSDF sampling alone finds light by hitting it, and nothing hits a point or a direction: the
    // image would be rendered without this light, so the scene is refused (pbrt-v4 renders it
    // black without a word). The integrator is what the user can change, so the error is there.
    if (scene.integrator.type == IntegratorType::kBsdf)
        c.document().fail("/integrator/type",
                          fmt::format("the bsdf integrator finds light only by hitting it, so it cannot see "
                                      "the {} light at {} (point, spot and directional lights have no "
                                      "area); use path or whitted, or an area light (a shape with emission)",
                                      type, c.pointer()));
    return settings;
}

}  // namespace

void read_lights(const JsonCursor& lights, const std::filesystem::path& folder, Scene& scene,
                 MemoryBudget& budget) {
    std::string first_environment;
    for (JsonCursor c : lights.elements()) {
        std::string_view type = c.require("type").choice("light type", kLightTypes);
        if (type != "environment") {
            if (std::optional<DeltaLightSettings> light = read_delta_light(c, type, scene))
                scene.delta_lights.push_back(*light);
            continue;
        }
        if (!first_environment.empty())
            c.fail(fmt::format("a scene has at most one environment light, and {} is one",
                               first_environment));
        const bool from_file = c.has("file");
        EnvironmentSettings env = read_environment(c, folder, scene.warnings, budget);
        first_environment = c.pointer();
        // A light of zero power would only take part in light selection to no effect; without
        // it the image is the same (escaping rays see black either way).
        if (auto dark = why_dark(env, from_file)) {
            add_warning(scene, c, fmt::format("the environment light emits nothing ({}); it is ignored", *dark));
            continue;
        }
        scene.environment = std::move(env);
    }
}

}  // namespace candela
