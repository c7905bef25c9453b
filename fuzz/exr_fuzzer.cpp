// libFuzzer target: OpenEXR files through read_image (image/exr_file.cpp over Debian's OpenEXR).
// The library is not instrumented, so coverage comes from our side only and ASan sees its
// allocations but not its out-of-bounds reads (docs/RELIABILITY.md); crashes and hangs inside it
// still count. A SceneError is the expected answer to bad input.
#include <cstdint>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static candela::fuzz::ScratchFile file(".exr");
    try {
        candela::fuzz::require_valid_image(candela::read_image(file.write(data, size)));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
