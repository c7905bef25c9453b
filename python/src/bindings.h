#pragma once
// What the extension's files share: the scene as Python holds it, and each file's bindings.
// The extension is as thin as the CLI: scenes load through formats/ (scene_file.h, the pbrt-v4
// importer), renders run through the render job (render/job/job.h), images go through image/.
#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "candela/formats/json/scene_loader.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/scene/scene.h"

namespace candela::python {

namespace py = pybind11;

// A scene document and what loading it needs besides: candela.Scene. Immutable: an edit is a new
// document (Scene.from_dict), so a render always loads what the object shows.
struct SceneDocument {
    // Names the scene in errors (empty for a dict); relative file names resolve against its folder.
    std::filesystem::path file;
    nlohmann::ordered_json document;
    // The file's own text while the document is the file's: the scene then loads exactly as the
    // CLI loads it, and errors point at its lines. Empty for an edited document.
    std::optional<std::string> text;
    // A pbrt-v4 scene: the importer's meshes and curves held in memory (the document names them
    // as files) and where each element came from, for errors in the pbrt files.
    std::shared_ptr<const pbrt::ImportedScene> imported;

    // Loads it into a renderable Scene (SceneError with a location on bad input).
    Scene load(const LoadOptions& options) const;
};

// nlohmann::ordered_json <-> Python's dict, list, str, float, int, bool, None (and numpy arrays and
// scalars, by their tolist()). Throws TypeError naming the JSON pointer of a value it cannot hold.
py::object to_python(const nlohmann::ordered_json& value);
nlohmann::ordered_json from_python(py::handle value, const std::string& pointer = "");

void bind_errors(py::module_& m);
void bind_scene(py::module_& m);
void bind_render(py::module_& m);
void bind_images(py::module_& m);

}  // namespace candela::python
