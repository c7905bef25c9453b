// The conductor, dielectric and thin-dielectric lobes against their closed forms: the microfacet
// formulas, reciprocity (and the generalized reciprocity of refraction), energy bounds by
// quadrature, and the smooth limits. Generic checks (sample() against eval() and pdf(), weights,
// transport modes) run over every lobe in lobes_test.cpp; sampling's chi-square tests and the
// furnace estimates are in bsdf_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/materials/bsdf_lobes.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "materials/microfacet_quadrature.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;
constexpr TransportMode kImportance = TransportMode::kImportance;

// Random unit directions on both sides, none closer than cos 0.02 to the plane.
std::vector<Vec3f> random_directions(uint64_t seed, int n) {
    Rng rng(seed, 3);
    std::vector<Vec3f> out;
    while (static_cast<int>(out.size()) < n) {
        Vec2f u = rng.next_vec2f();
        Vec3f w = direction(2.0f * u.x - 1.0f, 2.0f * kPi * u.y);
        if (std::abs(w.z) > 0.02f) out.push_back(w);
    }
    return out;
}

// |a - b| <= tol max(|a|, |b|), channel by channel.
void expect_relative_near(const Color& a, const Color& b, float tol) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(a[i], b[i], tol * std::max(std::abs(a[i]), std::abs(b[i])) + 1e-12f) << "channel " << i;
}

// ---- conductor

const ConductorLobe kGold{TrowbridgeReitz(0.3f), kGoldEta, kGoldK};
const ConductorLobe kBrushedGold{TrowbridgeReitz(0.05f, 0.4f), kGoldEta, kGoldK};

TEST(ConductorLobe, EvalIsTorranceSparrowWithComplexFresnel) {
    // f = D(wh) G(wo, wi) F(wo.wh) / (4 cos_o cos_i), wh the half vector, written out here.
    for (const ConductorLobe& lobe : {kGold, kBrushedGold}) {
        const TrowbridgeReitz& tr = lobe.distribution;
        for (const Vec3f& wo : random_directions(1, 20)) {
            for (const Vec3f& wi : random_directions(2, 20)) {
                Color f = lobe.eval(wo, wi, kRadiance);
                if (!same_hemisphere(wo, wi)) {
                    EXPECT_EQ(f, Color(0.0f));
                    EXPECT_EQ(lobe.pdf(wo, wi), 0.0f);
                    continue;
                }
                Vec3f wh = normalize(wo + wi);
                if (wh.z < 0.0f) wh = -wh;
                Color expected = fresnel_complex(abs_dot(wo, wh), kGoldEta, kGoldK) *
                               (tr.d(wh) * tr.g(wo, wi) / (4.0f * std::abs(wo.z * wi.z)));
                expect_relative_near(f, expected, 1e-5f);
                // The visible-normal density through the reflection Jacobian.
                EXPECT_NEAR(lobe.pdf(wo, wi), tr.d_visible(wo, wh) / (4.0f * abs_dot(wo, wh)),
                            1e-5f * lobe.pdf(wo, wi));
            }
        }
    }
}

TEST(ConductorLobe, IsReciprocalAndTwoSided) {
    // f(wo, wi) = f(wi, wo) (Helmholtz), and the same below the surface as above it.
    for (const ConductorLobe& lobe : {kGold, kBrushedGold}) {
        for (const Vec3f& wo : random_directions(3, 30)) {
            for (const Vec3f& wi : random_directions(4, 30)) {
                expect_relative_near(lobe.eval(wo, wi, kRadiance), lobe.eval(wi, wo, kRadiance), 1e-5f);
                Vec3f wo_below(wo.x, wo.y, -wo.z), wi_below(wi.x, wi.y, -wi.z);
                expect_relative_near(lobe.eval(wo, wi, kRadiance),
                                     lobe.eval(wo_below, wi_below, kRadiance), 1e-5f);
            }
        }
    }
}

