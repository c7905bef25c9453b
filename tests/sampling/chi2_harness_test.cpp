// The chi-square harness's own arithmetic: p-values against closed forms, the Sidak level, and
// the cell integration. Its power to reject is tested in chi2_harness_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// Q(n, y) for integer n in closed form: exp(-y) sum_{i<n} y^i / i! (the Poisson CDF), each term
// through logarithms so large n neither overflows nor underflows.
double gamma_q_integer(int n, double y) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += std::exp(-y + i * std::log(y) - std::lgamma(i + 1.0));
    return sum;
}

TEST(Chi2Harness, PValueMatchesClosedFormsForSmallDof) {
    for (double x : {0.01, 0.5, 1.0, 3.841458820694124, 10.0, 40.0}) {
        EXPECT_NEAR(chi2_p_value(x, 1.0), std::erfc(std::sqrt(0.5 * x)), 1e-12) << x;
        EXPECT_NEAR(chi2_p_value(x, 2.0), std::exp(-0.5 * x), 1e-12) << x;
        EXPECT_NEAR(chi2_p_value(x, 4.0), std::exp(-0.5 * x) * (1.0 + 0.5 * x), 1e-12) << x;
    }
    EXPECT_NEAR(chi2_p_value(3.841458820694124, 1.0), 0.05, 1e-12);
    EXPECT_NEAR(chi2_p_value(18.307038053275146, 10.0), 0.05, 1e-10);
}

TEST(Chi2Harness, PValueMatchesClosedFormsForThousandsOfDof) {
    // Both branches (series below a + 1, continued fraction above) around the mean.
    for (int n : {100, 1000, 2500})
        for (double ratio : {0.9, 0.97, 1.0, 1.03, 1.1}) {
            double y = ratio * n;
            double expected = gamma_q_integer(n, y);
            EXPECT_NEAR(chi2_p_value(2.0 * y, 2.0 * n), expected, 1e-9 + 1e-8 * expected)
                << "dof " << 2 * n << ", statistic " << 2.0 * y;
        }
}

TEST(Chi2Harness, PValueIsOneAtZeroAndFallsWithTheStatistic) {
    EXPECT_EQ(chi2_p_value(0.0, 5.0), 1.0);
    double previous = 1.0;
    for (double x = 100.0; x < 400.0; x += 10.0) {
        double p = chi2_p_value(x, 200.0);
        EXPECT_LT(p, previous);
        previous = p;
    }
    EXPECT_LT(chi2_p_value(400.0, 200.0), 1e-12);
}

TEST(Chi2Harness, SidakLevelKeepsTheFamilyWiseRate) {
    EXPECT_NEAR(sidak_alpha(0.01, 1), 0.01, 1e-15);
    for (int m : {2, 10, 40}) EXPECT_NEAR(std::pow(1.0 - sidak_alpha(0.01, m), m), 0.99, 1e-12);
    EXPECT_LT(sidak_alpha(0.01, 10), 0.01 / 10.0 * 1.01);  // close to Bonferroni's alpha / m
    EXPECT_GT(sidak_alpha(0.01, 10), 0.01 / 10.0);
}

TEST(Chi2Harness, CellIntegrationIsExactForPolynomialsAndAccurateAtSteps) {
    PlanarDomain square{{0.0, 0.0}, {2.0, 1.0}};
    // x^2 y over [0, 2] x [0, 1] is 8/3 * 1/2; Simpson is exact for cubics.
    auto poly = [](Vec2f p) { return p.x * p.x * p.y; };
    EXPECT_NEAR(integrate_pdf(square, poly, 7, 3), 4.0 / 3.0, 1e-6);
    // The unit disk's quarter inside the square [0, 1]^2 (a curved step through the cells).
    PlanarDomain unit{{0.0, 0.0}, {1.0, 1.0}};
    auto quarter_disk = [](Vec2f p) { return p.x * p.x + p.y * p.y <= 1.0f ? 1.0f : 0.0f; };
    EXPECT_NEAR(integrate_pdf(unit, quarter_disk, 9, 9), kPiD / 4.0, 1e-5);
}

TEST(Chi2Harness, SphericalDomainHasUnitJacobian) {
    // The parametrisation covers the sphere's 4 pi steradians, and round-trips directions.
    EXPECT_NEAR(integrate_pdf(SphericalDomain{}, [](Vec3f) { return 1.0f; }), 4.0 * kPiD, 1e-6);
    SphericalDomain sphere;
    Vec3f w = normalize(Vec3f(0.3f, -0.5f, 0.2f));
    Vec3f back = sphere.from_param(sphere.to_param(w));
    EXPECT_NEAR(back.x, w.x, 1e-6f);
    EXPECT_NEAR(back.y, w.y, 1e-6f);
    EXPECT_NEAR(back.z, w.z, 1e-6f);
}

}  // namespace
}  // namespace candela::test
