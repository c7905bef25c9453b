#pragma once
// Helpers for the image tests: a scratch folder, whole-file reads and writes, test images.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "candela/image/image.h"

namespace candela::testing {

// A fresh, empty folder under the system's temporary directory for one test, removed with
// everything in it when the test ends.
class TempDir {
  public:
    TempDir() {
        static std::atomic<unsigned> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("candela-image-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    // The names of the folder's entries, sorted (temporary files start with a dot).
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

  private:
    std::filesystem::path path_;
};

inline void write_test_file(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string read_test_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return std::move(bytes).str();
}

// Every pixel different and no symmetry, so a flipped, mirrored or transposed image shows.
// Channels lie in [lo, hi].
inline Image pattern_image(int width, int height, float lo = 0.0f, float hi = 1.0f) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float r = (float(x) + 0.25f) / float(width);
            const float g = (float(y) + 0.75f) / float(height);
            const float b = float((x * 5 + y * 3) % 11) / 10.0f;
            image.at(x, y) = Rgb(lo + (hi - lo) * r, lo + (hi - lo) * g, lo + (hi - lo) * b);
        }
    }
    return image;
}

}  // namespace candela::testing