TEST(ConductorLobe, SmoothIsTheFresnelWeightedMirror) {
    ConductorLobe lobe{TrowbridgeReitz(0.0005f), kGoldEta, kGoldK};
    EXPECT_TRUE(lobe.is_delta());
    EXPECT_FALSE(kGold.is_delta());
    for (const Vec3f& wo : probe_directions()) {
        auto s = lobe.sample(wo, 0.5f, Vec2f(0.3f, 0.7f), kRadiance);
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->is_delta);
        EXPECT_EQ(s->wi, Vec3f(-wo.x, -wo.y, wo.z));
        EXPECT_EQ(s->pdf, 1.0f);
        expect_relative_near(s->f * std::abs(s->wi.z),
                             fresnel_complex(std::abs(wo.z), kGoldEta, kGoldK), 1e-6f);
        EXPECT_EQ(lobe.eval(wo, s->wi, kRadiance), Color(0.0f));
    }
    // The albedo view shows the colour at normal incidence.
    EXPECT_EQ(lobe.albedo(), fresnel_complex(1.0f, kGoldEta, kGoldK));
}

// A conductor that reflects everything at every angle: F = 1 (a purely imaginary index).
ConductorLobe perfect_conductor(float alpha) {
    return ConductorLobe{TrowbridgeReitz(alpha), Color(0.0f), Color(1.0f)};
}

TEST(ConductorLobe, QuadratureOverNormalsAgreesWithQuadratureOverDirections) {
    // The energy tests rest on albedo_by_quadrature (an integral over microfacet normals); for
    // lobes broad enough, integrating f |cos| over the sphere of wi directly must agree.
    for (float alpha : {0.5f, 1.0f}) {
        ConductorLobe lobe = perfect_conductor(alpha);
        for (float c : {0.9f, 0.4f, -0.2f}) {
            Vec3f wo = direction(c, 0.5f);
            auto integrand = [&](double phi, double ct) {
                double st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
                Vec3f wi(Vec3d(st * std::cos(phi), st * std::sin(phi), ct));
                return double(lobe.eval(wo, wi, kRadiance)[0]) * std::abs(ct);
            };
            double by_directions = integrate_2d(integrand, -kPiD, kPiD, c > 0 ? 0.0 : -1.0,
                                                c > 0 ? 1.0 : 0.0, 1e-6);
            EXPECT_NEAR(albedo_by_quadrature(lobe, wo, kRadiance), by_directions, 1e-5)
                << alpha << ", " << c;
        }
    }
}

TEST(ConductorLobe, SingleScatteringLosesEnergyAsRoughnessGrows) {
    // With F = 1 all the loss is the light that microfacets send to other microfacets, which
    // a single-scattering model drops (Heitz et al. 2016): the albedo is below 1 and falls with
    // roughness.
    Vec3f wo(0, 0, 1);
    double previous = 1.0;
    for (float alpha : {0.1f, 0.3f, 0.5f, 0.8f, 1.0f}) {
        double albedo = albedo_by_quadrature(perfect_conductor(alpha), wo, kRadiance);
        EXPECT_LT(albedo, previous) << alpha;
        previous = albedo;
    }
    EXPECT_LT(albedo_by_quadrature(perfect_conductor(0.5f), wo, kRadiance), 0.7);
    // At alpha 1, D cos is the cosine distribution and, at normal incidence, so are the visible
    // normals; the reflection at theta_m leaves at 2 theta_m, below the surface beyond 45
    // degrees, and keeps G / G1 = 1 / (1 + Lambda(2 theta_m)) = cos(2 theta_m) / cos^2(theta_m).
    // The albedo is the integral of 2 sin cos cos(2 theta) / cos^2 over [0, pi / 4] = 1 - ln 2.
    EXPECT_NEAR(albedo_by_quadrature(perfect_conductor(1.0f), wo, kRadiance), 1.0 - std::log(2.0), 1e-5);
    // At alpha 0.1 masking is negligible; the loss is GGX's long tail: a fraction
    // alpha^2 / (alpha^2 + 1) of the normals seen at normal incidence lean beyond 45 degrees and
    // reflect below the surface.
    EXPECT_NEAR(albedo_by_quadrature(perfect_conductor(0.1f), wo, kRadiance), 1.0 - 0.01 / 1.01, 2e-3);
}

