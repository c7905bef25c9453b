// The `lights` part of a scene file. Area lights are shapes with `emission`; this part holds the
// lights that are not shapes: for now the environment.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "candela/image/image_io.h"
#include "candela/scene/scene_sections.h"

namespace candela {

namespace {

constexpr std::array<std::string_view, 1> kLightTypes = {"environment"};

Image read_environment_image(const JsonCursor& file, const std::filesystem::path& folder) {
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
    return image;
}

EnvironmentSettings read_environment(JsonCursor c, const std::filesystem::path& folder) {
    // Either an image or one colour: both at once would leave one silently ignored.
    bool has_file = c.has("file"), has_color = c.has("color");
    if (has_file && has_color) c.get("color")->fail("give \"file\" or \"color\", not both");
    if (!has_file && !has_color)
        c.fail("an environment needs \"file\" (an .hdr or .exr image) or \"color\"");
    EnvironmentSettings env;
    if (auto v = c.get("scale")) env.scale = v->number_f(Bounds::at_least(0));
    if (auto v = c.get("transform")) env.to_world = read_transform(*v);
    std::optional<JsonCursor> file = c.get("file");
    if (!file) {
        env.radiance = Image(1, 1);
        env.radiance.at(0, 0) = c.get("color")->colour(Bounds::at_least(0));
    }
    c.reject_unknown_keys();
    if (file) env.radiance = read_environment_image(*file, folder);
    return env;
}

}  // namespace

void read_lights(const JsonCursor& lights, const std::filesystem::path& folder, Scene& scene) {
    std::string first_environment;
    for (JsonCursor c : lights.elements()) {
        c.require("type").choice("light type", kLightTypes);
        if (scene.environment)
            c.fail(fmt::format("a scene has at most one environment light, and {} is one",
                               first_environment));
        scene.environment = read_environment(c, folder);
        first_environment = c.pointer();
    }
}

}  // namespace candela
