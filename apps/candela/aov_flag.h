#pragma once
// `--aov albedo,normal,...`: the AOV layers to write beside the image (film/aov_layers.h).
#include <string>

#include "candela/film/aov_layers.h"

namespace candela::cli {

// The layers a comma-separated list names ("none" or "" for none). Throws SceneError for an
// unknown name (listing the known ones), a repeated one, or one not available yet.
AovLayers parse_aov_flag(const std::string& list);

}  // namespace candela::cli
