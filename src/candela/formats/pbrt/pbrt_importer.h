#pragma once
// pbrt-v4's semantics: the importer is the parser's Target that turns a pbrt-v4 scene into a
// candela JSON scene document (docs/SCENE_FORMAT.md) plus the meshes the file holds inline, which
// the JSON loader then loads like any candela scene (pbrt_scene_loader.h), and which
// `candela convert` writes out. What pbrt-v4 does that candela cannot is a located warning, one
// per kind of thing; what is wrong in the file is a located error, as pbrt-v4 would give it.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "candela/formats/curves/curve_file.h"
#include "candela/formats/mesh/mesh_store.h"
#include "candela/formats/pbrt/pbrt_location.h"

namespace candela::pbrt {

struct ImportedScene {
    nlohmann::ordered_json document;  // the candela scene; relative file names are relative to
                                      // the main .pbrt file's folder (pbrt-v4's rule)
    MeshStore meshes;                 // the meshes the document names that are not files
    CurveStore curves;                // the curves likewise (runs of Shape "curve")
    // Where the document's elements came from: JSON pointer -> location in the pbrt files.
    std::vector<std::pair<std::string, Location>> origins;
    std::vector<std::string> warnings;  // located, one line each
};

// Parses `file` (and what it includes) and translates it. Throws SceneError on bad input.
ImportedScene import_pbrt_file(const std::filesystem::path& file);
// The same for text in memory named `name` (tests, fuzzing).
ImportedScene import_pbrt_string(std::string_view text, const std::filesystem::path& name);

}  // namespace candela::pbrt
