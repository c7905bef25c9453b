#pragma once
// Closed forms for a smooth dielectric coat of index eta over a Lambertian base of albedo a in a
// clear slab of zero thickness (transmittance 1), computed in double precision independently of
// the lobe code, against which the coated lobes are tested.
//
// Light entering at cos_o is transmitted with T(cos_o) = 1 - F(cos_o), reaches the base, and
// leaves it cosine-distributed; at the coat from inside it leaves with probability 1 - F, else
// is mirrored back to the base, so every return to the coat sees the same cosine distribution
// and is reflected with the internal diffuse reflectance
//   r = int_0^1 F_inside(mu) 2 mu dmu                       (total internal reflection included).
// Paths of at most max_depth events between the layers count (layered.h); events alternate base
// and coat, base first, and a path leaves after a base event, so K = (max_depth + 1) / 2 paths
// with k = 0 .. K-1 internal reflections count:
//   f(wo, wi)  = a T(cos_o) T(cos_i) / (pi eta^2) sum_{k<K} (a r)^k          (radiance mode)
//   albedo(wo) = F(cos_o) + (1 - F(cos_o)) a (1 - r) sum_{k<K} (a r)^k
//              = F(cos_o) + (1 - F(cos_o)) (1 - r^K)                        for a = 1,
// the first term being the coat's mirror reflection (a delta lobe, outside f). The exit
// direction of a sampled walk has, per coat visit, the density per outside solid angle
// t(wi) = T(cos_i) cos_i / (pi eta^2) (the inside density cos_t (1 - F) / pi times the
// refraction's Jacobian cos_i / (eta^2 cos_t)), whose integral is 1 - r.
#include <cmath>

#include "candela/math/constants.h"

namespace candela::test {

// Unpolarized Fresnel reflectance of a smooth interface of relative index eta (behind over in
// front) for light arriving at cos_i > 0 from the front (pass 1 / eta from behind).
inline double fresnel_reference(double cos_i, double eta) {
    double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) return 1.0;
    double cos_t = std::sqrt(1.0 - sin2_t);
    double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// r: the cosine-weighted reflectance of the coat seen from inside (midpoint rule on 2 mu dmu,
// 200000 intervals: error far below 1e-8; the integrand's kink at the critical angle costs at
// most one interval's share).
inline double internal_diffuse_reflectance(double eta) {
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double mu = (i + 0.5) / n;
        sum += fresnel_reference(mu, 1.0 / eta) * 2.0 * mu;
    }
    return sum / n;
}

// The paths counted for max_depth.
inline int counted_paths(int max_depth) { return (max_depth + 1) / 2; }

// The expected coated-diffuse f (see the top of the file) for cosines cos_o, cos_i > 0, counting
// `paths` paths.
inline double coated_diffuse_f(double cos_o, double cos_i, double eta, double a, int paths) {
    double r = internal_diffuse_reflectance(eta);
    double series = 0.0, term = 1.0;
    for (int k = 0; k < paths; ++k, term *= a * r) series += term;
    return a * (1.0 - fresnel_reference(cos_o, eta)) * (1.0 - fresnel_reference(cos_i, eta)) /
           (kPiD * eta * eta) * series;
}

// The directional albedo of a white (a = 1) base under the coat at cos_o > 0, counting `paths`
// paths, without the coat's mirror reflection F(cos_o) (what f integrates to).
inline double coated_white_albedo_without_mirror(double cos_o, double eta, int paths) {
    double r = internal_diffuse_reflectance(eta), f = fresnel_reference(cos_o, eta);
    return (1.0 - f) * (1.0 - std::pow(r, paths));
}

}  // namespace candela::test
