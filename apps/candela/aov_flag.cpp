#include "aov_flag.h"

#include <fmt/format.h>

#include <sstream>

#include "candela/core/error.h"

namespace candela::cli {

AovLayers parse_aov_flag(const std::string& list) {
    auto bad = [](const std::string& message) { throw SceneError({}, "--aov: " + message); };
    AovLayers layers;
    if (list.empty() || list == "none") return layers;
    std::istringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        const std::optional<AovLayer> layer = parse_aov_layer(name);
        if (!layer) bad(fmt::format("unknown AOV layer \"{}\"; expected one of: {}", name, kAovLayerNames));
        if (layers.has(*layer)) bad(fmt::format("AOV layer \"{}\" is listed twice", name));
        layers.add(*layer);
    }
    if (list.back() == ',') bad(fmt::format("empty AOV layer name in \"{}\"", list));
    return layers;
}

}  // namespace candela::cli
