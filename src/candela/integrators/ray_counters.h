#pragma once
// Rays traced, by kind, for the summary line and benchmarks. Each render thread keeps its own and
// they are summed at the end, so counting costs no synchronisation.
#include <cstdint>

namespace candela {

struct RayCounters {
    uint64_t camera = 0;  // primary rays
    uint64_t bounce = 0;  // closest-hit rays after the first
    uint64_t shadow = 0;  // occlusion queries

    uint64_t total() const { return camera + bounce + shadow; }
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        bounce += o.bounce;
        shadow += o.shadow;
        return *this;
    }
};

}  // namespace candela
