// The Trowbridge-Reitz distribution: D's projected area is the macro-surface's, the visible
// normals' density integrates to 1 (the definition of G1 through Lambda), Lambda and G1 against
// their closed forms, and the smooth threshold. The sampler's chi-square test is in
// trowbridge_reitz_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "candela/materials/trowbridge_reitz.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "materials/microfacet_quadrature.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The integrals below are accurate to about 1e-6: D and D_w are evaluated in float (relative
// error ~1e-6) and integrated to 1e-7 per piece; 5e-5 leaves room for that and nothing more.
const std::vector<TrowbridgeReitz> kDistributions = {
    TrowbridgeReitz(0.01f), TrowbridgeReitz(0.1f),        TrowbridgeReitz(0.3f),
    TrowbridgeReitz(0.8f),  TrowbridgeReitz(1.0f),        TrowbridgeReitz(0.05f, 0.4f),
    TrowbridgeReitz(0.8f, 0.1f)};

double min_alpha(const TrowbridgeReitz& tr) { return double(std::min(tr.alpha_x, tr.alpha_y)); }

TEST(TrowbridgeReitz, ProjectedAreaOfTheNormalsIsOne) {
    // The microfacets' area projected onto the macro-surface is its area: the integral of
    // D(wm) cos(theta_m) over the hemisphere is 1 (Heitz 2014, eq. 4).
    for (const TrowbridgeReitz& tr : kDistributions) {
        double integral = integrate_hemisphere(
            [&](Vec3f wm) { return double(tr.d(wm)) * double(wm.z); }, min_alpha(tr), 1e-7);
        EXPECT_NEAR(integral, 1.0, 5e-5) << tr.alpha_x << ", " << tr.alpha_y;
    }
}

TEST(TrowbridgeReitz, DMatchesTheSlopeSpaceDensity) {
    // An independent form of D: the stretched slope density over cos^4 (ggx_d), in double.
    for (const TrowbridgeReitz& tr : kDistributions) {
        for (float c : {1.0f, 0.99f, 0.9f, 0.5f, 0.1f}) {
            for (float phi : {0.0f, 0.7f, 2.0f, 4.0f}) {
                Vec3f wm = direction(c, phi);
                double expected = ggx_d(tr, Vec3d(wm));
                EXPECT_NEAR(double(tr.d(wm)), expected, 2e-6 * expected) << c << ", " << phi;
            }
        }
        EXPECT_EQ(tr.d(direction(-0.5f, 1.0f)), 0.0f);
        EXPECT_EQ(tr.d(Vec3f(1, 0, 0)), 0.0f);
    }
}

// Directions on both sides, from normal incidence to grazing, at azimuths that tell the axes
// of an anisotropic distribution apart.
std::vector<Vec3f> test_directions() {
    std::vector<Vec3f> out;
    for (float c : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f, -0.3f, -0.9f})
        for (float phi : {0.0f, 1.0f, 2.5f}) out.push_back(direction(c, phi));
    return out;
}

TEST(TrowbridgeReitz, VisibleNormalDensityIntegratesToOne) {
    // D_w(wm) = G1(w) max(0, w.wm) D(wm) / cos(theta_w) integrates to 1 exactly when G1 is the
    // ratio of the macro-surface's projected area to the visible microfacets' (Heitz 2014,
    // eq. 38): this checks G1 and Lambda against D itself.
    for (const TrowbridgeReitz& tr : kDistributions) {
        for (const Vec3f& w : test_directions()) {
            double integral = integrate_hemisphere(
                [&](Vec3f wm) { return double(tr.d_visible(w, wm)); }, min_alpha(tr), 1e-7);
            EXPECT_NEAR(integral, 1.0, 5e-5)
                << tr.alpha_x << ", " << tr.alpha_y << ", w = (" << w.x << ", " << w.y << ", "
                << w.z << ")";
        }
    }
}

