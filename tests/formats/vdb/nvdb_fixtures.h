#pragma once
// The .nvdb fixtures of tests/data/vdb/, which are kept gzip-compressed (a NanoVDB file is mostly
// the zeros of its node tables: 300 KB that compress to 1 KB): inflated into the build tree on
// first use. The values they hold are listed in tests/data/vdb/README.md.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "candela/formats/mesh/gzip_stream.h"
#include "support/test_files.h"

namespace candela::test {

// CANDELA_TEST_BINARY_DIR/vdb_fixtures/NAME, inflated from tests/data/vdb/NAME.gz.
inline std::filesystem::path nvdb_fixture(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / "vdb_fixtures";
    std::filesystem::create_directories(dir);
    const std::filesystem::path out = dir / name;
    const std::filesystem::path gz = std::filesystem::path(CANDELA_TEST_DATA_DIR) / "vdb" / (name + ".gz");
    const std::string compressed = read_bytes(gz);
    std::string bytes;
    GzipStream(compressed, gz.string()).inflate_rest(bytes);
    // Written aside and renamed into place: ctest runs the tests of one binary in parallel
    // processes, which may inflate the same fixture at once.
    const std::filesystem::path part = dir / (name + "." + std::to_string(::getpid()) + ".part");
    std::ofstream(part, std::ios::binary | std::ios::trunc) << bytes;
    std::filesystem::rename(part, out);
    return out;
}

}  // namespace candela::test
