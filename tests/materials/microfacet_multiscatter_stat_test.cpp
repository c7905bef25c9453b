// Sampling of rough conductors and dielectrics with the multiple-scattering compensation on
// (materials/microfacet_multiscatter.h): chi-square goodness of fit of sample() against pdf() on
// the full sphere of directions (tests/support/chi2.h), and the sample weights' mean against the
// white furnace.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/conductor.h"
#include "candela/materials/dielectric.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 10;

template <class Lobe>
void expect_sampling_fits_pdf(const Lobe& lobe, Vec3f wo) {
    ASSERT_TRUE(lobe.multiscatter);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
        if (!s) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](Vec3f wi) { return lobe.pdf(wo, wi); };
    // The pdf integrates to the probability that sampling succeeds (the single-scattering part
    // fails for normals that reflect through the surface), known only numerically: the histogram's
    // cells compare it with the counts.
    opt.expected_integral = std::nullopt;
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

ConductorLobe gold(float ax, float ay) {
    return ConductorLobe{TrowbridgeReitz(ax, ay), kGoldEta, kGoldK}.with_multiscatter();
}
DielectricLobe glass(float alpha, float eta) {
    return DielectricLobe{Color(1.0f), eta, TrowbridgeReitz(alpha)}.with_multiscatter();
}

TEST(MultiscatterChi2, ConductorAlphaPoint1) { expect_sampling_fits_pdf(gold(0.1f, 0.1f), direction(0.7f, 0.3f)); }
TEST(MultiscatterChi2, ConductorAlphaPoint5Grazing) {
    expect_sampling_fits_pdf(gold(0.5f, 0.5f), direction(0.15f, 1.0f));
}
TEST(MultiscatterChi2, ConductorAlpha1BelowTheSurface) {
    expect_sampling_fits_pdf(gold(1.0f, 1.0f), direction(-0.6f, 2.0f));
}
TEST(MultiscatterChi2, ConductorAnisotropic) { expect_sampling_fits_pdf(gold(0.05f, 0.4f), direction(0.5f, 0.8f)); }
TEST(MultiscatterChi2, DielectricFromOutside) { expect_sampling_fits_pdf(glass(0.3f, 1.5f), direction(0.6f, 0.2f)); }
TEST(MultiscatterChi2, DielectricFromInside) { expect_sampling_fits_pdf(glass(0.3f, 1.5f), direction(-0.8f, 1.2f)); }
TEST(MultiscatterChi2, DielectricFromInsidePastTheCriticalAngle) {
    expect_sampling_fits_pdf(glass(0.5f, 1.5f), direction(-0.4f, 1.2f));
}
TEST(MultiscatterChi2, DielectricBelowOne) {
    expect_sampling_fits_pdf(glass(0.5f, 1.0f / 1.33f), direction(0.5f, 2.2f));
}
TEST(MultiscatterChi2, DielectricAlpha1Grazing) { expect_sampling_fits_pdf(glass(1.0f, 1.5f), direction(0.1f, 0.5f)); }
TEST(MultiscatterChi2, DielectricAnisotropic) {
    expect_sampling_fits_pdf(DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.05f, 0.4f)}.with_multiscatter(),
                             direction(0.5f, 0.8f));
}

// ---- the sample weights f |cos| / pdf average to the directional albedo, 1 in a white furnace

// Mean and standard error of the weights (red channel; failed samples count 0).
template <class Lobe>
std::pair<double, double> mean_weight(const Lobe& lobe, Vec3f wo, TransportMode mode) {
    Rng rng(41, 7);
    const int n = 200'000;
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < n; ++i) {
        float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), mode);
        double w = s ? double(s->f[0]) * double(std::abs(s->wi.z)) / double(s->pdf) : 0.0;
        sum += w;
        sum_sq += w * w;
    }
    double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum_sq / n - mean * mean) / (n - 1.0))};
}

TEST(MultiscatterFurnace, SampleWeightsOfWhiteLobesAverageToOne) {
    // Within 5 standard errors plus the tables' 0.5 % (microfacet_multiscatter_test.cpp measures
    // that part deterministically).
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
        ConductorLobe metal = ConductorLobe{TrowbridgeReitz(alpha), Color(1.0f), Color(2e4f)}.with_multiscatter();
        DielectricLobe dielectric = glass(alpha, 1.5f);
        for (float c : {0.9f, 0.5f, -0.3f}) {
            auto [m, se] = mean_weight(metal, direction(c, 0.4f), kRadiance);
            EXPECT_NEAR(m, 1.0, 5.0 * se + 0.005) << "conductor alpha " << alpha << ", cos " << c;
            auto [d, dse] = mean_weight(dielectric, direction(c, 0.4f), TransportMode::kImportance);
            EXPECT_NEAR(d, 1.0, 5.0 * dse + 0.005) << "dielectric alpha " << alpha << ", cos " << c;
        }
    }
}

}  // namespace
}  // namespace candela::test
