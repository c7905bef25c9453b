#pragma once
// How next-event estimation picks one light among many.

namespace candela {

// kPower: probability proportional to emitted power (pbrt's PowerLightSampler); kUniform: equal.
enum class LightSelection { kPower, kUniform };

}  // namespace candela
