// libFuzzer target: Radiance .hdr files through read_image, which reads them with our own RGBE
// decoder (image/rgbe_file.cpp). The input goes through a scratch file so that the whole path a
// scene's environment map takes is fuzzed. A SceneError is the expected answer to bad input.
#include <cstdint>

#include "candela/core/error.h"
#include "candela/image/image_io.h"
#include "image_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static candela::fuzz::ScratchFile file(".hdr");
    try {
        candela::fuzz::require_valid_image(candela::read_image(file.write(data, size)));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
