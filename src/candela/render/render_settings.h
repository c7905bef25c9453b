#pragma once
// The integrator and sampler sections of the scene file.
#include <cstdint>

#include "candela/math/constants.h"

namespace candela {

enum class IntegratorType { kNormals, kDepth, kAlbedo, kAo };

struct IntegratorSettings {
    IntegratorType type = IntegratorType::kAo;
    int max_depth = 64;
    int rr_depth = 3;
    float max_distance = kInfinity;  // `ao`: occluders farther than this do not count
};

struct SamplerSettings {
    int spp = 16;
    uint64_t seed = 0;
};

}  // namespace candela