TEST(TrowbridgeReitz, LambdaAndG1MatchTheirClosedForms) {
    // Lambda = (-1 + sqrt(1 + alpha(phi)^2 tan^2(theta))) / 2 with alpha(phi)^2 = cos^2(phi) ax^2
    // + sin^2(phi) ay^2 (Heitz 2014, eq. 86 and section 5.3), in double.
    for (const TrowbridgeReitz& tr : kDistributions) {
        for (const Vec3f& w : test_directions()) {
            Vec3d v(w);
            double sin2 = v.x * v.x + v.y * v.y;
            double tan2 = sin2 / (v.z * v.z);
            double alpha2 = sin2 == 0.0 ? 0.0
                                        : (v.x * v.x * sqr(double(tr.alpha_x)) +
                                           v.y * v.y * sqr(double(tr.alpha_y))) / sin2;
            double lambda = (-1.0 + std::sqrt(1.0 + alpha2 * tan2)) / 2.0;
            EXPECT_NEAR(double(tr.lambda(w)), lambda, 1e-5 * (1.0 + lambda));
            EXPECT_NEAR(double(tr.g1(w)), 1.0 / (1.0 + lambda), 1e-6);
        }
        // In the plane nothing is visible.
        EXPECT_EQ(tr.g1(Vec3f(0.6f, 0.8f, 0.0f)), 0.0f);
        EXPECT_EQ(tr.lambda(Vec3f(0, 0, 1)), 0.0f);
    }
}

TEST(TrowbridgeReitz, HeightCorrelatedGLiesBetweenTheProductAndTheMinimum) {
    // 1 / (1 + La + Lb) >= 1 / ((1 + La) (1 + Lb)) (uncorrelated) and <= min(G1): the
    // height-correlated form lies between the two limits of correlation (Heitz 2014, 6.2).
    for (const TrowbridgeReitz& tr : kDistributions) {
        for (const Vec3f& a : test_directions()) {
            for (const Vec3f& b : test_directions()) {
                float g = tr.g(a, b);
                EXPECT_GE(g, tr.g1(a) * tr.g1(b) * (1.0f - 1e-6f));
                EXPECT_LE(g, std::min(tr.g1(a), tr.g1(b)) * (1.0f + 1e-6f));
                EXPECT_EQ(g, tr.g(b, a));
            }
        }
    }
}

TEST(TrowbridgeReitz, VisibleNormalsFaceTheViewer) {
    // Sampled normals lie in the upper hemisphere, facing w (or -w below the surface), and
    // where the density is positive.
    Rng rng(3, 1);
    for (const TrowbridgeReitz& tr : kDistributions) {
        for (const Vec3f& w : test_directions()) {
            for (int i = 0; i < 200; ++i) {
                Vec3f wm = tr.sample_wm(w, rng.next_vec2f());
                ASSERT_NEAR(length(wm), 1.0f, 1e-5f);
                EXPECT_GE(wm.z, 0.0f);
                EXPECT_GE(w.z > 0.0f ? dot(w, wm) : -dot(w, wm), -1e-6f);
                EXPECT_GT(tr.pdf(w, wm), 0.0f);
            }
        }
    }
}

TEST(TrowbridgeReitz, EffectivelySmoothBelowAlphaOneThousandth) {
    EXPECT_TRUE(TrowbridgeReitz(0.0f).effectively_smooth());
    EXPECT_TRUE(TrowbridgeReitz(0.00099f).effectively_smooth());
    EXPECT_FALSE(TrowbridgeReitz(0.001f).effectively_smooth());
    EXPECT_FALSE(TrowbridgeReitz(0.0f, 0.01f).effectively_smooth());
    // A rough distribution keeps its other axis away from 0.
    TrowbridgeReitz stripe(0.0f, 0.5f);
    EXPECT_EQ(stripe.alpha_x, 1e-4f);
    EXPECT_EQ(stripe.alpha_y, 0.5f);
    EXPECT_EQ(TrowbridgeReitz(0.0f).alpha_x, 0.0f);
}

}  // namespace
}  // namespace candela::test
