// Chi-square goodness of fit of the four wavelengths SampledWavelengths::sample_visible draws
// against visible_wavelength_pdf (tests/support/chi2.h). Each of the four, the hero and the three
// shifted by a quarter, is on its own distributed by that density.
#include <gtest/gtest.h>

#include "candela/spectrum/sampled_wavelengths.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = kColorChannels;

// Wavelength `channel` of sample_visible against `pdf` (per nm), on [360, 830] nm in 94 cells of
// 5 nm (the domain's second parameter is unused: one row).
template <class Pdf>
Chi2Result wavelength_chi2(int channel, Pdf pdf) {
    Chi2Options opt;
    opt.res_x = 94;
    opt.res_y = 1;
    opt.test_count = kChi2Tests;
    auto sample = [channel](Sampler& rng) {
        const SampledWavelengths w = SampledWavelengths::sample_visible(rng.next_float());
        return Vec2f(w.lambda[channel], 0.5f);
    };
    return chi2_test(PlanarDomain{{double(kLambdaMin), 0.0}, {double(kLambdaMax), 1.0}}, sample, pdf, opt);
}

Chi2Result wavelength_chi2(int channel) {
    return wavelength_chi2(channel, [](Vec2f p) { return visible_wavelength_pdf(p.x); });
}

TEST(SampledWavelengthsChi2, HeroMatchesVisiblePdf) {
    Chi2Result r = wavelength_chi2(0);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(SampledWavelengthsChi2, EachSecondaryMatchesVisiblePdf) {
    for (int channel = 1; channel < kColorChannels; ++channel) {
        Chi2Result r = wavelength_chi2(channel);
        EXPECT_TRUE(r.passed) << "wavelength " << channel << ": " << r.message;
    }
}

TEST(SampledWavelengthsChi2, ControlRejectsAUniformPdf) {
    // The test has power: the same samples against the uniform density on [360, 830] fail.
    Chi2Result r = wavelength_chi2(0, [](Vec2f) { return 1.0f / (kLambdaMax - kLambdaMin); });
    EXPECT_FALSE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
