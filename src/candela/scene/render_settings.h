#pragma once
// The integrator and sampler sections of the scene file.
#include <cstdint>
#include <optional>

#include "candela/lights/light_selection.h"
#include "candela/math/constants.h"
#include "candela/sampling/sampler.h"

namespace candela {

// The largest camera resolution (each side) and samples per pixel a scene may ask for: the scene
// loader, the render job's overrides and the checkpoint reader share them.
inline constexpr int kMaxResolution = 32768;
inline constexpr int kMaxSpp = 1 << 24;

// path: next-event estimation + BSDF sampling with MIS (the default). bsdf: BSDF sampling only
// (smallpt's estimator). whitted: direct light + perfect specular recursion. The rest are debug
// views of the first hit.
// Appended only: checkpoints record the value.
enum class IntegratorType { kPath, kBsdf, kWhitted, kNormals, kDepth, kAlbedo, kAo, kVolPath };

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

// sampler.adaptive (render/adaptive_sampling.h): after min_spp samples, a block of pixels whose
// estimated relative error is below the threshold receives no more samples.
struct AdaptiveSettings {
    float threshold = 0.01f;  // relative standard error, sqrt of the pixel's estimated relMSE
    int min_spp = 16;         // samples every pixel takes before the first decision (>= 2)
    bool operator==(const AdaptiveSettings&) const = default;
};

struct SamplerSettings {
    SamplerType type = SamplerType::kSobol;  // the faster to a given error (bench/RESULTS.md)
    int spp = 16;                            // with adaptive sampling: the most a pixel takes
    uint64_t seed = 0;
    std::optional<AdaptiveSettings> adaptive;  // none: every pixel takes spp samples
};

}  // namespace candela
