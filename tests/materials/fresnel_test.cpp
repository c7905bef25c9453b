// Fresnel reflectance, Snell refraction and Schlick's approximation against values known in
// closed form, computed here independently in double from the textbook angle formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/fresnel.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The unit direction at polar cosine cos_theta and azimuth phi (local frame, z = normal).
Vec3f direction(float cos_theta, float phi) {
    float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

float sin_theta(const Vec3f& w) { return std::sqrt(w.x * w.x + w.y * w.y); }

// Unpolarized Fresnel reflectance from the angle forms of the Fresnel equations (Hecht, Optics,
// 4.42-4.43): R_s = sin^2(ti - tt) / sin^2(ti + tt), R_p = tan^2(ti - tt) / tan^2(ti + tt),
// incidence from the medium of index n1 into n2. Not valid at exactly normal incidence.
double fresnel_reference(double theta_i, double n1, double n2) {
    double theta_t = std::asin(n1 / n2 * std::sin(theta_i));
    double rs = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(Fresnel, NormalIncidenceOnGlassReflectsFourPercent) {
    EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f), 0.04f, 1e-6f);
    // The same from inside the glass, and what r0 says.
    EXPECT_NEAR(fresnel_dielectric(-1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_r0(1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_r0(1.0f / 1.5f), 0.04f, 1e-6f);
}

TEST(Fresnel, MatchesTheAngleFormsOfTheFresnelEquations) {
    for (float eta : {1.33f, 1.5f, 2.4f}) {
        for (int i = 1; i < 90; ++i) {
            double theta = i * kPiD / 180.0;
            float cos_i = static_cast<float>(std::cos(theta));
            // From outside into the medium.
            EXPECT_NEAR(fresnel_dielectric(cos_i, eta), fresnel_reference(theta, 1.0, eta), 2e-6)
                << "eta " << eta << ", " << i << " degrees";
            // From inside out, below the critical angle.
            if (std::sin(theta) * double(eta) < 1.0) {
                EXPECT_NEAR(fresnel_dielectric(-cos_i, eta), fresnel_reference(theta, eta, 1.0),
                            2e-5)
                    << "eta " << eta << ", " << i << " degrees from inside";
            }
        }
    }
}

TEST(Fresnel, BrewsterAngleReflectsOnlyTheSPolarization) {
    // At tan(theta) = eta the p reflectance vanishes; R_s = ((1 - eta^2) / (1 + eta^2))^2 there.
    const double eta = 1.5;
    float cos_b = static_cast<float>(std::cos(std::atan(eta)));
    double rs = std::pow((1.0 - eta * eta) / (1.0 + eta * eta), 2.0);
    EXPECT_NEAR(fresnel_dielectric(cos_b, 1.5f), 0.5 * rs, 1e-6);
}

TEST(Fresnel, IndexOneReflectsNothing) {
    // Up to the rounding of cos_t = sqrt(1 - sin^2) back to cos_i.
    for (float c : {-1.0f, -0.5f, 0.1f, 1.0f}) EXPECT_LT(fresnel_dielectric(c, 1.0f), 1e-10f);
}

TEST(Fresnel, TotalInternalReflectionStartsJustBeyondTheCriticalAngle) {
    const double eta = 1.5;
    const double critical = std::asin(1.0 / eta);
    const double delta = 1e-3;
    for (double theta : {critical - delta, critical + delta}) {
        // Inside the glass, heading out: the direction is below the surface.
        Vec3f wi = direction(-static_cast<float>(std::cos(theta)), 0.7f);
        Vec3f wt;
        bool refracted = refract(wi, Vec3f(0, 0, 1), 1.5f, &wt);
        float f = fresnel_dielectric(wi.z, 1.5f);
        if (theta < critical) {
            EXPECT_TRUE(refracted);
            EXPECT_LT(f, 1.0f);
            EXPECT_GT(f, 0.5f);  // steeply rising towards 1 near the critical angle
        } else {
            EXPECT_FALSE(refracted);
            EXPECT_EQ(f, 1.0f);
        }
    }
    // From outside there is no critical angle, even at grazing incidence.
    Vec3f wt;
    EXPECT_TRUE(refract(direction(1e-4f, 0.0f), Vec3f(0, 0, 1), 1.5f, &wt));
    EXPECT_LT(fresnel_dielectric(1e-4f, 1.5f), 1.0f);
}

TEST(Refract, ObeysSnellsLawOnBothSides) {
    for (float eta : {1.33f, 1.5f, 0.8f}) {
        for (int i = -19; i <= 19; ++i) {
            if (i == 0) continue;
            Vec3f wi = direction(static_cast<float>(i) / 20.0f, 0.3f * static_cast<float>(i));
            Vec3f wt;
            float eta_rel = 0.0f;
            bool entering = wi.z > 0.0f;
            // Indices of the medium wi lies in and the one wt goes to.
            float n_i = entering ? 1.0f : eta, n_t = entering ? eta : 1.0f;
            if (!refract(wi, Vec3f(0, 0, 1), eta, &wt, &eta_rel)) {
                EXPECT_GE(n_i * sin_theta(wi), n_t) << "refused below the critical angle";
                continue;
            }
            EXPECT_NEAR(length(wt), 1.0f, 1e-5f);
            EXPECT_LT(wt.z * wi.z, 0.0f) << "wt must cross the surface";
            EXPECT_NEAR(n_i * sin_theta(wi), n_t * sin_theta(wt), 2e-5f);
            EXPECT_FLOAT_EQ(eta_rel, n_t / n_i);
            // The plane of incidence holds wi, n and wt, with wt on the far side of n.
            EXPECT_NEAR(wi.x * wt.y - wi.y * wt.x, 0.0f, 1e-5f);
            EXPECT_LE(wi.x * wt.x + wi.y * wt.y, 0.0f);
        }
    }
}

TEST(Refract, NormalIncidenceGoesStraightThrough) {
    Vec3f wt;
    ASSERT_TRUE(refract(Vec3f(0, 0, 1), Vec3f(0, 0, 1), 1.5f, &wt));
    EXPECT_NEAR(wt.z, -1.0f, 1e-6f);
    ASSERT_TRUE(refract(Vec3f(0, 0, -1), Vec3f(0, 0, 1), 1.5f, &wt));
    EXPECT_NEAR(wt.z, 1.0f, 1e-6f);
}

TEST(Fresnel, IsReciprocal) {
    // Light reversing its path through the interface is reflected in the same proportion.
    for (float eta : {1.33f, 1.5f, 2.4f}) {
        for (int i = 1; i <= 20; ++i) {
            float cos_i = static_cast<float>(i) / 20.0f;
            Vec3f wi = direction(cos_i, 0.0f), wt;
            ASSERT_TRUE(refract(wi, Vec3f(0, 0, 1), eta, &wt));
            float f = fresnel_dielectric(cos_i, eta);
            EXPECT_NEAR(fresnel_dielectric(-wt.z, 1.0f / eta), f, 1e-5f);
            EXPECT_NEAR(fresnel_dielectric(wt.z, eta), f, 1e-5f);
        }
    }
}

// Unpolarized reflectance of a conductor of complex index n + i k in the real form (Born & Wolf,
// Principles of Optics, 14.4; as Mitsuba's fresnel_conductor writes it): with
// a^2 + b^2 = sqrt((n^2 - k^2 - sin^2)^2 + 4 n^2 k^2) and a^2 = (a^2 + b^2 + n^2 - k^2 - sin^2) / 2,
// R_s = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2) and
// R_p = R_s (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4).
double conductor_reference(double cos_i, double n, double k) {
    double c2 = cos_i * cos_i, s2 = 1.0 - c2;
    double t = n * n - k * k - s2;
    double a2b2 = std::sqrt(t * t + 4.0 * n * n * k * k);
    double a = std::sqrt(0.5 * (a2b2 + t));
    double rs = (a2b2 - 2.0 * a * cos_i + c2) / (a2b2 + 2.0 * a * cos_i + c2);
    double rp = rs * (c2 * a2b2 - 2.0 * a * cos_i * s2 + s2 * s2) /
                (c2 * a2b2 + 2.0 * a * cos_i * s2 + s2 * s2);
    return 0.5 * (rs + rp);
}

TEST(FresnelComplex, MatchesTheRealFormOfTheConductorEquations) {
    // Gold, silver, aluminium-like indices, and a weak absorber.
    const double indices[][2] = {{0.143, 3.983}, {0.155, 4.83}, {1.66, 8.06}, {1.5, 0.1}, {2.9, 3.0}};
    for (const auto& nk : indices) {
        for (int i = 0; i <= 100; ++i) {
            double cos_i = i / 100.0;
            EXPECT_NEAR(double(fresnel_complex(float(cos_i), float(nk[0]), float(nk[1]))),
                        conductor_reference(cos_i, nk[0], nk[1]), 2e-6)
                << "n " << nk[0] << ", k " << nk[1] << ", cos " << cos_i;
        }
    }
}

TEST(FresnelComplex, NormalIncidenceAndLimits) {
    // ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) at normal incidence; 1 at grazing.
    EXPECT_NEAR(fresnel_complex(1.0f, 0.2f, 3.0f), (0.64f + 9.0f) / (1.44f + 9.0f), 1e-6f);
    EXPECT_NEAR(fresnel_complex(0.0f, 0.2f, 3.0f), 1.0f, 1e-6f);
    // No absorption: the dielectric's reflectance.
    for (float c : {1.0f, 0.7f, 0.3f, 0.05f})
        EXPECT_NEAR(fresnel_complex(c, 1.5f, 0.0f), fresnel_dielectric(c, 1.5f), 1e-6f) << c;
    // A purely imaginary index reflects everything (both amplitudes have modulus 1).
    for (float c : {1.0f, 0.5f, 0.01f}) EXPECT_NEAR(fresnel_complex(c, 0.0f, 1.0f), 1.0f, 1e-6f);
    // Clamped: below the surface counts as grazing.
    EXPECT_EQ(fresnel_complex(-0.5f, 0.2f, 3.0f), fresnel_complex(0.0f, 0.2f, 3.0f));
    // Per channel: the scalar function on each channel. Within a few ulps, not bit for bit: a
    // compiler may contract the two forms' multiply-adds differently (clang's default
    // -ffp-contract=on did in the sanitizer build).
    Color f = fresnel_complex(0.6f, Color(0.2f, 1.5f, 0.0f), Color(3.0f, 0.0f, 1.0f));
    EXPECT_NEAR(f[0], fresnel_complex(0.6f, 0.2f, 3.0f), 1e-6f);
    EXPECT_NEAR(f[1], fresnel_complex(0.6f, 1.5f, 0.0f), 1e-6f);
    EXPECT_NEAR(f[2], fresnel_complex(0.6f, 0.0f, 1.0f), 1e-6f);
}

TEST(Reflect, MirrorsAboutTheNormal) {
    Vec3f w = normalize(Vec3f(0.3f, -0.4f, 0.5f));
    Vec3f r = reflect(w, Vec3f(0, 0, 1));
    EXPECT_NEAR(r.x, -w.x, 1e-6f);
    EXPECT_NEAR(r.y, -w.y, 1e-6f);
    EXPECT_NEAR(r.z, w.z, 1e-6f);
}

TEST(Schlick, ExactAtNormalIncidenceAndOneAtGrazing) {
    float r0 = fresnel_r0(1.5f);
    EXPECT_NEAR(fresnel_schlick(r0, 1.0f), fresnel_dielectric(1.0f, 1.5f), 1e-6f);
    EXPECT_EQ(fresnel_schlick(r0, 0.0f), 1.0f);
    // Monotone in between, and near the exact curve for glass: the approximation's error peaks
    // at about 0.036 around 85 degrees.
    float previous = 1.0f;
    for (int i = 1; i <= 100; ++i) {
        float c = static_cast<float>(i) / 100.0f;
        float s = fresnel_schlick(r0, c);
        EXPECT_LE(s, previous);
        EXPECT_NEAR(s, fresnel_dielectric(c, 1.5f), 0.04f) << "cos " << c;
        previous = s;
    }
}

// The Fresnel moments' polynomial fits against the integral they fit, int_0^1 R(mu) mu^k dmu
// for light inside a medium of relative index eta meeting the boundary (R from the angle forms
// above, 1 beyond the critical angle), by the midpoint rule on 20,000 intervals (40,000 moves
// the integrals by < 1.1e-6). The fits' largest errors on the grid below are 1.9e-5 (first
// moment) and 1.5e-5 (second) for eta <= 0.9, and 5e-4 and 1.2e-3 for eta >= 1.2; near 1, where the
// moments fall to 0 with a kink, the fits are worse (8e-4 and 1.5e-3 at 1.1) and are not tested.
// Control: reading the argument as the outside's index over the inside's (R from outside, as
// the name invEta in pbrt-v4's header suggests) misses by 0.2 at 1.33.
double fresnel_moment_reference(double eta, int k, bool from_inside = true) {
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double mu = (i + 0.5) / n;
        double theta = std::acos(mu);
        double n1 = from_inside ? eta : 1.0, n2 = from_inside ? 1.0 : eta;
        double r = n1 / n2 * std::sin(theta) >= 1.0 ? 1.0 : fresnel_reference(theta, n1, n2);
        sum += r * std::pow(mu, k);
    }
    return sum / n;
}

TEST(Fresnel, MomentFitsMatchTheirIntegrals) {
    for (double eta : {0.5, 0.6, 0.67, 0.75, 0.8, 0.9, 1.2, 1.33, 1.4, 1.5, 1.7, 2.0}) {
        const double tolerance1 = eta < 1.0 ? 3e-5 : 1e-3, tolerance2 = eta < 1.0 ? 3e-5 : 2e-3;
        const auto eta_f = static_cast<float>(eta);
        EXPECT_NEAR(fresnel_moment1(eta_f), fresnel_moment_reference(eta, 1), tolerance1) << "eta " << eta;
        EXPECT_NEAR(fresnel_moment2(eta_f), fresnel_moment_reference(eta, 2), tolerance2) << "eta " << eta;
    }
    // 2 FM1(eta) is the reflectance to a uniform flux from inside; from outside it is 2 FM1(1 / eta).
    EXPECT_NEAR(fresnel_moment1(1.0f / 1.33f), fresnel_moment_reference(1.33, 1, false), 2e-5);
    EXPECT_GT(std::abs(static_cast<double>(fresnel_moment1(1.33f)) - fresnel_moment_reference(1.33, 1, false)), 0.2);
}

}  // namespace
}  // namespace candela
