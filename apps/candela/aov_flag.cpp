#include "aov_flag.h"

#include <fmt/format.h>

#include <sstream>
#include <string>
#include <vector>

#include "candela/render/job/render_overrides.h"

namespace candela::cli {

AovLayers parse_aov_flag(const std::string& list) {
    if (list.empty() || list == "none") return {};
    std::istringstream in(list);
    std::vector<std::string> names;
    for (std::string name; std::getline(in, name, ',');) names.push_back(name);
    const AovLayers layers = aov_layers_override("--aov", names);
    if (list.back() == ',') bad_flag(fmt::format("--aov: empty AOV layer name in \"{}\"", list));
    return layers;
}

}  // namespace candela::cli
