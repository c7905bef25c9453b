// libFuzzer target: pbrt-v4 scene text through the whole import, as `candela render scene.pbrt`
// loads it: the parser, the importer (pbrt-v4's semantics into a candela JSON document and
// meshes) and the JSON loader. The text is a file in tests/data/pbrt/, so Include, Import and the
// meshes and images named there resolve. A SceneError is the expected answer to bad input;
// anything else escaping (a nlohmann exception, std::out_of_range, bad_alloc), a crash, a
// sanitizer report or a scene that breaks the invariants of scene_invariants.h is a bug.
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/pbrt/pbrt_importer.h"
#include "candela/formats/pbrt/pbrt_scene_loader.h"
#include "scene_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr const char* kName = CANDELA_FUZZ_PBRT_DIR "/fuzz.pbrt";
    try {
        candela::fuzz::require_valid_scene(
            candela::pbrt::load_imported_scene(candela::pbrt::import_pbrt_string(text, kName), kName));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
