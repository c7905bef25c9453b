#pragma once
// What the fuzz targets share: a scratch file for readers that take a path, and invariant checks
// that turn a wrong result into a crash libFuzzer reports (an expected SceneError is not one).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace candela::fuzz {

// Aborts with a message when a property every successful load must have does not hold.
inline void require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "fuzz: invariant violated: %s\n", what);
    std::abort();
}

// One file per process (the pid keeps parallel fuzzers apart) with a fixed extension, rewritten
// for every input; in /dev/shm when there is one, so that no input touches the disk.
class ScratchFile {
  public:
    explicit ScratchFile(std::string_view extension) {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path folder = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
        path_ = folder / ("candela-fuzz-" + std::to_string(::getpid()) + std::string(extension));
    }
    ~ScratchFile() {
        std::error_code ec;
        std::filesystem::remove(path_, ec);
    }
    ScratchFile(const ScratchFile&) = delete;
    ScratchFile& operator=(const ScratchFile&) = delete;

    const std::filesystem::path& write(const uint8_t* data, size_t size) {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        out.close();
        require(bool(out), "the scratch file could be written");
        return path_;
    }

  private:
    std::filesystem::path path_;
};

}  // namespace candela::fuzz
