#include "candela/lights/environment_light.h"

#include <cmath>
#include <vector>

#include "candela/core/check.h"
#include "candela/math/constants.h"
#include "candela/sampling/warps.h"

namespace candela {
namespace {

// (u, v) of a light-frame unit direction, u wrapped to [0, 1), v in [0, 1].
Vec2f direction_to_uv(const Vec3f& d) {
    float u = std::atan2(d.x, -d.z) * kInv2Pi;
    if (u < 0.0f) u += 1.0f;
    if (!(u < 1.0f)) u = 0.0f;  // -tiny + 1 rounds to 1, which is u = 0 on the circle
    float v = std::acos(clamp(d.y, -1.0f, 1.0f)) * kInvPi;
    return {u, clamp(v, 0.0f, 1.0f)};
}

// The light-frame unit direction of (u, v): the inverse of direction_to_uv.
Vec3f uv_to_direction(Vec2f uv) {
    float phi = 2.0f * kPi * uv.x, theta = kPi * uv.y;
    float sin_theta = std::sin(theta);
    return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

// Luminance as a sampling weight or power term: negative or non-finite counts as 0.
float weight_luminance(const Rgb& c) {
    float l = c.luminance();
    return l > 0.0f && std::isfinite(l) ? l : 0.0f;
}

}  // namespace

EnvironmentLight::EnvironmentLight(const Image& radiance, float scale, const Transform& to_world,
                                   EnvironmentSampling sampling)
    : map_(radiance), scale_(scale), to_world_(to_world), to_light_(to_world.inverse()),
      sampling_(sampling) {
    CANDELA_CHECK(map_.width > 0 && map_.height > 0);
    CANDELA_CHECK(map_.pixels.size() == static_cast<size_t>(map_.width) * static_cast<size_t>(map_.height));
    const auto w = static_cast<size_t>(map_.width);
    const auto h = static_cast<size_t>(map_.height);

    // The mean over the sphere integrates each row over its exact solid angle
    // (cos theta0 - cos theta1) x 2pi / W, so a constant map has exactly its value as the mean
    // (a midpoint rule in theta would make a 1x1 map pi/2 too bright).
    double sum = 0.0;
    for (size_t y = 0; y < h; ++y) {
        double row = 0.0;
        for (size_t x = 0; x < w; ++x) row += static_cast<double>(weight_luminance(map_.pixels[y * w + x]));
        double band = std::cos(kPiD * static_cast<double>(y) / static_cast<double>(h)) -
                      std::cos(kPiD * static_cast<double>(y + 1) / static_cast<double>(h));
        sum += row * band;
    }
    mean_luminance_ = sum / (2.0 * static_cast<double>(w));

    if (sampling_ != EnvironmentSampling::kImportance) return;
    // Weights luminance x sin(theta at the texel centre): the sin converts the (u, v) density to
    // one per solid angle, so rows near the poles (small solid angle) are drawn less often.
    std::vector<float> weights(w * h);
    for (size_t y = 0; y < h; ++y) {
        auto sin_theta = static_cast<float>(
            std::sin(kPiD * (static_cast<double>(y) + 0.5) / static_cast<double>(h)));
        for (size_t x = 0; x < w; ++x) weights[y * w + x] = weight_luminance(map_.pixels[y * w + x]) * sin_theta;
    }
    distribution_ = Distribution2D(weights, map_.width, map_.height);
}

Vec3f EnvironmentLight::to_light(const Vec3f& w) const {
    return normalize(to_light_.apply_vector(w));
}

Rgb EnvironmentLight::lookup(const Vec3f& d) const {
    Vec2f uv = direction_to_uv(d);
    // Texel centres sit at ((x + 0.5) / W, (y + 0.5) / H): wrap around in u, clamp in v.
    float s = uv.x * static_cast<float>(map_.width) - 0.5f;
    float t = uv.y * static_cast<float>(map_.height) - 0.5f;
    float sf = std::floor(s), tf = std::floor(t);
    float fx = s - sf, fy = t - tf;
    int x0 = static_cast<int>(sf) % map_.width;
    if (x0 < 0) x0 += map_.width;
    int x1 = x0 + 1 == map_.width ? 0 : x0 + 1;
    int y0 = clamp(static_cast<int>(tf), 0, map_.height - 1);
    int y1 = clamp(static_cast<int>(tf) + 1, 0, map_.height - 1);
    Rgb top = map_.at(x0, y0) * (1.0f - fx) + map_.at(x1, y0) * fx;
    Rgb bottom = map_.at(x0, y1) * (1.0f - fx) + map_.at(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

Rgb EnvironmentLight::radiance(const Vec3f& w) const {
    return lookup(to_light(w)) * scale_;
}

float EnvironmentLight::pdf_local(const Vec3f& d) const {
    if (!(mean_luminance_ > 0.0)) return 0.0f;  // black everywhere: sample() never succeeds
    if (sampling_ == EnvironmentSampling::kUniform) return kInv4Pi;
    // sin(theta) from x and z rather than from v keeps its precision near the poles.
    float sin_theta = std::sqrt(d.x * d.x + d.z * d.z);
    if (!(sin_theta > 0.0f)) return 0.0f;
    return distribution_.pdf(direction_to_uv(d)) / (2.0f * kPi * kPi * sin_theta);
}

float EnvironmentLight::pdf(const Vec3f& w) const {
    return pdf_local(to_light(w));
}

std::optional<EnvironmentSample> EnvironmentLight::sample(const Vec2f& u) const {
    if (!(mean_luminance_ > 0.0)) return std::nullopt;
    EnvironmentSample s;
    if (sampling_ == EnvironmentSampling::kUniform) {
        // Uniform over the sphere is the same in every frame.
        s.wi = sample_uniform_sphere(u);
        s.pdf = kInv4Pi;
    } else {
        if (distribution_.empty()) return std::nullopt;
        Distribution2DSample uv = distribution_.sample(u);
        s.wi = normalize(to_world_.apply_vector(uv_to_direction(uv.uv)));
        // The density of the direction as pdf() computes it, so that sample() and pdf() agree
        // exactly even where rounding moves wi across a texel edge (or onto a pole).
        s.pdf = pdf(s.wi);
        if (!(s.pdf > 0.0f)) return std::nullopt;
    }
    s.Le = radiance(s.wi);
    return s;
}

float EnvironmentLight::power(float scene_radius) const {
    return static_cast<float>(kPiD * sqr(static_cast<double>(scene_radius)) * mean_luminance_ *
                              static_cast<double>(scale_));
}

}  // namespace candela
