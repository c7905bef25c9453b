#pragma once
// Reflection, refraction and the Fresnel reflectance of a smooth dielectric interface. `eta` is
// always the relative index eta_t / eta_i across the interface as seen from the side its normal
// points to (index behind the surface over index in front: 1.5 for glass in air); a direction or
// cosine on the other side swaps the roles, so callers need not know which side they are on.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/math/complex.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

// The mirror image of w about the normal n (both unit; w points away from the surface).
CANDELA_HD inline Vec3f reflect(const Vec3f& w, const Vec3f& n) {
    return -w + n * (2.0f * dot(w, n));
}

// Refracts wi (unit, pointing away from the surface, either side of n) through the interface of
// relative index eta (see the top of the file) into *wt (unit, on the other side). Returns false
// on total internal reflection, leaving *wt untouched; *eta_rel (if given) receives the index
// eta_t / eta_i actually crossed: eta from n's side, 1 / eta from the other. (pbrt-v4 Refract.)
CANDELA_HD inline bool refract(const Vec3f& wi, Vec3f n, float eta, Vec3f* wt,
                               float* eta_rel = nullptr) {
    float cos_i = dot(n, wi);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
        n = -n;
    }
    // Snell: eta_i sin(theta_i) = eta_t sin(theta_t), so sin^2(theta_t) = sin^2(theta_i) / eta^2.
    float sin2_i = 1.0f - cos_i * cos_i;
    float sin2_t = (sin2_i > 0.0f ? sin2_i : 0.0f) / (eta * eta);
    if (sin2_t >= 1.0f) return false;
    float cos_t = safe_sqrt(1.0f - sin2_t);
    *wt = -wi / eta + n * (cos_i / eta - cos_t);
    if (eta_rel != nullptr) *eta_rel = eta;
    return true;
}

// The fraction of unpolarized light a smooth dielectric reflects, for incidence at cos_theta_i to
// the normal (negative: from behind, where the index ratio is 1 / eta). 1 under total internal
// reflection. The average of the s and p Fresnel equations (pbrt-v4 FrDielectric).
CANDELA_HD inline float fresnel_dielectric(float cos_theta_i, float eta) {
    cos_theta_i = clamp(cos_theta_i, -1.0f, 1.0f);
    if (cos_theta_i < 0.0f) {
        eta = 1.0f / eta;
        cos_theta_i = -cos_theta_i;
    }
    float sin2_t = (1.0f - cos_theta_i * cos_theta_i) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    float cos_t = safe_sqrt(1.0f - sin2_t);
    float r_parallel = (eta * cos_theta_i - cos_t) / (eta * cos_theta_i + cos_t);
    float r_perpendicular = (cos_theta_i - eta * cos_t) / (cos_theta_i + eta * cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

// The fraction of unpolarized light a conductor of complex index eta + i k (relative to the
// medium it faces) reflects, for incidence at cos_theta_i (clamped to [0, 1]: a conductor is
// only ever lit from outside). The Fresnel equations with a complex refracted cosine, averaging
// |r_parallel|^2 and |r_perpendicular|^2 (Born & Wolf 14.2; pbrt-v4 FrComplex). k = 0 gives
// fresnel_dielectric.
CANDELA_HD inline float fresnel_complex(float cos_theta_i, float eta, float k) {
    cos_theta_i = clamp(cos_theta_i, 0.0f, 1.0f);
    Complex n(eta, k);
    // Snell's law with a complex index: sin^2(theta_t) = sin^2(theta_i) / n^2.
    Complex sin2_t = Complex(1.0f - cos_theta_i * cos_theta_i) / (n * n);
    Complex cos_t = sqrt(Complex(1.0f) - sin2_t);
    Complex cos_i(cos_theta_i);
    Complex r_parallel = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    Complex r_perpendicular = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    return 0.5f * (norm(r_parallel) + norm(r_perpendicular));
}

// fresnel_complex per colour channel.
CANDELA_HD inline Color fresnel_complex(float cos_theta_i, const Color& eta, const Color& k) {
    return map_channels(eta, k, [&](float e, float kk) { return fresnel_complex(cos_theta_i, e, kk); });
}

// Reflectance at normal incidence, ((eta - 1) / (eta + 1))^2: the same from both sides.
CANDELA_HD inline float fresnel_r0(float eta) { return sqr((eta - 1.0f) / (eta + 1.0f)); }

// Schlick's approximation (1994, "An Inexpensive BRDF Model for Physically-based Rendering"):
// r0 + (1 - r0) (1 - cos)^5, where cos_theta is measured on the optically thinner side (smallpt
// takes the transmitted angle when light leaves glass; see FresnelSpecularLobe).
CANDELA_HD inline float fresnel_schlick(float r0, float cos_theta) {
    float c = 1.0f - clamp(std::abs(cos_theta), 0.0f, 1.0f);
    float c2 = c * c;
    return r0 + (1.0f - r0) * c2 * c2 * c;
}

// The first and second moments of the Fresnel reflectance met by light inside a medium of
// relative index eta (inside over outside) as it reaches the boundary:
//   fresnel_moment_k(eta) = int_0^1 fresnel_dielectric(mu, 1 / eta) mu^k dmu,
// so 2 fresnel_moment1(eta) is the reflectance of the boundary to a uniform (Lambertian) flux
// from inside, and 2 fresnel_moment1(1 / eta) that to one from outside. Polynomial fits, eta in
// about [0.5, 2] (d'Eon and Irving 2011; pbrt-v4 FresnelMoment1, FresnelMoment2), so that the
// photon beam diffusion profile (bssrdf_table.h) is pbrt-v4's; tests/materials/fresnel_test.cpp
// compares them with the integral.
CANDELA_HD inline float fresnel_moment1(float eta) {
    float eta2 = eta * eta, eta3 = eta2 * eta, eta4 = eta3 * eta, eta5 = eta4 * eta;
    if (eta < 1.0f)
        return 0.45966f - 1.73965f * eta + 3.37668f * eta2 - 3.904945f * eta3 + 2.49277f * eta4 -
               0.68441f * eta5;
    return -4.61686f + 11.1136f * eta - 10.4646f * eta2 + 5.11455f * eta3 - 1.27198f * eta4 +
           0.12746f * eta5;
}
CANDELA_HD inline float fresnel_moment2(float eta) {
    float eta2 = eta * eta, eta3 = eta2 * eta, eta4 = eta3 * eta, eta5 = eta4 * eta;
    if (eta < 1.0f)
        return 0.27614f - 0.87350f * eta + 1.12077f * eta2 - 0.65095f * eta3 + 0.07883f * eta4 +
               0.04860f * eta5;
    float r_eta = 1.0f / eta, r_eta2 = r_eta * r_eta, r_eta3 = r_eta2 * r_eta;
    return -547.033f + 45.3087f * r_eta3 - 218.725f * r_eta2 + 458.843f * r_eta + 404.557f * eta -
           189.519f * eta2 + 54.9327f * eta3 - 9.00603f * eta4 + 0.63942f * eta5;
}

}  // namespace candela
