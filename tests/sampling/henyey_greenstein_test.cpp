// The Henyey-Greenstein phase function: normalized, with mean cosine g in the direction of
// travel, and sampled with the value it reports (its chi-square fit is in layered_stat_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "candela/sampling/henyey_greenstein.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The integral over the sphere of p(cos) weight(cos), by the midpoint rule in cos (d omega =
// 2 pi d cos for a function of cos alone); 100000 intervals resolve the peak of |g| = 0.9.
template <class F>
double integrate_over_cos(float g, F weight) {
    const int n = 100000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double c = -1.0 + 2.0 * (i + 0.5) / n;
        sum += double(henyey_greenstein(float(c), g)) * weight(c);
    }
    return sum * 2.0 * kPiD * 2.0 / n;
}

TEST(HenyeyGreenstein, IntegratesToOneWithMeanCosineG) {
    for (float g : {-0.9f, -0.5f, 0.0f, 0.3f, 0.9f}) {
        SCOPED_TRACE(testing::Message() << "g = " << g);
        EXPECT_NEAR(integrate_over_cos(g, [](double) { return 1.0; }), 1.0, 1e-4);
        // cos = dot(wo, wi) with wo pointing back along the incoming light: travelling on is
        // cos = -1, so the mean of -cos is g (forward scattering for g > 0).
        EXPECT_NEAR(integrate_over_cos(g, [](double c) { return -c; }), double(g), 1e-4);
    }
}

TEST(HenyeyGreenstein, IsotropicAtZeroAndClampedNearOne) {
    EXPECT_FLOAT_EQ(henyey_greenstein(0.3f, 0.0f), kInv4Pi);
    EXPECT_EQ(henyey_greenstein(-1.0f, 1.0f), henyey_greenstein(-1.0f, 0.99f));
    EXPECT_EQ(henyey_greenstein(0.5f, -1.0f), henyey_greenstein(0.5f, -0.99f));
    EXPECT_TRUE(std::isfinite(henyey_greenstein(-1.0f, 1.0f)));
}

TEST(HenyeyGreenstein, SamplesReportTheFunctionAtTheirDirection) {
    Rng rng(5, 8);
    for (float g : {-0.7f, 0.0f, 0.0005f, 0.6f, 1.0f}) {
        for (const Vec3f& wo : probe_directions()) {
            for (int i = 0; i < 200; ++i) {
                PhaseSample s = sample_henyey_greenstein(wo, g, rng.next_vec2f());
                EXPECT_NEAR(length(s.wi), 1.0f, 1e-5f);
                float expected = henyey_greenstein(dot(wo, s.wi), g);
                // At g = 1 (clamped to 0.99) the peak's denominator (1 - g)^2 = 1e-4 magnifies
                // the float rounding of the cosine (6e-8) some 2e4 times.
                float tol = g == 1.0f ? 1e-2f : 1e-3f;
                EXPECT_NEAR(s.p, expected, tol * expected) << "g = " << g;
            }
        }
    }
}

}  // namespace
}  // namespace candela::test
