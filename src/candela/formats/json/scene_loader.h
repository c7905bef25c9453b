#pragma once
// Loads a scene file (JSON, scene format v1: docs/SCENE_FORMAT.md) into a Scene: validates every
// key, loads the meshes and environment images it names, and moves geometry to world space. Any
// problem throws SceneError located as "file:line:col: /json/pointer: message"; unknown keys are
// errors, with a "did you mean" for near misses.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/curves/curve_file.h"
#include "candela/formats/mesh/mesh_store.h"
#include "candela/scene/memory_budget.h"
#include "candela/scene/scene.h"

namespace candela {

struct LoadOptions {
    // What the scene may need in memory to render (film, meshes with their BVH, environment),
    // checked as it loads, before each large allocation; by default what this process can have.
    std::optional<MemoryLimit> memory_limit;
    // Meshes by the `file` names the scene gives them, looked up before the disk (mesh_store.h).
    const MeshStore* meshes = nullptr;
    // Curves likewise (formats/curves/curve_file.h).
    const CurveStore* curves = nullptr;
    // For a scene translated from another file (a pbrt-v4 scene): where the element at a JSON
    // pointer came from, so that errors point into that file; nullopt for "unknown here".
    std::function<std::optional<SourceLocation>(const std::string& pointer)> source_map;
    // Charge the film (and the adaptive sampler's statistics) at the scene's resolution. False
    // when the caller renders at a resolution it sets after loading (a render job's --resolution,
    // a checkpoint's): it then checks the whole scene once that is set (memory_refusal).
    bool charge_film = true;
};

// A scene file's text, as load_scene reads it (the Python module keeps it, so that a scene loaded
// from a file reports errors at its lines). Throws SceneError naming a missing or unreadable file.
std::string read_text_file(const std::filesystem::path& file);

// Reads and loads `file`; the location of errors names it as given. Throws SceneError for a
// missing or unreadable file as well, and for a scene that needs more memory than the limit.
// Problems with a documented fallback (degenerate triangles skipped, a light that emits nothing,
// no light at all) are not errors: they load and add a line to Scene::warnings.
Scene load_scene(const std::filesystem::path& file, const LoadOptions& options = {});

// Loads a scene from JSON text. `file` is the name errors show and the folder relative `file`
// keys of meshes and images are resolved against (its parent); it need not exist.
Scene load_scene_from_string(std::string_view json, const std::filesystem::path& file,
                             const LoadOptions& options = {});

}  // namespace candela
