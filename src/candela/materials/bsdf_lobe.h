#pragma once
// What every BSDF lobe provides, checked at each lobe's definition so a missing or mistyped
// method fails there and not deep inside visit (STYLE.md). All directions are unit vectors in the
// local shading frame (z = shading normal, pointing to the surface's front), wo and wi point away
// from the surface, and wo may lie on either side.
#include <concepts>
#include <optional>

#include "candela/materials/bsdf_sample.h"

namespace candela {

template <class T>
concept BsdfLobeType = requires(const T& lobe, Vec3f wo, Vec3f wi, float uc, Vec2f u,
                                TransportMode mode) {
    // f(wo, wi) without the cosine; 0 for a delta lobe (its f lives only in sample()).
    { lobe.eval(wo, wi, mode) } -> std::same_as<Color>;
    // Density of sample() per solid angle; 0 for a delta lobe.
    { lobe.pdf(wo, wi) } -> std::same_as<float>;
    // A direction wi for wo, from uc (a discrete choice inside the lobe) and u; nullopt when the
    // lobe sends nothing there (wo in the surface's plane, total internal reflection ...).
    { lobe.sample(wo, uc, u, mode) } -> std::same_as<std::optional<BsdfSample>>;
    // True when the lobe scatters into isolated directions only (mirror, smooth glass).
    { lobe.is_delta() } -> std::same_as<bool>;
    // Whether sample() reads uc. When no lobe of a BSDF does, the integrator need not compute
    // that random number (Sampler::skip_float keeps the later ones where they were).
    { T::kUsesChoice } -> std::convertible_to<bool>;
    // The lobe's colour for the `albedo` debug view: its reflectance or tint.
    { lobe.albedo() } -> std::same_as<Color>;
};

// cos(theta) of a local-frame direction, and whether two directions share a hemisphere.
CANDELA_HD inline float cos_theta(const Vec3f& w) { return w.z; }
CANDELA_HD inline float abs_cos_theta(const Vec3f& w) { return w.z < 0.0f ? -w.z : w.z; }
CANDELA_HD inline bool same_hemisphere(const Vec3f& a, const Vec3f& b) { return a.z * b.z > 0.0f; }

}  // namespace candela
