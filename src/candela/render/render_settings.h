#pragma once
// The integrator and sampler sections of the scene file.
#include <cstdint>

#include "candela/lights/light_selection.h"
#include "candela/math/constants.h"
#include "candela/sampling/sampler.h"

namespace candela {

// path: next-event estimation + BSDF sampling with MIS (the default). bsdf: BSDF sampling only
// (smallpt's estimator). whitted: direct light + perfect specular recursion. The rest are debug
// views of the first hit.
enum class IntegratorType { kPath, kBsdf, kWhitted, kNormals, kDepth, kAlbedo, kAo };

struct IntegratorSettings {
    IntegratorType type = IntegratorType::kPath;
    int max_depth = 64;               // longest path, in bounces (path, bsdf, whitted)
    int rr_depth = 3;                 // bounces before Russian roulette may end a path
    float rr_probability = 0.0f;      // fixed survival probability (GAMES101: 0.8); 0: by throughput
    bool mis = true;                  // path: weight light and BSDF sampling by the power heuristic;
                                      // false: NEE only (emission found by BSDF rays ignored)
    LightSelection light_selection = LightSelection::kPower;
    float max_distance = kInfinity;   // `ao`: occluders farther than this do not count
    bool spectral = false;            // transport four wavelengths per path (path, bsdf, whitted)
};

struct SamplerSettings {
    SamplerType type = SamplerType::kSobol;  // the faster to a given error (bench/RESULTS.md)
    int spp = 16;
    uint64_t seed = 0;
};

}  // namespace candela
