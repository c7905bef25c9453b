// Kulla & Conty's multiple-scattering compensation (materials/microfacet_multiscatter.h) and its
// albedo tables (materials/microfacet_albedo.h): white furnaces by deterministic quadrature of
// eval(), the tables against an independent integration, reciprocity, and the colour of the
// compensation of a coloured conductor.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/conductor.h"
#include "candela/materials/dielectric.h"
#include "candela/materials/microfacet_albedo.h"
#include "materials/lobe_cases.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kImportance = TransportMode::kImportance;
constexpr TransportMode kRadiance = TransportMode::kRadiance;

// A conductor that reflects everything: F = 1 - 4 eta / ((eta + 1)^2 + k^2) = 1 - 1e-8.
ConductorLobe white_conductor(float alpha) { return ConductorLobe{TrowbridgeReitz(alpha), Color(1.0f), Color(2e4f)}; }

DielectricLobe glass(float alpha, float eta) { return DielectricLobe{Color(1.0f), eta, TrowbridgeReitz(alpha)}; }

// D(m) of an isotropic distribution, in double (the slope-space form, Heitz 2014 eqs. 8, 10).
double ggx_d(double alpha, Vec3d m) {
    if (!(m.z > 0.0)) return 0.0;
    double s2 = (m.x * m.x + m.y * m.y) / (alpha * alpha * m.z * m.z);
    return 1.0 / (kPiD * alpha * alpha * sqr(1.0 + s2) * sqr(m.z * m.z));
}

// The single-scattering albedo of a lobe (red channel): the integral of evaluate_single(wo, wi)
// |cos wi| over wi, written over the microfacet normal m that takes wo to wi by reflection (d wi =
// 4 |wo.m| d m) and, for the dielectric, by refraction (d wi = (wi.m + wo.m / eta')^2 / |wi.m|
// d m, Walter et al. 2007 eq. 17). m is parametrized so that it is distributed as D(m) cos(theta_m)
// for uniform (u1, u2) (slope radius alpha sqrt(u1 / (1 - u1)), angle 2 pi u2), which is divided
// out: the integrand is then f / D times bounded factors. Adaptive Simpson to about eps,
// independent of the tables' generator (which integrates G / G1 over the visible normals).
// The single-scattering f of either lobe (the conductor's does not depend on the transport mode).
Color single_f(const ConductorLobe& lobe, Vec3f wo, Vec3f wi, TransportMode) { return lobe.evaluate_single(wo, wi).f; }
Color single_f(const DielectricLobe& lobe, Vec3f wo, Vec3f wi, TransportMode mode) {
    return lobe.evaluate_single(wo, wi, mode).f;
}

template <class Lobe>
double single_scatter_albedo(const Lobe& lobe, Vec3f wo, TransportMode mode, double eps) {
    const double alpha = lobe.distribution.alpha_x;
    const double side = wo.z > 0.0f ? 1.0 : -1.0;
    auto integrand = [&](double u1, double u2) {
        if (u1 >= 1.0) return 0.0;
        double r = alpha * std::sqrt(u1 / (1.0 - u1)), phi = 2.0 * kPiD * u2;
        Vec3d m = normalize(Vec3d(-r * std::cos(phi), -r * std::sin(phi), 1.0));
        double density = ggx_d(alpha, m) * m.z;
        Vec3f wm(m);
        double wo_dot_m = double(dot(wo, wm));
        if (!(density > 0.0) || !(side * wo_dot_m > 0.0)) return 0.0;
        Vec3f wr = reflect(wo, wm);
        double sum = 0.0;
        if (wr.z * wo.z > 0.0f) {
            sum += double(single_f(lobe, wo, wr, mode)[0]) * std::abs(double(wr.z)) * 4.0 * std::abs(wo_dot_m);
        }
        if constexpr (std::is_same_v<Lobe, DielectricLobe>) {
            Vec3f wt;
            float eta_rel = 1.0f;
            if (refract(wo, wm, lobe.eta, &wt, &eta_rel) && wt.z * wo.z < 0.0f) {
                double wt_dot_m = double(dot(wt, wm));
                double jacobian = sqr(wt_dot_m + wo_dot_m / double(eta_rel)) / std::abs(wt_dot_m);
                sum += double(single_f(lobe, wo, wt, mode)[0]) * std::abs(double(wt.z)) * jacobian;
            }
        }
        return sum / density;
    };
    // In u1, pieces [0, 0.9], [0.9, 0.99], ... up to 1 - 1e-10: as u1 -> 1 the normals tilt
    // towards the horizon, where the integrand grows like the slope until the reflection passes
    // below the surface, in a sliver of u1 that a single Simpson panel would step over.
    auto row = [&](double u2) {
        auto g = [&](double u1) { return integrand(u1, u2); };
        double sum = detail::integrate_1d(g, 0.0, 0.9, 0.01 * eps), lo = 0.9;
        for (double gap = 1e-2; gap >= 1e-10; gap *= 0.1) {
            sum += detail::integrate_1d(g, lo, 1.0 - gap, 0.01 * eps);
            lo = 1.0 - gap;
        }
        return sum;
    };
    return detail::integrate_1d(row, 0.0, 1.0, eps);
}

