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
static_assert(std::variant_size_v<BsdfLobe> == 4, "add the new lobe to kLobeCases");

struct LobeCase {
    const char* name;
    BsdfLobe lobe;
};

inline const std::array<LobeCase, 8> kLobeCases = {{
    {"lambertian", LambertianLobe{Rgb(0.8f, 0.5f, 0.2f)}},
    {"lambertian_white", LambertianLobe{Rgb(1.0f)}},
    {"mirror", SpecularReflectionLobe{Rgb(0.9f, 0.6f, 0.3f)}},
    {"dielectric_exact", FresnelSpecularLobe{Rgb(1.0f, 0.9f, 0.8f), 1.5f, false}},
    {"dielectric_schlick", FresnelSpecularLobe{Rgb(1.0f), 1.5f, true}},
    {"dielectric_below_one", FresnelSpecularLobe{Rgb(1.0f), 1.0f / 1.33f, false}},
    {"transmission", SpecularTransmissionLobe{Rgb(0.7f, 0.8f, 0.9f), 1.5f}},
    {"transmission_diamond", SpecularTransmissionLobe{Rgb(1.0f), 2.4f}},
}};

// The unit direction at polar cosine cos_theta and azimuth phi (local frame, z = normal).
inline Vec3f direction(float cos_theta, float phi) {
    float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Outgoing directions on both sides, from normal to grazing (cos theta = +-0.001).
inline std::vector<Vec3f> probe_directions() {
    std::vector<Vec3f> out;
    for (float c : {1.0f, 0.9f, 0.6f, 0.3f, 0.1f, 0.001f})
        for (float sign : {1.0f, -1.0f}) out.push_back(direction(sign * c, 0.4f + 2.0f * c));
    return out;
}

}  // namespace candela::test
