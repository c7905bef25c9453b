#pragma once
// The Henyey-Greenstein phase function (Henyey & Greenstein 1941): the phase function of
// participating media (media/) and of the medium between a layered lobe's interfaces
// (materials/layered.h). Both directions point away from the scattering
// point, as wo and wi of a BSDF do (pbrt-v4's convention), so light travelling along -wo that
// keeps its direction leaves along wi = -wo, where cos = dot(wo, wi) = -1:
//   p(wo, wi) = (1 - g^2) / (4 pi (1 + g^2 + 2 g dot(wo, wi))^(3/2))
// g > 0 scatters forward, g < 0 backward, g = 0 is isotropic; p integrates to 1 over the sphere.
// g is clamped to [-0.99, 0.99], where float evaluation and sampling stay stable (pbrt-v4 does
// the same).
#include <optional>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/frame.h"
#include "candela/math/vec.h"

namespace candela {

// p as a function of cos = dot(wo, wi), per steradian.
CANDELA_HD inline float henyey_greenstein(float cos_theta, float g) {
    g = clamp(g, -0.99f, 0.99f);
    float denom = 1.0f + g * g + 2.0f * g * cos_theta;
    return kInv4Pi * (1.0f - g * g) / (denom * safe_sqrt(denom));
}

struct PhaseSample {
    Vec3f wi;   // unit, pointing away from the scattering point
    float p;    // the phase function's value, equal to its density (it is its own pdf)
};

// Draws wi from p(wo, .) by inverting the distribution of cos = dot(wo, wi) (its CDF in closed
// form; isotropic below |g| = 1e-3, where the closed form cancels) and a uniform azimuth about wo.
CANDELA_HD inline PhaseSample sample_henyey_greenstein(const Vec3f& wo, float g, const Vec2f& u) {
    g = clamp(g, -0.99f, 0.99f);
    float cos_theta;
    if (std::abs(g) < 1e-3f) {
        cos_theta = 1.0f - 2.0f * u.x;
    } else {
        float s = (1.0f - g * g) / (1.0f + g - 2.0f * g * u.x);
        cos_theta = clamp(-(1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
    }
    float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    float phi = 2.0f * kPi * u.y;
    Frame frame = Frame::from_normal(wo);
    Vec3f wi = frame.to_world(Vec3f(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
    return {wi, henyey_greenstein(cos_theta, g)};
}

}  // namespace candela
