#pragma once
// Deterministic integrals for the microfacet tests: over the hemisphere of microfacet normals,
// and the directional albedo of rough lobes, by nested adaptive Simpson (support/chi2.h's rule),
// so that sampling estimates can be compared to values that no sampler produced.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "candela/materials/conductor.h"
#include "candela/materials/dielectric.h"
#include "support/chi2.h"

namespace candela::test {

// The integral of f(x, y) over [x0, x1] x [y0, y1], to about eps.
template <class F>
double integrate_2d(const F& f, double x0, double x1, double y0, double y1, double eps) {
    auto row = [&](double y) {
        return detail::integrate_1d([&](double x) { return f(x, y); }, x0, x1,
                                    0.1 * eps / (y1 - y0));
    };
    return detail::integrate_1d(row, y0, y1, eps);
}

// The integral of g(w) over the upper hemisphere of unit directions, in (theta, phi) with
// d omega = sin(theta) d theta d phi. Theta is cut at alpha / 8, alpha / 4, ... up to pi / 2, so
// that a peak at the pole of width alpha is found by the first nodes of some piece.
template <class G>
double integrate_hemisphere(const G& g, double alpha, double eps) {
    auto integrand = [&](double phi, double theta) {
        double s = std::sin(theta);
        Vec3d w(s * std::cos(phi), s * std::sin(phi), std::cos(theta));
        return g(Vec3f(w)) * s;
    };
    double sum = 0.0, lo = 0.0, hi = alpha / 8.0;
    while (lo < kPiD / 2.0) {
        hi = std::min(hi, kPiD / 2.0);
        sum += integrate_2d(integrand, 0.0, 2.0 * kPiD, lo, hi, eps);
        lo = hi;
        hi *= 2.0;
    }
    return sum;
}

// D(wm) of a distribution in double, independent of TrowbridgeReitz::d: the slope-space density
// P22(-x/z, -y/z) = 1 / (pi ax ay (1 + (x/(ax z))^2 + (y/(ay z))^2)^2) over cos^4 (Heitz 2014,
// eqs. 8 and 10, stretched by (ax, ay)).
inline double ggx_d(const TrowbridgeReitz& tr, Vec3d wm) {
    if (!(wm.z > 0.0)) return 0.0;
    double ax = double(tr.alpha_x), ay = double(tr.alpha_y);
    double sx = wm.x / (ax * wm.z), sy = wm.y / (ay * wm.z);
    double p22 = 1.0 / (kPiD * ax * ay * sqr(1.0 + sx * sx + sy * sy));
    return p22 / sqr(sqr(wm.z));
}

// The directional albedo of a rough conductor or dielectric, integral of f(wo, wi) |cos wi| over
// all wi (red channel), written as an integral over the microfacet normal wm that takes wo to wi:
// by reflection (d wi = 4 |wo.wm| d wm) or, for the dielectric, by refraction (d wi =
// (wi.wm + wo.wm / eta')^2 / |wi.wm| d wm, Walter et al. 2007 eq. 17). Only normals facing wo's
// side count, each wi being the reflection or refraction of wo about exactly one of them.
// wm is parametrized by the map that makes it distributed as D(wm) cos(theta_m) from uniform
// (u1, u2) (slope radius^2 = u1 / (1 - u1), angle 2 pi u2), whose density is divided out with
// ggx_d: the integrand is then f / D times bounded factors, smooth even at alpha = 0.01, but for
// the refraction through microfacets near the horizon, which grows as 1 / cos(theta_m) ~
// 1 / sqrt(1 - u1). The substitution u1 = 1 - s^2 (d u1 = 2 s ds) removes that singularity.
template <class Lobe>
double albedo_by_quadrature(const Lobe& lobe, Vec3f wo, TransportMode mode, double eps = 1e-6) {
    const TrowbridgeReitz& tr = lobe.distribution;
    const double sign = wo.z > 0.0f ? 1.0 : -1.0;
    auto integrand = [&](double s, double u2) {
        if (s <= 0.0) return 0.0;
        double u1 = 1.0 - s * s;
        double r = std::sqrt(u1) / s, phi = 2.0 * kPiD * u2;
        Vec3d m = normalize(Vec3d(-double(tr.alpha_x) * r * std::cos(phi),
                                  -double(tr.alpha_y) * r * std::sin(phi), 1.0));
        double density = ggx_d(tr, m) * m.z;
        Vec3f wm(m);
        double wo_dot_wm = double(dot(wo, wm));
        if (!(density > 0.0) || !(sign * wo_dot_wm > 0.0)) return 0.0;
        // A reflection that ends on the other side (or a refraction on wo's side) is no
        // scattering at wm: eval would read it as the other kind, about another normal.
        double sum = 0.0;
        Vec3f wi = reflect(wo, wm);
        if (same_hemisphere(wo, wi))
            sum += double(lobe.eval(wo, wi, mode)[0]) * double(std::abs(wi.z)) * 4.0 * std::abs(wo_dot_wm);
        if constexpr (std::is_same_v<Lobe, DielectricLobe>) {
            Vec3f wt;
            float eta_rel = 1.0f;
            if (refract(wo, wm, lobe.eta, &wt, &eta_rel) && wt.z * wo.z < 0.0f) {
                double wt_dot_wm = double(dot(wt, wm));
                double jacobian = sqr(wt_dot_wm + wo_dot_wm / double(eta_rel)) / std::abs(wt_dot_wm);
                sum += double(lobe.eval(wo, wt, mode)[0]) * double(std::abs(wt.z)) * jacobian;
            }
        }
        return sum / density * 2.0 * s;
    };
    return integrate_2d(integrand, 0.0, 1.0, 0.0, 1.0, eps);
}

}  // namespace candela::test
