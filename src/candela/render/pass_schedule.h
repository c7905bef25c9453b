#pragma once
// The size of rendering passes. A pass takes samples [begin, end) of every pixel; passes do not
// change the image (each pixel still sums its samples in index order), only how often a render
// can stop, checkpoint or meet a deadline. Passes start at one sample per pixel (a first image
// soon, little lost to an early stop) and grow, at most doubling, until one lasts about
// `target_seconds` at the rate the previous pass measured.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace candela {

struct PassTiming {
    uint32_t spp = 0;      // samples per pixel of the previous pass; 0 before the first
    double seconds = 0.0;  // how long it took
};

// The next pass's samples per pixel, at most `remaining` (> 0). With `seconds_left` before a
// deadline, no more than the measured rate fits into it; 0 when not even one sample per pixel
// fits, meaning: stop now. `fixed_spp` > 0 gives passes of that size instead (for tests).
inline uint32_t next_pass_spp(PassTiming previous, uint32_t remaining, double target_seconds,
                              std::optional<double> seconds_left, uint32_t fixed_spp = 0) {
    if (fixed_spp > 0) return std::min(fixed_spp, remaining);
    if (previous.spp == 0) return std::min(1u, remaining);
    const double per_spp = previous.seconds / double(previous.spp);
    // How many samples per pixel fit into `seconds` at that rate (a lot when the rate is ~0).
    auto fitting = [&](double seconds) {
        double n = per_spp > 0.0 ? std::floor(seconds / per_spp) : double(remaining);
        return uint32_t(std::clamp(n, 0.0, double(remaining)));
    };
    const uint32_t doubled = uint32_t(std::min<uint64_t>(2ull * previous.spp, remaining));
    uint32_t next = std::min(std::max(fitting(target_seconds), 1u), doubled);
    if (seconds_left) next = std::min(next, fitting(*seconds_left));
    return next;
}

}  // namespace candela
