#include "candela/lights/environment_light.h"

#include <cmath>
#include <vector>

#include "candela/core/check.h"
#include "candela/lights/equal_area_mapping.h"
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

// The bilinear lookup of an equirectangular map at (u, v). Texel centres sit at
// ((x + 0.5) / W, (y + 0.5) / H): wrap around in u, clamp in v.
Rgb equirectangular_bilinear(const Image& map, Vec2f uv) {
    float s = uv.x * static_cast<float>(map.width) - 0.5f;
    float t = uv.y * static_cast<float>(map.height) - 0.5f;
    float sf = std::floor(s), tf = std::floor(t);
    float fx = s - sf, fy = t - tf;
    int x0 = static_cast<int>(sf) % map.width;
    if (x0 < 0) x0 += map.width;
    int x1 = x0 + 1 == map.width ? 0 : x0 + 1;
    int y0 = clamp(static_cast<int>(tf), 0, map.height - 1);
    int y1 = clamp(static_cast<int>(tf) + 1, 0, map.height - 1);
    Rgb top = map.at(x0, y0) * (1.0f - fx) + map.at(x1, y0) * fx;
    Rgb bottom = map.at(x0, y1) * (1.0f - fx) + map.at(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

// The bilinear lookup of an equal-area map at (u, v): texels beyond an edge are the ones the
// fold of the square puts there (octahedral_wrap_texel).
Rgb equal_area_bilinear(const Image& map, Vec2f uv) {
    float s = uv.x * static_cast<float>(map.width) - 0.5f;
    float t = uv.y * static_cast<float>(map.height) - 0.5f;
    float sf = std::floor(s), tf = std::floor(t);
    float fx = s - sf, fy = t - tf;
    const int x = static_cast<int>(sf), y = static_cast<int>(tf);
    auto texel = [&](int tx, int ty) -> const Rgb& {
        octahedral_wrap_texel(tx, ty, map.width, map.height);
        return map.at(tx, ty);
    };
    Rgb top = texel(x, y) * (1.0f - fx) + texel(x + 1, y) * fx;
    Rgb bottom = texel(x, y + 1) * (1.0f - fx) + texel(x + 1, y + 1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

// The texel (u, v) falls in (u, v = 1 fall in the last column, row).
const Rgb& point_lookup(const Image& map, Vec2f uv) {
    int x = clamp(static_cast<int>(uv.x * static_cast<float>(map.width)), 0, map.width - 1);
    int y = clamp(static_cast<int>(uv.y * static_cast<float>(map.height)), 0, map.height - 1);
    return map.at(x, y);
}

Rgb lookup_uv(const Image& map, EnvironmentMapping mapping, EnvironmentFilter filter, Vec2f uv) {
    if (filter == EnvironmentFilter::kPoint) return point_lookup(map, uv);
    return mapping == EnvironmentMapping::kEqualArea ? equal_area_bilinear(map, uv) : equirectangular_bilinear(map, uv);
}

// (u, v) of a light-frame unit direction in the map's parametrization.
Vec2f map_uv(EnvironmentMapping mapping, const Vec3f& d) {
    return mapping == EnvironmentMapping::kEqualArea ? equal_area_sphere_to_square(d) : direction_to_uv(d);
}

}  // namespace

EnvironmentLight::EnvironmentLight(const Image& radiance, float scale, const Transform& to_world,
                                   EnvironmentSampling sampling, EnvironmentMapping mapping,
                                   EnvironmentFilter filter)
    : map_(radiance), scale_(scale), to_world_(to_world), to_light_(to_world.inverse()),
      sampling_(sampling), mapping_(mapping), filter_(filter) {
    CANDELA_CHECK(map_.width > 0 && map_.height > 0);
    CANDELA_CHECK(map_.pixels.size() == static_cast<size_t>(map_.width) * static_cast<size_t>(map_.height));
    const auto w = static_cast<size_t>(map_.width);
    const auto h = static_cast<size_t>(map_.height);
    if (mapping_ == EnvironmentMapping::kEqualArea) {
        CANDELA_CHECK(w == h);
        init_equal_area();
        return;
    }

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

void EnvironmentLight::init_equal_area() {
    // Every texel of an equal-area map covers the same solid angle, 4pi / (W H): the mean is the
    // plain mean, and the sampling weights need no Jacobian.
    std::vector<float> weights(map_.pixels.size());
    double sum = 0.0;
    for (size_t i = 0; i < weights.size(); ++i) {
        weights[i] = weight_luminance(map_.pixels[i]);
        sum += static_cast<double>(weights[i]);
    }
    mean_luminance_ = sum / static_cast<double>(weights.size());
    if (sampling_ == EnvironmentSampling::kImportance)
        distribution_ = Distribution2D(weights, map_.width, map_.height);
}

Rgb EnvironmentLight::lookup(const Vec3f& d) const {
    if (mapping_ == EnvironmentMapping::kEquirectangular && filter_ == EnvironmentFilter::kBilinear)
        return equirectangular_bilinear(map_, direction_to_uv(d));
    return lookup_uv(map_, mapping_, filter_, map_uv(mapping_, d));
}

Rgb EnvironmentLight::radiance(const Vec3f& w) const {
    return lookup(to_light(w)) * scale_;
}

float EnvironmentLight::pdf_local(const Vec3f& d) const {
    if (!(mean_luminance_ > 0.0)) return 0.0f;  // black everywhere: sample() never succeeds
    if (sampling_ == EnvironmentSampling::kUniform) return kInv4Pi;
    if (mapping_ == EnvironmentMapping::kEqualArea) {
        // The square's far edges (u or v = 1) belong to its last texels, as in point_lookup.
        Vec2f uv = equal_area_sphere_to_square(d);
        constexpr float kBelowOne = 0x1.fffffep-1f;
        return distribution_.pdf({std::min(uv.x, kBelowOne), std::min(uv.y, kBelowOne)}) * kInv4Pi;
    }
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
        Vec3f local = mapping_ == EnvironmentMapping::kEqualArea ? equal_area_square_to_sphere(uv.uv)
                                                                 : uv_to_direction(uv.uv);
        s.wi = normalize(to_world_.apply_vector(local));
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

double environment_up_illuminance(const Image& map, EnvironmentMapping mapping, EnvironmentFilter filter) {
    if (map.width <= 0 || map.height <= 0) return 0.0;
    // A constant field: E = integral over the hemisphere of L cos = pi L, exactly.
    if (map.width == 1 && map.height == 1) return kPiD * static_cast<double>(map.pixels[0].luminance());
    // The midpoint rule on a grid of n_x x n_y points, `split` per texel and axis, over the
    // lookups themselves (so a bilinear map is integrated as it is rendered).
    constexpr int kMinPoints = 1024;
    const int split = std::max(1, (kMinPoints + std::min(map.width, map.height) - 1) / std::min(map.width, map.height));
    const int nx = map.width * split, ny = map.height * split;
    double sum = 0.0;
    for (int j = 0; j < ny; ++j) {
        const float v = (static_cast<float>(j) + 0.5f) / static_cast<float>(ny);
        double row = 0.0;
        for (int i = 0; i < nx; ++i) {
            const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(nx);
            // The cosine to the up direction, and the solid angle per unit (u, v) up to a constant.
            float cos_up = 0.0f, jacobian = 1.0f;
            if (mapping == EnvironmentMapping::kEqualArea) {
                cos_up = equal_area_square_to_sphere({u, v}).z;
            } else {
                cos_up = std::cos(kPi * v);
                jacobian = std::sin(kPi * v);
            }
            if (!(cos_up > 0.0f)) continue;
            row += static_cast<double>(lookup_uv(map, mapping, filter, {u, v}).luminance() * cos_up * jacobian);
        }
        sum += row;
    }
    // Solid angle per grid point: 4pi / (n_x n_y) for the equal-area map, 2pi^2 sin(theta) /
    // (n_x n_y) for the equirectangular one (the sin is in the sum).
    const double per_point = (mapping == EnvironmentMapping::kEqualArea ? 4.0 * kPiD : 2.0 * kPiD * kPiD) /
                             (static_cast<double>(nx) * static_cast<double>(ny));
    return std::max(0.0, sum * per_point);
}

}  // namespace candela
