// The `lights` part of a scene file. Area lights are shapes with `emission`; this part holds the
// lights that are not shapes: for now the environment.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "candela/image/image_io.h"
#include "candela/scene/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 1> kLightTypes = {"environment"};
constexpr std::array<std::string_view, 2> kEnvironmentSamplingNames = {"importance", "uniform"};

Image read_environment_image(const JsonCursor& file, const std::filesystem::path& folder,
                             std::vector<std::string>& warnings, MemoryBudget& budget) {
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
    if (auto v = c.get("transform")) env.to_world = read_transform(*v);
    if (auto v = c.get("sampling")) {
        env.sampling = v->choice("environment sampling", kEnvironmentSamplingNames) == "uniform"
                           ? EnvironmentSampling::kUniform
                           : EnvironmentSampling::kImportance;
    }
    std::optional<JsonCursor> file = c.get("file");
    if (!file) {
        env.radiance = Image(1, 1);
        env.radiance.at(0, 0) = c.get("color")->colour(Bounds::at_least(0));
    }
    c.reject_unknown_keys();
    if (file) env.radiance = read_environment_image(*file, folder, warnings, budget);
    return env;
}

// Why an environment gives no light, or nothing when it does.
std::optional<std::string> why_dark(const EnvironmentSettings& env, bool from_file) {
    if (env.scale == 0.0f) return "its scale is 0";
    for (const Rgb& p : env.radiance.pixels)
        if (!p.is_black()) return std::nullopt;
    return from_file ? "its image is black" : "its color is 0";
}

}  // namespace

void read_lights(const JsonCursor& lights, const std::filesystem::path& folder, Scene& scene,
                 MemoryBudget& budget) {
    std::string first_environment;
    for (JsonCursor c : lights.elements()) {
        c.require("type").choice("light type", kLightTypes);
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