// ---- rough dielectric

const std::vector<DielectricLobe> kRoughGlasses = {
    DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.3f)},
    DielectricLobe{Color(1.0f), 1.0f / 1.5f, TrowbridgeReitz(0.1f)},
    DielectricLobe{Color(1.0f), 1.33f, TrowbridgeReitz(0.05f, 0.4f)}};

TEST(DielectricLobe, ReflectionIsReciprocal) {
    for (const DielectricLobe& lobe : kRoughGlasses) {
        for (const Vec3f& wo : random_directions(5, 30)) {
            for (const Vec3f& wi : random_directions(6, 30)) {
                if (!same_hemisphere(wo, wi)) continue;
                expect_relative_near(lobe.eval(wo, wi, kRadiance), lobe.eval(wi, wo, kRadiance), 1e-5f);
            }
        }
    }
}

TEST(DielectricLobe, TransmissionObeysTheGeneralizedReciprocity) {
    // Veach's thesis, 5.2: the BSDF of radiance satisfies f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2
    // (n_o, n_i the indices on wo's and wi's sides), and the importance BSDF is its adjoint:
    // f_importance(wo, wi) = f_radiance(wi, wo). The two evaluations round the half vector
    // differently, by ~1e-7, which changes a direction's cosine c to the microfacet by 1e-7 / c
    // relative: the tolerance allows that beside a few float roundings.
    for (const DielectricLobe& lobe : kRoughGlasses) {
        for (const Vec3f& wo : random_directions(7, 30)) {
            for (const Vec3f& wi : random_directions(8, 30)) {
                if (same_hemisphere(wo, wi)) continue;
                float n_o = wo.z > 0.0f ? 1.0f : lobe.eta, n_i = wi.z > 0.0f ? 1.0f : lobe.eta;
                Vec3f wm = normalize(wo * n_o + wi * n_i);
                float tol = 2e-5f + 2e-7f / std::min(abs_dot(wo, wm), abs_dot(wi, wm));
                Color forward = lobe.eval(wo, wi, kRadiance), backward = lobe.eval(wi, wo, kRadiance);
                expect_relative_near(forward / (n_o * n_o), backward / (n_i * n_i), tol);
                expect_relative_near(lobe.eval(wo, wi, kImportance), backward, tol);
            }
        }
    }
}

TEST(DielectricLobe, RoughReflectionPlusTransmissionIsAtMostOne) {
    // In importance mode (no 1 / eta'^2) a single-scattering interface can only lose energy:
    // R + T <= 1 from either side. From the optically thinner side near normal incidence it is
    // close to 1 (refraction bends toward the normal and little is masked); from the denser
    // side, light refracted out through tilted microfacets may leave below the surface, which a
    // single-scattering model loses (about 10% at alpha 0.3).
    for (const DielectricLobe& lobe : kRoughGlasses) {
        for (float c : {1.0f, 0.7f, 0.3f, 0.05f, -0.05f, -0.3f, -0.7f, -1.0f}) {
            Vec3f wo = direction(c, 0.8f);
            double albedo = albedo_by_quadrature(lobe, wo, kImportance);
            EXPECT_LE(albedo, 1.0 + 1e-5) << lobe.eta << ", cos " << c;
            bool thinner_side = (c > 0.0f) == (lobe.eta > 1.0f);
            if (thinner_side && std::abs(c) >= 0.7f && lobe.distribution.alpha_y <= 0.3f) {
                EXPECT_GT(albedo, 0.95) << lobe.eta << ", cos " << c;
            }
        }
    }
}

