#pragma once
// The Trowbridge-Reitz (GGX) microfacet distribution, isotropic or anisotropic, with Smith's
// height-correlated masking-shadowing and sampling of the visible normals. alpha_x is the
// roughness along the local x axis (the surface's dpdu direction), alpha_y along y; the local
// frame's z is the macro-surface normal. Microfacet normals wm lie in the upper hemisphere.
//
// Names follow the literature (and pbrt-v4's TrowbridgeReitzDistribution): d(wm) = D, lambda(w)
// = Lambda, g1 = G1, g = G, d_visible(w, wm) = D_w. Sampling uses Dupuy & Benyoub's spherical caps
// (2023, "Sound and Robust Sampling of Visible Normals"), which draws the same density as Heitz's
// 2018 hemisphere projection with fewer operations.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/math/constants.h"
#include "candela/math/vec.h"

namespace candela {

struct TrowbridgeReitz {
    float alpha_x = 0.0f;
    float alpha_y = 0.0f;

    // Below this alpha (along both axes) a lobe is a perfect specular one (pbrt-v4's threshold):
    // the distribution is too narrow for float arithmetic and for any sampler to find.
    static constexpr float kSmoothAlpha = 1e-3f;

    TrowbridgeReitz() = default;
    CANDELA_HD explicit TrowbridgeReitz(float alpha) : TrowbridgeReitz(alpha, alpha) {}
    // A rough distribution keeps both alphas >= 1e-4: with one axis near 0 the other's roughness
    // would still make D's ellipse degenerate (pbrt-v4 does the same).
    CANDELA_HD TrowbridgeReitz(float ax, float ay) : alpha_x(ax), alpha_y(ay) {
        if (!effectively_smooth()) {
            alpha_x = alpha_x > 1e-4f ? alpha_x : 1e-4f;
            alpha_y = alpha_y > 1e-4f ? alpha_y : 1e-4f;
        }
    }

    // True when both alphas are below kSmoothAlpha: lobes then use their specular limit.
    CANDELA_HD bool effectively_smooth() const {
        return (alpha_x > alpha_y ? alpha_x : alpha_y) < kSmoothAlpha;
    }

    // D(wm): microfacet normals per unit solid angle per unit macro-surface area; 0 below the
    // surface. For unit wm, D = 1 / (pi ax ay ((x/ax)^2 + (y/ay)^2 + z^2)^2) (Walter et al. 2007,
    // eq. 33, anisotropic form), which needs no tangent or trigonometry.
    CANDELA_HD float d(const Vec3f& wm) const {
        if (!(wm.z > 0.0f)) return 0.0f;
        float e = sqr(wm.x / alpha_x) + sqr(wm.y / alpha_y) + wm.z * wm.z;
        return 1.0f / (kPi * alpha_x * alpha_y * e * e);
    }

    // Smith's Lambda(w) (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 86):
    // (sqrt(1 + alpha^2 tan^2) - 1) / 2 with alpha^2 tan^2 = s / z^2, s = (ax x)^2 + (ay y)^2,
    // written as s / (2 z (z + sqrt(z^2 + s))) so it does not cancel near normal incidence.
    // Symmetric in w.z; infinite in the surface's plane.
    CANDELA_HD float lambda(const Vec3f& w) const {
        float s = sqr(alpha_x * w.x) + sqr(alpha_y * w.y);
        if (s == 0.0f) return 0.0f;
        float z = std::abs(w.z);
        return s / (2.0f * z * (z + std::sqrt(z * z + s)));
    }

    // The masking function G1(w) = 1 / (1 + Lambda(w)): the visible fraction of the microfacets
    // facing w.
    CANDELA_HD float g1(const Vec3f& w) const { return 1.0f / (1.0f + lambda(w)); }

    // Height-correlated masking-shadowing G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz
    // 2014, eq. 99). The Lambdas are added first so that G is exactly symmetric.
    CANDELA_HD float g(const Vec3f& wo, const Vec3f& wi) const {
        return 1.0f / (1.0f + (lambda(wo) + lambda(wi)));
    }

    // D_w(wm) = G1(w) max(0, w.wm) D(wm) / |cos w|: the density per solid angle of the normals
    // seen from w (Heitz 2014, eq. 38). w may be below the surface: it then stands for -w (the
    // normals seen from the other side of the same upper-hemisphere distribution), as sample_wm.
    CANDELA_HD float d_visible(const Vec3f& w, const Vec3f& wm) const {
        if (w.z == 0.0f) return 0.0f;
        float c = w.z > 0.0f ? dot(w, wm) : -dot(w, wm);
        if (!(c > 0.0f)) return 0.0f;
        return g1(w) * c * d(wm) / std::abs(w.z);
    }

    // Density of sample_wm(w, .) per solid angle of wm: the visible-normal density.
    CANDELA_HD float pdf(const Vec3f& w, const Vec3f& wm) const { return d_visible(w, wm); }

    // A microfacet normal drawn from D_w for w on either side (see d_visible), from u in [0,1)^2.
    // Stretch w to the unit-roughness configuration, where the visible normals are h = c + w with
    // c uniform on the spherical cap z >= -w.z (Dupuy & Benyoub 2023, listing 3), and stretch
    // the normal back.
    CANDELA_HD Vec3f sample_wm(const Vec3f& w, const Vec2f& u) const {
        Vec3f wh = normalize(Vec3f(alpha_x * w.x, alpha_y * w.y, w.z));
        if (wh.z < 0.0f) wh = -wh;
        float phi = 2.0f * kPi * u.x;
        float z = (1.0f - u.y) * (1.0f + wh.z) - wh.z;
        float sin_theta = safe_sqrt(1.0f - z * z);
        Vec3f h(sin_theta * std::cos(phi) + wh.x, sin_theta * std::sin(phi) + wh.y, z + wh.z);
        // h.z >= 0 up to rounding; the floor keeps the normal defined where c = -wh (measure 0).
        return normalize(Vec3f(alpha_x * h.x, alpha_y * h.y, h.z > 1e-6f ? h.z : 1e-6f));
    }
};

}  // namespace candela
