#pragma once
// Configured lobes covering every alternative of BsdfLobe, shared by the materials tests, and
// directions to probe them with.
#include <array>
#include <cmath>
#include <variant>
#include <vector>

#include "candela/materials/bsdf_lobes.h"

namespace candela::test {

// A new lobe type must be added to kLobeCases (and thereby to every test that runs over them).
static_assert(std::variant_size_v<BsdfLobe> == 11, "add the new lobe to kLobeCases");

// Lobes whose eval() and pdf() are stochastic estimates (materials/layered.h): sample() agrees
// with them in expectation only, which layered_stat_test.cpp checks; the generic tests check of
// them what holds sample by sample.
template <class T>
inline constexpr bool kIsLayered = kIsLayeredLobe<T>;

struct LobeCase {
    const char* name;
    BsdfLobe lobe;
};

// Gold's complex index at the sRGB primaries' dominant wavelengths, roughly (pbrt-v4's metal-Au).
inline const Color kGoldEta(0.143f, 0.374f, 1.442f);
inline const Color kGoldK(3.983f, 2.385f, 1.603f);

inline const std::array<LobeCase, 32> kLobeCases = {{
    {"lambertian", LambertianLobe{Color(0.8f, 0.5f, 0.2f)}},
    {"lambertian_white", LambertianLobe{Color(1.0f)}},
    {"mirror", SpecularReflectionLobe{Color(0.9f, 0.6f, 0.3f)}},
    {"dielectric_exact", FresnelSpecularLobe{Color(1.0f, 0.9f, 0.8f), 1.5f, false}},
    {"dielectric_schlick", FresnelSpecularLobe{Color(1.0f), 1.5f, true}},
    {"dielectric_below_one", FresnelSpecularLobe{Color(1.0f), 1.0f / 1.33f, false}},
    {"transmission", SpecularTransmissionLobe{Color(0.7f, 0.8f, 0.9f), 1.5f}},
    {"transmission_diamond", SpecularTransmissionLobe{Color(1.0f), 2.4f}},
    {"conductor_smooth", ConductorLobe{TrowbridgeReitz(0.0f), kGoldEta, kGoldK}},
    {"conductor_0.01", ConductorLobe{TrowbridgeReitz(0.01f), kGoldEta, kGoldK}},
    {"conductor_0.1", ConductorLobe{TrowbridgeReitz(0.1f), kGoldEta, kGoldK}},
    {"conductor_0.3", ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta, kGoldK}},
    {"conductor_0.8", ConductorLobe{TrowbridgeReitz(0.8f), kGoldEta, kGoldK}},
    {"conductor_anisotropic", ConductorLobe{TrowbridgeReitz(0.05f, 0.4f), kGoldEta, kGoldK}},
    {"dielectric_smooth", DielectricLobe{Color(1.0f, 0.9f, 0.8f), 1.5f, TrowbridgeReitz(0.0f)}},
    {"dielectric_0.1", DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.1f)}},
    {"dielectric_0.3", DielectricLobe{Color(1.0f, 0.9f, 0.8f), 1.5f, TrowbridgeReitz(0.3f)}},
    {"dielectric_below_one_0.1", DielectricLobe{Color(1.0f), 1.0f / 1.5f, TrowbridgeReitz(0.1f)}},
    {"dielectric_below_one_0.3", DielectricLobe{Color(1.0f), 1.0f / 1.5f, TrowbridgeReitz(0.3f)}},
    {"dielectric_anisotropic", DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.05f, 0.4f)}},
    {"thin_dielectric", ThinDielectricLobe{1.5f}},
    {"thin_dielectric_diamond", ThinDielectricLobe{2.4f}},
    // Coated lobes: coat, base, medium albedo, thickness, g, max depth, walks per eval.
    {"coated_diffuse_smooth", CoatedDiffuseLobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)},
                                                LambertianLobe{Color(0.7f, 0.3f, 0.2f)}, Color(0.0f),
                                                0.01f, 0.0f, 10, 1}},
    {"coated_diffuse_rough_medium", CoatedDiffuseLobe{CoatInterface{1.5f, TrowbridgeReitz(0.3f)},
                                                      LambertianLobe{Color(0.5f, 0.6f, 0.7f)},
                                                      Color(0.8f, 0.5f, 0.3f), 0.1f, 0.3f, 10, 2}},
    {"coated_conductor_smooth", CoatedConductorLobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)},
                                                    ConductorLobe{TrowbridgeReitz(0.0f), kGoldEta / 1.5f,
                                                                  kGoldK / 1.5f},
                                                    Color(0.0f), 0.01f, 0.0f, 10, 1}},
    {"coated_conductor_rough", CoatedConductorLobe{CoatInterface{1.5f, TrowbridgeReitz(0.1f)},
                                                   ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta / 1.5f,
                                                                 kGoldK / 1.5f},
                                                   Color(0.0f), 0.01f, 0.0f, 10, 1}},
    {"coated_conductor_anisotropic_medium",
     CoatedConductorLobe{CoatInterface{1.33f, TrowbridgeReitz(0.2f)},
                         ConductorLobe{TrowbridgeReitz(0.05f, 0.3f), kGoldEta / 1.33f, kGoldK / 1.33f},
                         Color(0.9f), 0.5f, -0.3f, 10, 1}},
    // Hair: offset h, eta, sigma_a, beta_m, beta_n, alpha (radians).
    {"hair_white", HairLobe::make(0.3f, 1.55f, Color(0.0f), 0.3f, 0.3f, 0.035f)},
    {"hair_brown", HairLobe::make(-0.7f, 1.55f, Color(0.54f, 0.91f, 1.78f), 0.5f, 0.4f, 0.035f)},
    // Diffuse transmission: pbrt-v4's default (0.25, 0.25); R + T = 1 (no loss); coloured, T = R / 2.
    {"diffuse_transmission", DiffuseTransmissionLobe{Color(0.25f), Color(0.25f)}},
    {"diffuse_transmission_lossless", DiffuseTransmissionLobe{Color(0.3f), Color(0.7f)}},
    {"diffuse_transmission_coloured", DiffuseTransmissionLobe{Color(0.6f, 0.4f, 0.2f), Color(0.3f, 0.2f, 0.1f)}},
}};

// The unit direction at polar cosine cos_theta and azimuth phi (local frame, z = normal).
inline Vec3f direction(float cos_theta, float phi) {
    float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Outgoing directions on both sides, from normal to grazing (cos theta = +-0.05, +-0.001).
inline std::vector<Vec3f> probe_directions() {
    std::vector<Vec3f> out;
    for (float c : {1.0f, 0.9f, 0.6f, 0.3f, 0.1f, 0.05f, 0.001f})
        for (float sign : {1.0f, -1.0f}) out.push_back(direction(sign * c, 0.4f + 2.0f * c));
    return out;
}

}  // namespace candela::test