TEST(DielectricLobe, SmoothIsFresnelSpecularWithExactFresnel) {
    // R + T = 1: the two choices' weights (in importance mode) are F / F and (1 - F) / (1 - F)
    // times the tint; the samples are those of FresnelSpecularLobe without Schlick.
    const Color tint(1.0f, 0.9f, 0.8f);
    for (float eta : {1.5f, 1.0f / 1.5f}) {
        DielectricLobe lobe{tint, eta, TrowbridgeReitz(0.0f)};
        FresnelSpecularLobe reference{tint, eta, false};
        EXPECT_TRUE(lobe.is_delta());
        for (const Vec3f& wo : probe_directions()) {
            for (float uc : {0.0f, 0.03f, 0.5f, kOneMinusEpsilon}) {
                auto s = lobe.sample(wo, uc, Vec2f(0.5f, 0.5f), kRadiance);
                auto r = reference.sample(wo, uc, Vec2f(0.5f, 0.5f), kRadiance);
                ASSERT_EQ(s.has_value(), r.has_value());
                if (!s) continue;
                EXPECT_EQ(s->wi, r->wi);
                EXPECT_EQ(s->f, r->f);
                EXPECT_EQ(s->pdf, r->pdf);
                EXPECT_EQ(s->eta, r->eta);
            }
        }
    }
    // eta = 1 is no interface at all: everything passes straight through, as a delta.
    DielectricLobe air{Color(1.0f), 1.0f, TrowbridgeReitz(0.3f)};
    EXPECT_TRUE(air.is_delta());
    auto s = air.sample(direction(0.6f, 1.0f), 0.0f, Vec2f(0.5f, 0.5f), kRadiance);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_transmission);
    EXPECT_NEAR(s->wi.z, -0.6f, 1e-6f);
}

// ---- thin dielectric

TEST(ThinDielectricLobe, ReflectsTheInterReflectedFresnelSumAndTransmitsStraight) {
    // R' = R + T^2 R / (1 - R^2) = 2R / (1 + R): the geometric series of reflections between
    // the two faces. Normal incidence on a glass pane: 2 0.04 / 1.04 = 7.7%.
    ThinDielectricLobe pane{1.5f};
    EXPECT_NEAR(pane.reflectance(Vec3f(0, 0, 1)), 0.08f / 1.04f, 1e-6f);
    for (const Vec3f& wo : probe_directions()) {
        float r = fresnel_dielectric(std::abs(wo.z), 1.5f);
        float expected = 2.0f * r / (1.0f + r);
        ASSERT_NEAR(pane.reflectance(wo), expected, 1e-6f) << wo.z;
        for (TransportMode mode : {kRadiance, kImportance}) {
            auto reflected = pane.sample(wo, 0.0f, Vec2f(), mode);
            auto transmitted = pane.sample(wo, kOneMinusEpsilon, Vec2f(), mode);
            ASSERT_TRUE(reflected && transmitted);
            EXPECT_EQ(reflected->wi, Vec3f(-wo.x, -wo.y, wo.z));
            EXPECT_FALSE(reflected->is_transmission);
            EXPECT_EQ(transmitted->wi, -wo);
            EXPECT_TRUE(transmitted->is_transmission);
            EXPECT_EQ(transmitted->eta, 1.0f);
            // Each choice weighs 1, so R' + T' = 1 whatever the transport mode.
            EXPECT_NEAR(reflected->f[0] * std::abs(wo.z) / reflected->pdf, 1.0f, 1e-5f);
            EXPECT_NEAR(transmitted->f[0] * std::abs(wo.z) / transmitted->pdf, 1.0f, 1e-5f);
            EXPECT_NEAR(reflected->pdf + transmitted->pdf, 1.0f, 1e-6f);
        }
    }
    // An index of 1 is no pane at all.
    EXPECT_LT(ThinDielectricLobe{1.0f}.reflectance(direction(0.3f, 0.0f)), 1e-12f);
}

}  // namespace
}  // namespace candela::test
