#pragma once
// Reading test fixtures from tests/data/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace candela::test {

// The bytes of tests/data/<relative>; a missing fixture fails the calling test.
inline std::string read_fixture(const std::string& relative) {
    const std::filesystem::path path = std::filesystem::path(CANDELA_TEST_DATA_DIR) / relative;
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in) << "missing fixture " << path;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace candela::test
