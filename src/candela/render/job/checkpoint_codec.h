#pragma once
// The byte-level pieces that checkpoint files (checkpoint.h, format versions 1 and 2) and shard
// part files (shard_part.h, format version 3) share: little-endian encoding, the common header,
// checked reads and the checksummed, atomic write. Internal to render/: the formats are
// documented in checkpoint.h and shard_part.h.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "candela/render/job/checkpoint.h"
#include "candela/scene/render_settings.h"

namespace candela::checkpoint_codec {

inline constexpr std::string_view kMagic = "CNDLCKPT";
inline constexpr uint32_t kFormatVersion = 1;
inline constexpr uint32_t kWeightedFormatVersion = 2;  // with weight sums
inline constexpr uint32_t kPartFormatVersion = 3;      // a shard's part
inline constexpr uint32_t kFilmValuesFormatVersion = 4;  // a film that describes its values (AOVs, statistics)
// Version 4's film-values word (and a part file's film flags): bit 0 weight sums, bit 1 adaptive
// sampling's statistics (film.h; checkpoints only), bit 2 (checkpoints only, always with bit 1)
// statistics with each pixel's rays and prefix sums (Film::kStatisticsValues = 13; the first
// builds with statistics kept 4 values and did not set it), bits kAovFlagShift.. the AovLayers mask.
inline constexpr uint32_t kWeightedFlag = 1u;
inline constexpr uint32_t kStatisticsFlag = 2u;
inline constexpr uint32_t kStatisticsV2Flag = 4u;
inline constexpr uint32_t kAovFlagShift = 8;
inline constexpr uint32_t kMaxString = 64;
// The longest common header: magic, format version, three names of kMaxString bytes, hash, seed,
// width, height, samples done, dropped samples.
inline constexpr uint64_t kMaxCommonHeaderBytes = 8 + 4 + 3 * (4 + kMaxString) + 8 + 8 + 4 + 4 + 4 + 8;

// Throws SceneError naming `file`.
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& message);

// Little-endian encoding into a byte string.
class Writer {
  public:
    void u32(uint32_t v) { bytes(v, 4); }
    void u64(uint64_t v) { bytes(v, 8); }
    void f64(double v);
    void string(std::string_view s) {
        u32(uint32_t(s.size()));
        out.append(s);
    }
    std::string out;

  private:
    void bytes(uint64_t v, int n) {
        for (int i = 0; i < n; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
    }
};

// Little-endian decoding. Reading past the end, or a string longer than kMaxString, fails the
// reader: it then returns zeros and empty strings, and says why once the header is read.
class Reader {
  public:
    explicit Reader(std::string_view data) : data_(data) {}
    uint32_t u32() { return uint32_t(bytes(4)); }
    uint64_t u64() { return bytes(8); }
    double f64();
    std::string string();
    bool truncated() const { return truncated_; }
    bool overlong() const { return overlong_; }
    size_t position() const { return at_; }

  private:
    uint64_t bytes(size_t n);
    std::string fail_string() {
        truncated_ = !overlong_;
        return {};
    }
    std::string_view data_;
    size_t at_ = 0;
    bool truncated_ = false;
    bool overlong_ = false;
};

// The identity's names and numbers up to its resolution, in file order: the common header's, and
// what rank 0 sends the other ranks of a resumed MPI job (render/job/job_files.cpp).
void write_identity_start(Writer& w, const RenderIdentity& identity);
void read_identity_start(Reader& r, RenderIdentity& identity);

// Writes the header every format starts with: magic, format version, identity (its width and
// height are the film's), samples done, dropped samples.
void write_common_header(Writer& w, uint32_t format, const RenderIdentity& identity, uint32_t samples_done,
                         uint64_t dropped_samples);

// What the common header says.
struct CommonHeader {
    uint32_t format = 0;  // 1 to 4
    RenderIdentity identity;
    uint32_t samples_done = 0;
    uint64_t dropped_samples = 0;
};

// Reads the common header from `r`, over the start of a file of `size` bytes that begins with
// the magic (checked by read_file_start). A format other than 1..4, a truncated or overlong
// header, or an impossible resolution throws SceneError naming `file`.
CommonHeader read_common_header(const std::filesystem::path& file, Reader& r, uint64_t size);

// The file's size, after checking that it is a readable file.
uint64_t file_size_of(const std::filesystem::path& file);
// The first `size` bytes of the file.
std::string read_bytes(const std::filesystem::path& file, uint64_t size);
// The first min(size, `bytes`) bytes of a file of `size` bytes, after checking that they start
// with the magic (an empty, foreign or truncated-in-the-magic file throws SceneError).
std::string read_file_start(const std::filesystem::path& file, uint64_t size, uint64_t bytes);
// Throws SceneError naming `file` unless the last 8 bytes of `data` are the checksum of the rest.
void check_checksum(const std::filesystem::path& file, std::string_view data);

// Writes `file` atomically: the bytes in `w`, then those `body` appends to `w` (it calls
// `flush` now and then, so that large bodies are written in blocks), then the checksum.
void write_checksummed(const std::filesystem::path& file, Writer& w,
                       const std::function<void(Writer& w, const std::function<void()>& flush)>& body);

}  // namespace candela::checkpoint_codec
