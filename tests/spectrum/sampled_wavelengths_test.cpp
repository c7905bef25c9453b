// The visible-wavelength density and its sampler (spectrum/sampled_wavelengths.h): the density
// integrates to 1 over [360, 830] nm, the sampler inverts its CDF (deterministic Jacobian check),
// the four wavelengths are a quarter apart in the sampler's number, and terminate_secondary keeps
// only the hero with a quarter of its pdf.
#include "candela/spectrum/sampled_wavelengths.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "support/chi2.h"

namespace candela {
namespace CANDELA_UNITY_ID {

TEST(VisibleWavelengthPdf, IntegratesToOneOverTheVisibleRange) {
    const auto pdf = [](double lambda) { return double(visible_wavelength_pdf(float(lambda))); };
    const double integral = test::detail::integrate_1d(pdf, kLambdaMin, kLambdaMax, 1e-10);
    // pbrt-v4's constants make the exact integral A / B (tanh(292 B) + tanh(178 B)) = 1 - 7e-9;
    // each float evaluation rounds by a few FLT_EPSILON relative (cosh, the square, the division),
    // which bounds the integral's error by 4 FLT_EPSILON = 5e-7.
    EXPECT_NEAR(integral, 1.0, 4.0 * double(FLT_EPSILON));
}

TEST(VisibleWavelengthPdf, IsZeroOutsideTheVisibleRange) {
    EXPECT_EQ(visible_wavelength_pdf(359.9f), 0.0f);
    EXPECT_EQ(visible_wavelength_pdf(830.1f), 0.0f);
    EXPECT_EQ(visible_wavelength_pdf(-1.0f), 0.0f);
    EXPECT_GT(visible_wavelength_pdf(360.0f), 0.0f);
    EXPECT_GT(visible_wavelength_pdf(830.0f), 0.0f);
    // Its peak is at 538 nm, near y-bar's 555 nm and x-bar + y-bar + z-bar's.
    EXPECT_GT(visible_wavelength_pdf(538.0f), visible_wavelength_pdf(500.0f));
    EXPECT_GT(visible_wavelength_pdf(538.0f), visible_wavelength_pdf(580.0f));
}

TEST(SampleVisibleWavelength, InvertsTheCdf) {
    // The ends of [0, 1] go to the ends of the range; in between, d lambda / du = 1 / pdf (the
    // Jacobian of an inverse-CDF map), checked by central differences at every 0.01 of u. The
    // difference quotient in float: lambda rounds by half an ulp of 830 (3e-5 nm) over a step of
    // 2h = 2e-3 in u, a relative error of about 3e-5 / (2e-3 * 200 nm) < 1e-4; the curvature's
    // error h^2 lambda''' / 6 is smaller still. So 1e-3 relative.
    EXPECT_NEAR(sample_visible_wavelength(0.0f), kLambdaMin, 1e-3f);
    EXPECT_NEAR(sample_visible_wavelength(1.0f), kLambdaMax, 1e-3f);
    const float h = 1e-3f;
    float previous = sample_visible_wavelength(0.0f);
    for (int k = 1; k < 100; ++k) {
        const float u = float(k) / 100.0f;
        const float lambda = sample_visible_wavelength(u);
        EXPECT_GT(lambda, previous) << u;  // increasing
        previous = lambda;
        const double slope = (double(sample_visible_wavelength(u + h)) - double(sample_visible_wavelength(u - h))) /
                             (2.0 * double(h));
        EXPECT_NEAR(slope * double(visible_wavelength_pdf(lambda)), 1.0, 1e-3) << "u = " << u;
    }
}

TEST(SampledWavelengths, FourWavelengthsAQuarterApartInU) {
    for (float u : {0.0f, 0.1f, 0.3f, 0.5f, 0.74f, 0.99f}) {
        const SampledWavelengths w = SampledWavelengths::sample_visible(u);
        for (int i = 0; i < kColorChannels; ++i) {
            float ui = u + float(i) / 4.0f;
            if (ui > 1.0f) ui -= 1.0f;
            EXPECT_EQ(w.lambda[i], sample_visible_wavelength(ui)) << u << " " << i;
            // The exact density of the transform, (1 - t^2) / (b c), against pbrt-v4's cosh form
            // evaluated in float: equal up to a few float roundings of each (1e-5 relative is
            // about 80 ulps, far below any error a renderer could see).
            EXPECT_NEAR(w.pdf[i], visible_wavelength_pdf(w.lambda[i]), 1e-5f * w.pdf[i]) << u << " " << i;
            EXPECT_GT(w.pdf[i], 0.0f);
        }
        EXPECT_FALSE(w.secondary_terminated());
    }
}

TEST(SampledWavelengths, TerminateSecondaryKeepsTheHeroWithAQuarterOfItsPdf) {
    SampledWavelengths w = SampledWavelengths::sample_visible(0.3f);
    const SampledWavelengths before = w;
    w.terminate_secondary();
    EXPECT_TRUE(w.secondary_terminated());
    EXPECT_EQ(w.lambda, before.lambda);  // the wavelengths stay, their pdfs go
    EXPECT_EQ(w.pdf[0], before.pdf[0] / 4.0f);
    for (int i = 1; i < kColorChannels; ++i) EXPECT_EQ(w.pdf[i], 0.0f) << i;
    // A second termination (a second dispersive refraction) changes nothing.
    const SampledWavelengths once = w;
    w.terminate_secondary();
    EXPECT_EQ(w.pdf, once.pdf);
    EXPECT_EQ(w.lambda, once.lambda);
}

}  // namespace
}  // namespace candela
