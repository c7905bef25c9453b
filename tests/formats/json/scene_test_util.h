#pragma once
// Helpers shared by the scene loader's tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

#include "candela/core/error.h"
#include "candela/formats/json/scene_loader.h"

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

// A scene whose one material "m" is the JSON object `material`, and the error loading it throws.
inline Scene load_material(const std::string& material) {
    return load_json(R"({"materials": {"m": )" + material + "}}");
}
inline SceneError material_error(const std::string& material) {
    return load_error(R"({"materials": {"m": )" + material + "}}");
}

// The one lobe of material "m", as a T (the test fails if it is another lobe).
template <class T>
T only_lobe(const Scene& s) {
    const Bsdf& bsdf = s.materials.at(0).bsdf;
    EXPECT_EQ(bsdf.lobe_count, 1u);
    const T* lobe = std::get_if<T>(&bsdf.lobes[0]);
    EXPECT_NE(lobe, nullptr);
    return lobe != nullptr ? *lobe : T{};
}

}  // namespace candela::test
