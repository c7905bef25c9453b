// libFuzzer target: PLY bytes through parse_ply, our own reader of the header and of the ascii,
// binary_little_endian and binary_big_endian data sections (the seeds have all three), and
// gzip-compressed ones (starting with gzip's magic number) through parse_ply_gz, as .ply.gz files
// are read. A SceneError is the expected answer to bad input; anything else is a bug.
#include <cstdint>
#include <string_view>

#include "candela/core/error.h"
#include "candela/formats/mesh/gzip_stream.h"
#include "candela/formats/mesh/ply_gz_loader.h"
#include "candela/formats/mesh/ply_loader.h"
#include "mesh_invariants.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        if (candela::is_gzip(bytes))
            candela::fuzz::require_valid_mesh(candela::parse_ply_gz(bytes, "fuzz.ply.gz"));
        else
            candela::fuzz::require_valid_mesh(candela::parse_ply(bytes, "fuzz.ply"));
    } catch (const candela::SceneError&) {
    }
    return 0;
}
