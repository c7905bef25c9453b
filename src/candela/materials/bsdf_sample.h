#pragma once
// What sampling a BSDF returns, and the transport mode that decides how refraction scales.
#include "candela/math/color.h"
#include "candela/math/vec.h"

namespace candela {

// Radiance: paths traced from the camera (the path tracer). Importance: paths traced from lights
// (a later light tracer). Refraction compresses radiance by (eta_i / eta_t)^2 but not importance
// (Veach's thesis 5.2; pbrt's TransportMode).
enum class TransportMode { kRadiance, kImportance };

struct BsdfSample {
    Color f;               // BSDF value for (wo, wi), without the cosine; for delta lobes the
                         // value whose f |cos wi| / pdf is the lobe's weight (pbrt's convention)
    Vec3f wi;            // sampled incident direction, local shading frame, unit
    float pdf = 0.0f;    // per solid angle; for a delta lobe the discrete probability of the choice
    bool is_delta = false;
    bool is_transmission = false;  // wi on the other side of the surface than wo
    float eta = 1.0f;    // relative index of refraction eta_t / eta_i crossed; 1 for reflection
};

}  // namespace candela
