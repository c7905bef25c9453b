#pragma once
// The ray files that candela_record_rays writes and candela_trace_bound reads: the renderer's own
// queries in the order it made them. A 24-byte header, then `count` 36-byte records, in the
// machine's byte order (the files are scratch data in the build folder, never shared).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela::bench {

enum class RayKind : uint8_t { kCamera = 0, kBounce = 1, kShadow = 2 };
inline constexpr int kRayKindCount = 3;
inline constexpr const char* kRayKindNames[kRayKindCount] = {"camera", "bounce", "shadow"};

struct RecordedRay {
    float org[3];
    float tnear;
    float dir[3];
    float tfar;
    RayKind kind;
    uint8_t hit;  // 1: the renderer's query found a hit (intersect) or an occluder (shadow)
    uint8_t unused[2];
};
static_assert(sizeof(RecordedRay) == 36);

struct RayFileHeader {
    char magic[8];  // "CNDLRAYS"
    uint32_t version;
    uint32_t record_bytes;
    uint64_t count;
};
static_assert(sizeof(RayFileHeader) == 24);

inline constexpr char kRayFileMagic[8] = {'C', 'N', 'D', 'L', 'R', 'A', 'Y', 'S'};
inline constexpr uint32_t kRayFileVersion = 1;

inline void write_ray_file(const std::filesystem::path& file, const std::vector<RecordedRay>& rays) {
    RayFileHeader h{};
    std::memcpy(h.magic, kRayFileMagic, sizeof(h.magic));
    h.version = kRayFileVersion;
    h.record_bytes = sizeof(RecordedRay);
    h.count = rays.size();
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot create " + file.string());
    bool ok = std::fwrite(&h, sizeof(h), 1, f) == 1 &&
              std::fwrite(rays.data(), sizeof(RecordedRay), rays.size(), f) == rays.size();
    ok = (std::fclose(f) == 0) && ok;
    if (!ok) throw std::runtime_error("cannot write " + file.string());
}

inline std::vector<RecordedRay> read_ray_file(const std::filesystem::path& file) {
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) throw std::runtime_error("cannot open " + file.string());
    RayFileHeader h{};
    std::vector<RecordedRay> rays;
    bool ok = std::fread(&h, sizeof(h), 1, f) == 1 && std::memcmp(h.magic, kRayFileMagic, sizeof(h.magic)) == 0 &&
              h.version == kRayFileVersion && h.record_bytes == sizeof(RecordedRay);
    if (ok) {
        rays.resize(h.count);
        ok = std::fread(rays.data(), sizeof(RecordedRay), rays.size(), f) == rays.size();
    }
    std::fclose(f);
    if (!ok) throw std::runtime_error(file.string() + ": not a candela ray file (version 1), or truncated");
    return rays;
}

}  // namespace candela::bench
