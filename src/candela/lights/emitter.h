#pragma once
// What every kind of area emitter provides (meshes and spheres; lights/area_light.h holds the
// closed set), checked at each emitter's definition (STYLE.md). An emitter knows only its geometry:
// radiance, sidedness and light selection live in AreaLight and LightSet.
#include <cmath>
#include <concepts>
#include <optional>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// A point sampled on one emitter, seen from a reference point.
struct EmitterSample {
    Vec3f p;           // on the surface (world)
    Vec3f n;           // unit geometric normal of the front side at p
    Vec3f wi;          // unit direction from the reference point towards p
    float pdf = 0.0f;  // per unit solid angle at the reference point, given this emitter
};

template <class T>
concept EmitterType = requires(const T& e, Vec3f ref, Vec2f u, Vec3f p, Vec3f n) {
    // A point seen from ref, from u (which also makes any discrete choice, e.g. the triangle);
    // nullopt when its pdf would be 0 or infinite (ref in the plane of the chosen triangle).
    { e.sample(ref, u) } -> std::same_as<std::optional<EmitterSample>>;
    // The density per solid angle at ref with which sample() produces point p with normal n;
    // bit-identical to the pdf sample() returned for that point (MIS relies on it).
    { e.pdf(ref, p, n) } -> std::same_as<float>;
    // Surface area, for the power of the light.
    { e.area() } -> std::same_as<float>;
};

// A point p seen from ref: the density per solid angle there and the direction to it.
struct SolidAngleDensity {
    float pdf = 0.0f;
    Vec3f wi;  // unit, from ref towards p; (0, 0, 0) when they coincide
};

// An area density at point p (unit normal n) converted to a density per solid angle at ref,
// pdf_area * dist^2 / |cos theta_light| (0 when ref lies on p, infinite when ref is in the
// tangent plane), and the direction towards p from the same difference, so that a light sample
// takes one square root for both. In float: p - ref is a correctly rounded difference of two
// floats, so its relative error is 2^-24 however large the coordinates are (smallpt's 1e5) and
// however close the points; the products after it add a few roundings more. |cos| dist comes
// from d itself, not from the normalized direction, so it does not wait for the square root.
CANDELA_HD inline SolidAngleDensity solid_angle_density(float pdf_area, const Vec3f& ref, const Vec3f& p,
                                                        const Vec3f& n) {
    SolidAngleDensity s;
    Vec3f d = p - ref;
    float dist2 = dot(d, d);
    if (dist2 == 0.0f) return s;
    float dist = std::sqrt(dist2);
    s.wi = d * (1.0f / dist);
    float abs_cos_times_dist = std::abs(dot(n, d));  // |cos theta_light| * dist
    s.pdf = abs_cos_times_dist == 0.0f ? kInfinity : pdf_area * dist2 * (dist / abs_cos_times_dist);
    return s;
}

// The density alone (emitters' pdf()); bit-identical to solid_angle_density's.
CANDELA_HD inline float solid_angle_pdf(float pdf_area, const Vec3f& ref, const Vec3f& p, const Vec3f& n) {
    return solid_angle_density(pdf_area, ref, p, n).pdf;
}

}  // namespace candela
