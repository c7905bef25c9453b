#pragma once
// Loads a pbrt-v4 scene: the importer translates it into a candela JSON document and meshes
// (pbrt_importer.h), and the JSON loader loads those as it loads any candela scene, with errors
// pointing back into the pbrt files. `candela convert` writes the same document, so the converted
// scene renders the same bits.
#include <filesystem>
#include <string>

#include "candela/formats/json/scene_loader.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/scene/scene.h"

namespace candela::pbrt {

// The document as JSON text, as `candela convert` writes it and the loader reads it.
std::string document_text(const ImportedScene& imported);

// Loads an imported scene; `file` is the main .pbrt file (relative names resolve against its
// folder). The importer's warnings come first in Scene::warnings.
Scene load_imported_scene(const ImportedScene& imported, const std::filesystem::path& file,
                          const LoadOptions& options = {});

Scene load_pbrt_scene(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace candela::pbrt
