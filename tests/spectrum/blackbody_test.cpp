// Planck's law, the blackbody spectrum normalized by Wien's displacement law, and the CIE
// daylight illuminants (spectrum/blackbody.h) against published values.
#include "candela/spectrum/blackbody.h"

#include <gtest/gtest.h>

#include <cmath>

#include "candela/spectrum/named_spectra.h"
#include "spectrum/chromaticity.h"

namespace candela {
namespace CANDELA_UNITY_ID {

using test::chromaticity;
using test::Xy;

// Spectral radiance from spectralcalc.com's blackbody calculator, as quoted by pbrt-v4's
// spectrum_test.cpp, in W / (m^2 sr m); given to 5 or 6 digits.
TEST(Planck, MatchesPublishedRadiance) {
    struct Case {
        double nm, kelvin, radiance;
    };
    for (const Case& c : {Case{483, 6000, 3.1849e13}, Case{600, 6000, 2.86772e13},
                          Case{500, 3700, 1.59845e12}, Case{600, 4500, 7.46497e12}}) {
        // The quoted digits leave 5e-5 relative; the constants' last digits change less.
        EXPECT_NEAR(planck(c.nm, c.kelvin) / c.radiance, 1.0, 1e-4) << c.nm << " nm, " << c.kelvin << " K";
    }
    EXPECT_EQ(planck(500.0, 0.0), 0.0);
}

TEST(Planck, PeaksAtWiensLambdaMax) {
    for (double t : {2700.0, 3000.0, 4500.0, 5600.0, 6000.0}) {
        const double peak = kWienDisplacement / t * 1e9;
        EXPECT_LT(planck(0.99 * peak, t), planck(peak, t)) << t;
        EXPECT_GT(planck(peak, t), planck(1.01 * peak, t)) << t;
    }
}

// pbrt-v4's BlackbodySpectrum is 1 at lambda_max = b / T and below 1 elsewhere. At T = b / 580 nm
// the peak falls on a tabulated nm, so the table holds the 1 itself: the two Planck values
// differ only by T's rounding to float (relative 6e-8 in lambda_max, whose effect on a maximum is
// of second order), and the quotient rounds to float. Away from the peak the spectrum falls at
// every nm on both sides.
TEST(BlackbodySpectrum, IsOneAtWiensPeakAndFallsAwayFromIt) {
    const auto t = float(kWienDisplacement / 580e-9);
    const DenseSpectrum s = blackbody_spectrum(t);
    EXPECT_NEAR(s(580.0f), 1.0f, 2e-7f);
    EXPECT_EQ(s.max_value(), s(580.0f));
    for (int lambda = 580; lambda > kDenseLambdaMin; --lambda)
        EXPECT_LT(s(float(lambda - 1)), s(float(lambda))) << lambda;
    for (int lambda = 580; lambda < kDenseLambdaMax; ++lambda)
        EXPECT_LT(s(float(lambda + 1)), s(float(lambda))) << lambda;
}

// Below 3491 K the peak is beyond 830 nm: the visible part rises all the way, below 1.
TEST(BlackbodySpectrum, RisesThroughTheVisibleWhenThePeakIsInTheInfrared) {
    const DenseSpectrum s = blackbody_spectrum(2000.0f);
    for (int lambda = kDenseLambdaMin + 1; lambda <= kDenseLambdaMax; ++lambda)
        EXPECT_GT(s(float(lambda)), s(float(lambda - 1))) << lambda;
    EXPECT_LT(s.max_value(), 1.0f);
}

// CIE illuminant A is a Planckian radiator of 2856 K (2848 K with the c2 of 1931), chromaticity
// x = 0.44757, y = 0.40745 (CIE 15:2004); the issue asks for 1e-3. The same against pbrt-v4's
// table of A (named "stdillum-A"), which its 5-nm steps interpolate.
TEST(BlackbodySpectrum, At2856KelvinHasTheChromaticityOfIlluminantA) {
    const Xy bb = chromaticity(blackbody_spectrum(2856.0f));
    EXPECT_NEAR(bb.x, 0.4476, 1e-3);
    EXPECT_NEAR(bb.y, 0.4074, 1e-3);
    const Xy a = chromaticity(*named_spectrum("stdillum-A"));
    EXPECT_NEAR(a.x, 0.4476, 1e-3);
    EXPECT_NEAR(a.y, 0.4074, 1e-3);
    EXPECT_NEAR(bb.x, a.x, 1e-3);
    EXPECT_NEAR(bb.y, a.y, 1e-3);
}

// Spectra::D(6500) is D65: the nominal 6500 K moved to today's c2 is 6504 K, where CIE 15:2004
// computes D65 from S0, S1, S2. The CIE table rounds M1 and M2 to 3 decimals (at most 5e-4
// times |S1|, |S2| <= 45: 0.02 of 100 at 560 nm) and its values to 6 digits: within 2.5e-4
// after pbrt-v4's scale of 1/100. Its chromaticity is D65's, (0.31272, 0.32903).
TEST(CieDaylight, At6500KelvinIsD65) {
    const DenseSpectrum d = cie_daylight(6500.0f);
    EXPECT_EQ(d(560.0f), 1.0f);  // S0 is 100 and S1, S2 are 0 at 560 nm
    // The CIE D65 table (pbrt-v4's CIE_Illum_D6500), at a few 5-nm nodes, divided by 100.
    struct Node {
        float nm, value;
    };
    for (const Node& n : {Node{380, 0.499755f}, Node{450, 1.17008f}, Node{600, 0.900062f},
                          Node{700, 0.716091f}, Node{780, 0.633828f}})
        EXPECT_NEAR(d(n.nm), n.value, 2.5e-4f) << n.nm;
    const Xy xy = chromaticity(d);
    EXPECT_NEAR(xy.x, 0.31272, 2e-4);
    EXPECT_NEAR(xy.y, 0.32903, 2e-4);
}

// The check: cie_daylight(6504) (a 3.6 K warmer D65) is near D65's (0.3127, 0.3290);
// and 5000 K gives D50, (0.34567, 0.35850) (CIE 15:2004).
TEST(CieDaylight, ChromaticitiesMatchCie) {
    const Xy d6504 = chromaticity(cie_daylight(6504.0f));
    EXPECT_NEAR(d6504.x, 0.3127, 1e-3);
    EXPECT_NEAR(d6504.y, 0.3290, 1e-3);
    const Xy d50 = chromaticity(cie_daylight(5000.0f));
    EXPECT_NEAR(d50.x, 0.34567, 2e-4);
    EXPECT_NEAR(d50.y, 0.35850, 2e-4);
}

// Below 4000 K (after the c2 correction) pbrt-v4's Spectra::D is the blackbody.
TEST(CieDaylight, BelowFourThousandKelvinIsTheBlackbody) {
    const float kelvin = 3000.0f;
    const DenseSpectrum d = cie_daylight(kelvin);
    const DenseSpectrum bb = blackbody_spectrum(float(double(kelvin) * 1.4388 / 1.4380));
    for (int i = 0; i < kDenseSamples; ++i) EXPECT_EQ(d.v[size_t(i)], bb.v[size_t(i)]) << i;
}

}  // namespace
}  // namespace candela
