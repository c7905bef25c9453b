#pragma once
// Helpers shared by the scene loader's tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <string_view>

#include "candela/core/error.h"
#include "candela/scene/scene_loader.h"

namespace candela::test {

inline std::filesystem::path scenes_dir() {
    return std::filesystem::path(CANDELA_TEST_DATA_DIR) / "scenes";
}

// Loads JSON text as if it were the file data/scenes/inline.json, so relative paths find the
// fixtures next to it (meshes/triangle.obj, sky_2x1.hdr).
inline Scene load_json(std::string_view json) {
    return load_scene_from_string(json, scenes_dir() / "inline.json");
}

// The SceneError that loading `json` throws; the test fails when it loads.
inline SceneError load_error(std::string_view json) {
    try {
        load_json(json);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "expected a SceneError loading " << json;
    return SceneError(SourceLocation{}, "no error");
}

}  // namespace candela::test
