#pragma once
// A sphere as an emitter. Seen from outside, it samples the cone of directions the sphere
// subtends, uniformly, and returns the visible point along the chosen direction: the density is
// the constant 1 / (2 pi (1 - cos theta_max)) with sin theta_max = r / d, much better than area
// sampling, which wastes half its samples on the hidden side. From inside, every point is
// visible: uniform by area, converted to solid angle.
//
// Points on the sphere itself (a path vertex on an emitting sphere, e.g. inside a furnace) are
// rounded to float and land on either side of it. From the inside they must not use the cone:
// seen from just outside, the visible cap is the outside, whose radiance is black for a sphere
// that emits inwards. So the cone is used only clearly outside, beyond a band of 1e-6 of the
// coordinates' magnitude (about 16 float roundings); area sampling is valid from anywhere, and
// pbrt-v4 does the same by offsetting the reference point towards the centre before this test.
//
// The geometry runs in double: smallpt's spheres have radius 1e5 with centres 1e5 away, and the
// point must land on the sphere (sphere.h). The front normal is the outward one unless
// reverse_orientation, exactly as hits report it (geometry/accelerator.cpp).
#include <cmath>
#include <optional>

#include "candela/core/platform.h"
#include "candela/geometry/sphere.h"
#include "candela/lights/emitter.h"
#include "candela/math/constants.h"
#include "candela/sampling/warps.h"

namespace candela {

struct SphereEmitter {
    Sphere sphere;

    // 4 pi r^2.
    CANDELA_HD float area() const { return static_cast<float>(4.0 * kPiD * sphere.radius * sphere.radius); }
    // A point the sphere shows to ref (u: the direction in the cone, or the point by area).
    CANDELA_HD std::optional<EmitterSample> sample(const Vec3f& ref, Vec2f u) const;
    // The cone density if ref is clearly outside the sphere (for any point p), else the area density
    // 1 / (4 pi r^2) converted at p.
    CANDELA_HD float pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const;
    // 1 - cos theta_max of the cone the sphere subtends from ref; 0 (sample by area) when ref is
    // inside, on the sphere or within rounding of it.
    CANDELA_HD double cone_one_minus_cos_max(const Vec3f& ref) const;

  private:
    // The front normal as hits compute it, from the unit outward normal.
    CANDELA_HD Vec3f front_normal(const Vec3d& n_out) const {
        return normalize(Vec3f(sphere.reverse_orientation ? -n_out : n_out));
    }
};
static_assert(EmitterType<SphereEmitter>);

CANDELA_HD inline double SphereEmitter::cone_one_minus_cos_max(const Vec3f& ref) const {
    Vec3d to_center = sphere.center - Vec3d(ref);
    double dc2 = dot(to_center, to_center);
    double r2 = sphere.radius * sphere.radius;
    double band = 1e-6 * (static_cast<double>(max_component(abs(ref))) + sphere.radius);
    if (dc2 <= sqr(sphere.radius + band)) return 0.0;
    // 1 - sqrt(1 - s) as s / (1 + sqrt(1 - s)): no cancellation for distant, narrow cones.
    double sin2_max = r2 / dc2;
    return sin2_max / (1.0 + safe_sqrt(1.0 - sin2_max));
}

CANDELA_HD inline float SphereEmitter::pdf(const Vec3f& ref, const Vec3f& p, const Vec3f& n) const {
    double one_minus_cos_max = cone_one_minus_cos_max(ref);
    if (one_minus_cos_max > 0.0) return static_cast<float>(1.0 / (2.0 * kPiD * one_minus_cos_max));
    return solid_angle_pdf(static_cast<float>(1.0 / (4.0 * kPiD * sphere.radius * sphere.radius)), ref, p, n);
}

CANDELA_HD inline std::optional<EmitterSample> SphereEmitter::sample(const Vec3f& ref, Vec2f u) const {
    const double r = sphere.radius;
    Vec3d n_out;  // unit outward normal at the sampled point
    double one_minus_cos_max = cone_one_minus_cos_max(ref);
    if (one_minus_cos_max > 0.0) {
        // pbrt-v4's Sphere::Sample(ctx, u) (Pharr et al., PBR 4th ed., 6.2.4): theta uniform in
        // the cone by 1 - cos theta, then the angle alpha at the centre between the direction to
        // ref and the visible point's normal, from the triangle (ref, centre, point):
        // cos alpha = sin^2 theta / sin theta_max + cos theta sqrt(1 - sin^2 theta / sin^2 theta_max).
        Vec3d to_center = sphere.center - Vec3d(ref);
        double dc2 = dot(to_center, to_center);
        Vec3d wc = to_center / std::sqrt(dc2);
        double sin2_max = r * r / dc2;
        double one_minus_cos = static_cast<double>(u.x) * one_minus_cos_max;
        double cos_theta = 1.0 - one_minus_cos;
        double sin2_theta = one_minus_cos * (2.0 - one_minus_cos);
        double cos_alpha =
            sin2_theta / std::sqrt(sin2_max) + cos_theta * safe_sqrt(1.0 - sin2_theta / sin2_max);
        double sin_alpha = safe_sqrt(1.0 - cos_alpha * cos_alpha);
        double phi = 2.0 * kPiD * static_cast<double>(u.y);
        // An orthonormal frame (s, t, -wc) (Duff et al. 2017), in double.
        Vec3d z = -wc;
        double sign = std::copysign(1.0, z.z);
        double a = -1.0 / (sign + z.z);
        double b = z.x * z.y * a;
        Vec3d s(1.0 + sign * z.x * z.x * a, sign * b, -sign * z.x);
        Vec3d t(b, sign + z.y * z.y * a, -z.y);
        n_out = s * (sin_alpha * std::cos(phi)) + t * (sin_alpha * std::sin(phi)) + z * cos_alpha;
    } else {
        n_out = normalize(Vec3d(sample_uniform_sphere(u)));
    }
    EmitterSample es;
    es.p = Vec3f(sphere.center + n_out * r);
    es.n = front_normal(n_out);
    es.pdf = pdf(ref, es.p, es.n);
    if (!(es.pdf > 0.0f) || !std::isfinite(es.pdf)) return std::nullopt;
    // In double, as the rest of this sphere's geometry (a float difference would be correctly
    // rounded too, emitter.h).
    Vec3d d = Vec3d(es.p) - Vec3d(ref);
    es.wi = Vec3f(d * (1.0 / length(d)));
    return es;
}

}  // namespace candela
