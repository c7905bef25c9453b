#pragma once
// Files in tests: a fresh, empty folder for one test case under the build tree, and a file's
// bytes (for comparing outputs byte for byte).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace candela::test {

// CANDELA_TEST_BINARY_DIR/NAME, emptied (created when missing).
inline std::filesystem::path fresh_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(CANDELA_TEST_BINARY_DIR) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// The file's bytes; empty when it cannot be read.
inline std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace candela::test
