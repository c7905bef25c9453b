// libFuzzer target: Wavefront OBJ text through parse_obj (tinyobjloader and our mesh builder).
// A SceneError is the expected answer to bad input; anything else escaping, a crash, a sanitizer
// report or a mesh with dangling indices is a bug.
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/mesh/obj_loader.h"
#include "mesh_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        candela::fuzz::require_valid_mesh(candela::parse_obj(text, "fuzz.obj"));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