// The albedo of what eval() adds to the single-scattering lobe (red channel): 2 pi integral of
// (eval - evaluate_single)(wo, wi) |cos wi| over cos wi, on wo's side and, for the dielectric,
// the other one (the compensation lobes do not depend on the azimuth). Node to node of the
// tables' mu axis, where the integrand has kinks.
template <class Lobe>
double compensation_albedo(const Lobe& lobe, Vec3f wo, TransportMode mode) {
    auto on_side = [&](double side) {
        auto g = [&](double mu) {
            Vec3f wi = direction(float(side * mu), 1.1f);
            double added = double(lobe.eval(wo, wi, mode)[0]) - double(single_f(lobe, wo, wi, mode)[0]);
            return added * mu;
        };
        double sum = 0.0;
        for (int j = 0; j + 1 < kAlbedoMuCount; ++j)
            sum += detail::integrate_1d(g, albedo_mu_node(j), albedo_mu_node(j + 1), 1e-9);
        return 2.0 * kPiD * sum;
    };
    double same = wo.z > 0.0f ? 1.0 : -1.0;
    double sum = on_side(same);
    if constexpr (std::is_same_v<Lobe, DielectricLobe>) sum += on_side(-same);
    return sum;
}

// To about 1e-4: ample for furnaces held to 5e-3, and fast enough for unit tests.
template <class Lobe>
double directional_albedo(const Lobe& lobe, Vec3f wo, TransportMode mode = kImportance) {
    return single_scatter_albedo(lobe, wo, mode, 2e-5) + compensation_albedo(lobe, wo, mode);
}

// The incident angles of the furnace tests: normal to 84 degrees.
constexpr float kFurnaceCosines[] = {1.0f, 0.8f, 0.5f, 0.2f, 0.1f};

void expect_white_conductor_furnace(float alpha) {
    ConductorLobe lobe = white_conductor(alpha).with_multiscatter();
    for (float c : kFurnaceCosines) {
        SCOPED_TRACE(testing::Message() << "alpha " << alpha << ", cos " << c);
        EXPECT_NEAR(directional_albedo(lobe, direction(c, 0.3f)), 1.0, 0.005);
        EXPECT_NEAR(directional_albedo(lobe, direction(-c, 2.0f)), 1.0, 0.005);  // two-sided
    }
}

TEST(ConductorMultiscatter, WhiteFurnaceAtAlphaPoint1) { expect_white_conductor_furnace(0.1f); }
TEST(ConductorMultiscatter, WhiteFurnaceAtAlphaPoint5) { expect_white_conductor_furnace(0.5f); }
TEST(ConductorMultiscatter, WhiteFurnaceAtAlpha1) { expect_white_conductor_furnace(1.0f); }

TEST(ConductorMultiscatter, SingleScatteringAloneFailsTheFurnace) {
    // The control: the quadrature sees the energy that multiscatter restores.
    ConductorLobe lobe = white_conductor(1.0f);
    EXPECT_LT(directional_albedo(lobe, direction(0.5f, 0.3f)), 0.9);
    EXPECT_LT(directional_albedo(white_conductor(0.5f), direction(0.2f, 0.3f)), 0.97);
}

