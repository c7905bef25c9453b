#pragma once
// The messages of an MPI render (distributed/mpi_renderer.h) as bytes: what travels between rank 0
// and the other ranks, and how many bytes per pixel that is. Plain C++, so that encoding and
// decoding are tested without MPI.
//
// Numbers are copied in the machine's own byte order: every rank runs the same candela build on
// the same architecture (a cluster's nodes), as they must anyway for the same bits.
//
// Worker to rank 0:
//   request  u8 kRequest, u32 tiles wanted
//   result   u8 kResult, u32 pass, u32 tile, u64 dropped samples, u64 x 3 rays (camera, bounce,
//            shadow) traced for the tile, f64 x values: the tile's pixels' values after the pass
//            (Film::read_region: 3 per pixel, 4 with weight sums)
//   stop     u8 kStop, i32 signal: this rank received SIGINT or SIGTERM
//   bye      u8 kBye, u64 x 3 rays traced by the rank in all (the summary line's count)
// Rank 0 to a worker:
//   assign   u8 kAssign, u32 pass, u32 first sample, u32 end sample, u8 has target scale, f64 the
//            scale (--target-error's allocation, render/error_allocation.h), u32 count, then per tile:
//            u32 tile, u8 has values, [f64 x values: the tile's start values]
//   end      u8 kEnd, i32 exit code: stop rendering, say bye, exit with this code
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "candela/integrators/ray_counters.h"

namespace candela {

enum class TileMessageType : uint8_t { kRequest = 1, kResult, kStop, kBye, kAssign, kEnd };

// A message being built, or being read (reading past the end fails the reader, never the program).
class MessageWriter {
  public:
    explicit MessageWriter(TileMessageType type) { u8(uint8_t(type)); }
    void u8(uint8_t v) { put(&v, 1); }
    void u32(uint32_t v) { put(&v, 4); }
    void i32(int32_t v) { put(&v, 4); }
    void u64(uint64_t v) { put(&v, 8); }
    void f64(double v) { put(&v, 8); }
    void rays(const RayCounters& r) {
        u64(r.camera);
        u64(r.bounce);
        u64(r.shadow);
    }
    // Appends `count` doubles (copied bytewise: the message has no alignment).
    void doubles(const double* values, size_t count) { put(values, count * sizeof(double)); }
    std::vector<unsigned char>& bytes() { return bytes_; }

  private:
    void put(const void* data, size_t n);
    std::vector<unsigned char> bytes_;
};

class MessageReader {
  public:
    explicit MessageReader(std::span<const unsigned char> bytes) : bytes_(bytes) {}
    std::optional<TileMessageType> type();
    uint8_t u8() { return get<uint8_t>(); }
    uint32_t u32() { return get<uint32_t>(); }
    int32_t i32() { return get<int32_t>(); }
    uint64_t u64() { return get<uint64_t>(); }
    double f64() { return get<double>(); }
    RayCounters rays() {
        RayCounters r;
        r.camera = u64();
        r.bounce = u64();
        r.shadow = u64();
        return r;
    }
    // `count` doubles copied out to `out` (an aligned buffer); false (and nothing copied) when
    // the message is shorter.
    bool doubles(double* out, size_t count);
    bool failed() const { return failed_; }
    bool at_end() const { return at_ == bytes_.size(); }

  private:
    template <class T>
    T get();
    std::span<const unsigned char> bytes_;
    size_t at_ = 0;
    bool failed_ = false;
};

}  // namespace candela
