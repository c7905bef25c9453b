#pragma once
// How next-event estimation picks one light among many.

namespace candela {

// kPower: probability proportional to emitted power (pbrt's PowerLightSampler); kUniform: equal;
// kBvh: by importance at the point lit (pbrt-v4's BVHLightSampler, light_bvh.h).
enum class LightSelection { kPower, kUniform, kBvh };

}  // namespace candela
