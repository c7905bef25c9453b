#pragma once
// The environment light: radiance arriving from infinitely far away, from an equirectangular map
// (or a constant colour as a 1x1 map). Direction convention (Mitsuba 3's, DESIGN.md): in the
// light's frame +Y is up; for a unit direction d, u = atan2(d.x, -d.z) / 2pi (wrapped to [0, 1)),
// v = acos(d.y) / pi, v = 0 the top row. `to_world` takes the light's frame to the world; a world
// direction is looked up after applying its inverse. Lookups are bilinear.
// Sampling: importance sampling of a piecewise-constant 2D distribution over the texels weighted
// by luminance x sin(theta) (pdf per solid angle = pdf(u, v) / (2 pi^2 sin theta)), or uniform
// over the sphere (pdf 1 / 4pi) for comparison.
#include <cstddef>
#include <optional>

#include "candela/image/image.h"
#include "candela/math/color.h"
#include "candela/math/transform.h"
#include "candela/math/vec.h"
#include "candela/sampling/distribution_2d.h"

namespace candela {

enum class EnvironmentSampling { kImportance, kUniform };
enum class EnvironmentMapping { kEquirectangular, kEqualArea };
enum class EnvironmentFilter { kBilinear, kPoint };

struct EnvironmentSample {
    Vec3f wi;          // world direction towards the light (unit)
    Rgb Le;            // radiance arriving from wi (scale applied)
    float pdf = 0.0f;  // per unit solid angle (light selection NOT included)
};

class EnvironmentLight {
  public:
    // An equal-area map must be square.
    EnvironmentLight(const Image& radiance, float scale, const Transform& to_world, EnvironmentSampling sampling,
                     EnvironmentMapping mapping = EnvironmentMapping::kEquirectangular,
                     EnvironmentFilter filter = EnvironmentFilter::kBilinear);

    // Radiance arriving from world direction w (unit), i.e. travelling along -w; scale applied.
    Rgb radiance(const Vec3f& w) const;
    // A direction sampled with u; nullopt only if the map is black everywhere (or pdf 0).
    std::optional<EnvironmentSample> sample(const Vec2f& u) const;
    // The density per solid angle with which sample() produces world direction w.
    float pdf(const Vec3f& w) const;
    // Estimated power for light selection: pi r^2 x the mean luminance of the map over the
    // sphere (solid-angle weighted), r the scene's bounding-sphere radius.
    float power(float scene_radius) const;
    // Bytes held by the sampling tables (0 for uniform sampling), for memory budgets.
    size_t sampling_memory_bytes() const { return distribution_.memory_bytes(); }

  private:
    // The direction of the light's frame towards world direction w, normalised.
    Vec3f to_light(const Vec3f& w) const;
    // The map at light-frame direction d (unit), scale not applied.
    Rgb lookup(const Vec3f& d) const;
    // The equal-area map's mean and sampling tables (the constructor's part for that mapping).
    void init_equal_area();
    // pdf() for a light-frame direction d (unit).
    float pdf_local(const Vec3f& d) const;

    Image map_;
    float scale_ = 1.0f;
    Transform to_world_;
    Transform to_light_;  // to_world_'s inverse
    EnvironmentSampling sampling_ = EnvironmentSampling::kImportance;
    EnvironmentMapping mapping_ = EnvironmentMapping::kEquirectangular;
    EnvironmentFilter filter_ = EnvironmentFilter::kBilinear;
    Distribution2D distribution_;  // over (u, v); empty with uniform sampling
    double mean_luminance_ = 0.0;  // over the sphere, solid-angle weighted, scale not applied
};

// The illuminance (luminance-weighted irradiance, scale 1) that `map`, looked up as the light
// looks it up, gives a surface facing the light frame's up direction: +Z for the equal-area map
// (pbrt-v4's convention for its infinite light's `illuminance`), +Y for the equirectangular one.
// A 1x1 map (a constant) gives exactly pi x its luminance; larger maps are integrated by the
// midpoint rule on a grid of at least 1024 x 1024 points (each texel split evenly), so the
// value is the rendered map's to about 1e-5. 0 when the upper hemisphere is black.
double environment_up_illuminance(const Image& map, EnvironmentMapping mapping, EnvironmentFilter filter);

}  // namespace candela
