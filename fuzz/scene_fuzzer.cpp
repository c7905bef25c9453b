// libFuzzer target: JSON scene text through load_scene_from_string. The scene's virtual file lies
// in tests/data/scenes/, so the mesh and image files named there (meshes/triangle.obj,
// sky_2x1.hdr, ...) load as they would from a real scene. A SceneError is the expected answer to
// bad input; anything else escaping (a nlohmann exception, std::out_of_range, bad_alloc), a crash,
// a sanitizer report or a scene that breaks the invariants of scene_invariants.h is a bug.
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/json/scene_loader.h"
#include "scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        candela::fuzz::require_valid_scene(
            candela::load_scene_from_string(text, CANDELA_FUZZ_SCENE_DIR "/fuzz.json"));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
