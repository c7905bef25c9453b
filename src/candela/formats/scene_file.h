#pragma once
// Loads a scene file of any format candela reads, chosen by extension: `.pbrt` (or `.pbrt.gz`) is pbrt-v4's
// (formats/pbrt), anything else candela's JSON (formats/json).
#include <filesystem>

#include "candela/formats/json/scene_loader.h"
#include "candela/scene/scene.h"

namespace candela {

bool is_pbrt_scene_file(const std::filesystem::path& file);

Scene load_scene_file(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace candela
