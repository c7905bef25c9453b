#pragma once
// The wall-clock seconds since a steady-clock time point: a render's timings and time limits.
#include <chrono>

namespace candela {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace candela