TEST(ConductorMultiscatter, ColouredMetalGainsItsFresnelWeightedShare) {
    // The compensation of gold is (1 - E(mu_o)) F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), E from
    // the table, F_avg by its own quadrature.
    ConductorLobe lobe = ConductorLobe{TrowbridgeReitz(0.6f), kGoldEta, kGoldK}.with_multiscatter();
    double f_avg = 2.0 * detail::integrate_1d(
                             [&](double mu) { return double(fresnel_complex(float(mu), kGoldEta[0], kGoldK[0])) * mu; },
                             0.0, 1.0, 1e-9);
    EXPECT_NEAR(lobe.fresnel_avg[0], f_avg, 1e-5);
    f_avg = lobe.fresnel_avg[0];
    AlbedoCurve e = conductor_albedo(0.6f);
    double e_avg = e.average;
    for (float c : {0.9f, 0.4f}) {
        double expected = (1.0 - double(e(c))) * f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
        EXPECT_NEAR(compensation_albedo(lobe, direction(c, 0.0f), kRadiance), expected, 1e-5) << c;
    }
}

void expect_glass_furnace(float alpha) {
    for (float eta : {1.5f, 1.0f / 1.33f, 2.4f}) {
        DielectricLobe lobe = glass(alpha, eta).with_multiscatter();
        for (float c : kFurnaceCosines) {
            for (float side : {1.0f, -1.0f}) {
                SCOPED_TRACE(testing::Message() << "alpha " << alpha << ", eta " << eta << ", cos " << side * c);
                EXPECT_NEAR(directional_albedo(lobe, direction(side * c, 0.7f)), 1.0, 0.005);
            }
        }
    }
}

TEST(DielectricMultiscatter, ReflectedPlusTransmittedIsOneAtAlphaPoint1) { expect_glass_furnace(0.1f); }
TEST(DielectricMultiscatter, ReflectedPlusTransmittedIsOneAtAlphaPoint5) { expect_glass_furnace(0.5f); }
TEST(DielectricMultiscatter, ReflectedPlusTransmittedIsOneAtAlpha1) { expect_glass_furnace(1.0f); }

TEST(DielectricMultiscatter, SingleScatteringAloneFailsTheFurnace) {
    EXPECT_LT(directional_albedo(glass(1.0f, 1.5f), direction(-0.5f, 0.3f)), 0.9);
    EXPECT_LT(directional_albedo(glass(0.5f, 1.5f), direction(0.2f, 0.3f)), 0.98);
}

TEST(Multiscatter, LobesStayReciprocal) {
    // Reflection: f(wo, wi) = f(wi, wo). Transmission (importance transport): n_o^2 f(wo, wi) =
    // n_i^2 f(wi, wo), the BTDF's generalized reciprocity, n the absolute indices (1 outside).
    ConductorLobe metal = ConductorLobe{TrowbridgeReitz(0.4f), kGoldEta, kGoldK}.with_multiscatter();
    DielectricLobe dielectric = glass(0.6f, 1.5f).with_multiscatter();
    auto n = [](Vec3f w) { return w.z > 0.0f ? 1.0 : 1.5; };
    for (const Vec3f& wo : probe_directions()) {
        for (const Vec3f& wi : probe_directions()) {
            if (std::abs(wo.z) < 0.01f || std::abs(wi.z) < 0.01f) continue;
            Color a = metal.eval(wo, wi, kRadiance), b = metal.eval(wi, wo, kRadiance);
            EXPECT_NEAR(a[1], b[1], 1e-4f * (1.0f + a[1])) << wo.z << " " << wi.z;
            double fo = dielectric.eval(wo, wi, kImportance)[0], fi = dielectric.eval(wi, wo, kImportance)[0];
            EXPECT_NEAR(sqr(n(wo)) * fo, sqr(n(wi)) * fi, 1e-4 * (1.0 + sqr(n(wo)) * fo)) << wo.z << " " << wi.z;
        }
    }
}

TEST(Multiscatter, OffUnlessAskedAndNeverOnSmoothLobes) {
    ConductorLobe rough{TrowbridgeReitz(0.5f), kGoldEta, kGoldK};
    EXPECT_FALSE(rough.multiscatter);
    EXPECT_EQ(rough.eval(direction(0.5f, 0.0f), direction(0.3f, 2.0f), kRadiance),
              rough.evaluate_single(direction(0.5f, 0.0f), direction(0.3f, 2.0f)).f);
    ConductorLobe smooth{TrowbridgeReitz(0.0f), kGoldEta, kGoldK};
    EXPECT_FALSE(smooth.with_multiscatter().multiscatter);
    EXPECT_FALSE(glass(0.0f, 1.5f).with_multiscatter().multiscatter);
    EXPECT_TRUE(glass(0.2f, 1.5f).with_multiscatter().multiscatter);
}

// ---- the tables

TEST(MicrofacetAlbedoTable, ConductorNodesMatchDirectIntegration) {
    // The generator's midpoint rule on 256^2 visible normals against adaptive Simpson over the
    // normals of eval(): both accurate to better than 1e-4 where the integrand is smooth; the
    // horizon cuts it, which costs the midpoint rule about 1e-4 at grazing wo.
    const int nodes[][2] = {{31, 31}, {31, 0}, {20, 10}, {10, 20}, {5, 28}, {16, 4}};  // (alpha, mu)
    for (const auto& [i, j] : nodes) {
        float alpha = albedo_alpha_node(i), mu = std::max(albedo_mu_node(j), 1e-4f);
        double direct = single_scatter_albedo(white_conductor(alpha), direction(mu, 0.0f), kImportance, 1e-5);
        EXPECT_NEAR(kConductorAlbedo[i][j], direct, 3e-4) << "alpha " << alpha << ", mu " << mu;
    }
}

TEST(MicrofacetAlbedoTable, DielectricNodesMatchDirectIntegration) {
    const int nodes[][4] = {{0, 8, 31, 31}, {0, 3, 20, 10}, {1, 8, 31, 31}, {1, 8, 20, 25},
                            {1, 12, 10, 8}, {0, 15, 28, 2}};  // (side, eta, alpha, mu)
    for (const auto& [side, k, i, j] : nodes) {
        float eta = albedo_eta_node(k), alpha = albedo_alpha_node(i), mu = std::max(albedo_mu_node(j), 1e-4f);
        // The lobe's eta is inside over outside: side 1 (leaving the denser medium) is wo inside.
        Vec3f wo = direction(side == 0 ? mu : -mu, 0.0f);
        double direct = single_scatter_albedo(glass(alpha, eta), wo, kImportance, 1e-5);
        EXPECT_NEAR(kDielectricAlbedo[side][k][i][j], direct, 3e-4)
            << "side " << side << ", eta " << eta << ", alpha " << alpha << ", mu " << mu;
    }
}

TEST(MicrofacetAlbedoTable, AveragesAreThoseOfTheInterpolatedCurves) {
    // The compensation adds exactly 1 - E(mu) only if E_avg is the average of the curve it uses.
    for (int i = 0; i < kAlbedoAlphaCount; ++i) {
        EXPECT_NEAR(kConductorAlbedoAvg[i], albedo_average(kConductorAlbedo[i]), 2e-7f);
        for (int side = 0; side < 2; ++side)
            for (int k = 0; k < kAlbedoEtaCount; ++k)
                EXPECT_NEAR(kDielectricAlbedoAvg[side][k][i], albedo_average(kDielectricAlbedo[side][k][i]), 2e-7f);
    }
    // And albedo_average is 2 integral E mu dmu, exact for curves linear in mu: 1 for E = 1, 2/3
    // for E = mu.
    float ones[kAlbedoMuCount], mus[kAlbedoMuCount];
    for (int j = 0; j < kAlbedoMuCount; ++j) ones[j] = 1.0f, mus[j] = albedo_mu_node(j);
    EXPECT_NEAR(albedo_average(ones), 1.0f, 1e-6f);
    EXPECT_NEAR(albedo_average(mus), 2.0f / 3.0f, 1e-6f);
}

TEST(MicrofacetAlbedoTable, SmoothSurfacesLoseNothingAndRougherOnesMore) {
    for (int j = 0; j < kAlbedoMuCount; ++j) EXPECT_EQ(kConductorAlbedo[0][j], 1.0f);
    for (int i = 1; i < kAlbedoAlphaCount; ++i) {
        EXPECT_LT(kConductorAlbedoAvg[i], kConductorAlbedoAvg[i - 1]);
        for (int side = 0; side < 2; ++side)
            for (int k = 1; k < kAlbedoEtaCount; ++k)
                EXPECT_LT(kDielectricAlbedoAvg[side][k][i], kDielectricAlbedoAvg[side][k][i - 1]);
    }
}

}  // namespace
}  // namespace candela::test
