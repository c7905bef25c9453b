// Statistical tests of BSDF sampling: chi-square goodness of fit of Bsdf::sample against
// Bsdf::pdf for every non-delta configuration (tests/support/chi2.h, the full sphere of
// directions, so a sample on the wrong side fails in a zero-pdf cell), and white-furnace
// estimates of each lobe's directional albedo.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "candela/materials/bsdf.h"
#include "materials/axis_domain.h"
#include "materials/lobe_cases.h"
#include "materials/microfacet_quadrature.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;

// The chi-square tests in this file, for the Sidak correction.
constexpr int kChi2Tests = 36;

Bsdf bsdf_of(std::initializer_list<BsdfLobe> lobes) {
    Bsdf b;
    for (const BsdfLobe& lobe : lobes) b.lobes[b.lobe_count++] = lobe;
    return b;
}

// Fits the directions Bsdf::sample draws from its non-delta lobes against Bsdf::pdf. Delta
// samples are left out (nullopt), so the pdf integrates to the probability of choosing a
// non-delta lobe: `non_delta_fraction`. The horizon cos theta = 0 is a row edge of the 50 rows.
void expect_sampling_fits_pdf(const Bsdf& bsdf, Vec3f wo, double non_delta_fraction) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.expected_integral = non_delta_fraction;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        float uc = rng.next_float();
        auto s = bsdf.sample(wo, uc, rng.next_vec2f(), kRadiance);
        if (!s || s->is_delta) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](Vec3f wi) { return bsdf.pdf(wo, wi); };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

// The same for a BSDF whose sampling may fail for other reasons than a delta lobe (a microfacet
// reflected below the surface, total internal reflection at a microfacet): the pdf then
// integrates to the probability that sampling succeeds, measured here from 1M samples (within
// 5 binomial standard deviations, plus the harness's integration error, below 1e-4). A narrow
// lobe is histogrammed around the mirror direction (AxisDomain), where it covers many cells.
void expect_rough_sampling_fits_pdf(const Bsdf& bsdf, Vec3f wo, bool narrow = false) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.expected_integral = std::nullopt;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        float uc = rng.next_float();
        auto s = bsdf.sample(wo, uc, rng.next_vec2f(), kRadiance);
        if (!s || s->is_delta) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](Vec3f wi) { return bsdf.pdf(wo, wi); };
    Chi2Result r = narrow ? chi2_test(AxisDomain(Vec3f(-wo.x, -wo.y, wo.z), kPiD), sampler, pdf, opt)
                          : chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;

    Rng rng(41, 7);
    const int n = 1'000'000;
    int succeeded = 0;
    for (int i = 0; i < n; ++i) {
        float uc = rng.next_float();
        auto s = bsdf.sample(wo, uc, rng.next_vec2f(), kRadiance);
        if (s && !s->is_delta) ++succeeded;
    }
    double p = double(succeeded) / n;
    EXPECT_NEAR(r.pdf_integral, p, 5.0 * std::sqrt(p * (1.0 - p) / n) + 1e-4);
}

Bsdf lambertian() { return bsdf_of({LambertianLobe{Color(0.7f)}}); }

TEST(LambertianChi2, NormalIncidence) {
    expect_sampling_fits_pdf(lambertian(), direction(1.0f, 0.0f), 1.0);
}
TEST(LambertianChi2, Oblique) {
    expect_sampling_fits_pdf(lambertian(), direction(0.5f, 1.0f), 1.0);
}
TEST(LambertianChi2, Grazing) {
    expect_sampling_fits_pdf(lambertian(), direction(0.01f, 2.0f), 1.0);
}
TEST(LambertianChi2, BelowTheSurface) {
    expect_sampling_fits_pdf(lambertian(), direction(-0.6f, -1.0f), 1.0);
}
TEST(LambertianChi2, GrazingBelowTheSurface) {
    expect_sampling_fits_pdf(lambertian(), direction(-0.01f, 0.5f), 1.0);
}

TEST(MixChi2, LambertianAndMirrorHalveTheDensity) {
    Bsdf b = bsdf_of({LambertianLobe{Color(0.5f)}, SpecularReflectionLobe{Color(0.5f)}});
    expect_sampling_fits_pdf(b, direction(0.7f, 0.3f), 0.5);
}
TEST(MixChi2, LambertianAndMirrorBelowTheSurface) {
    Bsdf b = bsdf_of({SpecularReflectionLobe{Color(0.5f)}, LambertianLobe{Color(0.5f)}});
    expect_sampling_fits_pdf(b, direction(-0.4f, 2.0f), 0.5);
}
TEST(MixChi2, LambertianAndDielectric) {
    Bsdf b = bsdf_of({LambertianLobe{Color(0.3f)}, FresnelSpecularLobe{Color(1.0f), 1.5f, false}});
    expect_sampling_fits_pdf(b, direction(0.2f, 1.5f), 0.5);
}
TEST(MixChi2, LambertianAndTransmissionUnderTotalInternalReflection) {
    // From inside glass at 60 degrees the transmission lobe fails; its share still counts.
    Bsdf b = bsdf_of({SpecularTransmissionLobe{Color(1.0f), 1.5f}, LambertianLobe{Color(0.3f)}});
    expect_sampling_fits_pdf(b, direction(-0.5f, 0.0f), 0.5);
}
TEST(MixChi2, TwoLambertiansAreOneCosineDensity) {
    Bsdf b = bsdf_of({LambertianLobe{Color(0.3f)}, LambertianLobe{Color(0.6f)}});
    expect_sampling_fits_pdf(b, direction(0.8f, -0.5f), 1.0);
}
TEST(MixChi2, ThreeLobesWithTwoDelta) {
    Bsdf b = bsdf_of({SpecularReflectionLobe{Color(0.2f)}, LambertianLobe{Color(0.3f)},
                      FresnelSpecularLobe{Color(0.4f), 1.33f, true}});
    expect_sampling_fits_pdf(b, direction(0.45f, 2.5f), 1.0 / 3.0);
}

Bsdf gold(TrowbridgeReitz tr) { return bsdf_of({ConductorLobe{tr, kGoldEta, kGoldK}}); }

TEST(ConductorChi2, NearlySmoothAroundTheMirrorDirection) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.01f)), direction(0.7f, 0.3f), true);
}
TEST(ConductorChi2, Alpha0_1) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.1f)), direction(0.5f, 1.0f));
}
TEST(ConductorChi2, Alpha0_3Grazing) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.3f)), direction(0.05f, -2.0f));
}
TEST(ConductorChi2, Alpha0_3GrazingBelowTheSurface) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.3f)), direction(-0.05f, 0.5f));
}
TEST(ConductorChi2, Alpha0_8BelowTheSurface) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.8f)), direction(-0.6f, 2.0f));
}
TEST(ConductorChi2, Anisotropic) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.05f, 0.4f)), direction(0.6f, 0.8f));
}
TEST(ConductorChi2, AnisotropicNormalIncidence) {
    expect_rough_sampling_fits_pdf(gold(TrowbridgeReitz(0.4f, 0.05f)), direction(1.0f, 0.0f));
}

Bsdf glass(float eta, TrowbridgeReitz tr) { return bsdf_of({DielectricLobe{Color(1.0f), eta, tr}}); }

TEST(RoughDielectricChi2, NormalIncidence) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.3f)), direction(1.0f, 0.0f));
}
TEST(RoughDielectricChi2, EnteringAlpha0_1) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.1f)), direction(0.8f, 0.4f));
}
TEST(RoughDielectricChi2, LeavingWithTotalInternalReflection) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.1f)), direction(-0.5f, 1.0f));
}
TEST(RoughDielectricChi2, GrazingOutside) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.3f)), direction(0.05f, 2.0f));
}
TEST(RoughDielectricChi2, GrazingInside) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.3f)), direction(-0.05f, 2.0f));
}
TEST(RoughDielectricChi2, IndexBelowOne) {
    expect_rough_sampling_fits_pdf(glass(1.0f / 1.5f, TrowbridgeReitz(0.3f)), direction(0.5f, -1.0f));
}
TEST(RoughDielectricChi2, IndexBelowOneFromInside) {
    expect_rough_sampling_fits_pdf(glass(1.0f / 1.5f, TrowbridgeReitz(0.1f)), direction(-0.8f, 0.2f));
}
TEST(RoughDielectricChi2, IndexBelowOneGrazingOutside) {
    expect_rough_sampling_fits_pdf(glass(1.0f / 1.5f, TrowbridgeReitz(0.3f)), direction(0.05f, 1.0f));
}
TEST(RoughDielectricChi2, IndexBelowOneGrazingInside) {
    expect_rough_sampling_fits_pdf(glass(1.0f / 1.5f, TrowbridgeReitz(0.3f)), direction(-0.05f, 1.0f));
}
TEST(RoughDielectricChi2, Anisotropic) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.05f, 0.4f)), direction(0.6f, 1.0f));
}
TEST(RoughDielectricChi2, AnisotropicFromInside) {
    expect_rough_sampling_fits_pdf(glass(1.5f, TrowbridgeReitz(0.05f, 0.4f)), direction(-0.3f, 2.0f));
}

// Diffuse transmission: a cosine lobe on each side, in the proportion of max R to max T.
Bsdf diffuse_transmission(Color r, Color t) { return bsdf_of({DiffuseTransmissionLobe{r, t}}); }

TEST(DiffuseTransmissionChi2, Equal) {
    expect_sampling_fits_pdf(diffuse_transmission(Color(0.25f), Color(0.25f)), direction(0.7f, 0.3f), 1.0);
}
TEST(DiffuseTransmissionChi2, MostlyTransmittedFromBelow) {
    expect_sampling_fits_pdf(diffuse_transmission(Color(0.1f), Color(0.8f)), direction(-0.4f, 1.0f), 1.0);
}
TEST(DiffuseTransmissionChi2, ColouredGrazing) {
    expect_sampling_fits_pdf(diffuse_transmission(Color(0.6f, 0.1f, 0.2f), Color(0.1f, 0.5f, 0.3f)),
                             direction(0.05f, 2.0f), 1.0);
}
TEST(DiffuseTransmissionChi2, ReflectionOnly) {
    expect_sampling_fits_pdf(diffuse_transmission(Color(0.7f), Color(0.0f)), direction(0.5f, 0.0f), 1.0);
}
TEST(DiffuseTransmissionChi2, TransmissionOnly) {
    expect_sampling_fits_pdf(diffuse_transmission(Color(0.0f), Color(0.7f)), direction(-0.9f, 0.0f), 1.0);
}

TEST(MixChi2, RoughConductorAndLambertian) {
    Bsdf b = bsdf_of({ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta, kGoldK}, LambertianLobe{Color(0.5f)}});
    expect_rough_sampling_fits_pdf(b, direction(0.4f, 1.0f));
}
TEST(MixChi2, RoughDielectricAndSmoothDielectric) {
    // The smooth lobe's samples are delta (left out), so the pdf integrates to half the rough
    // lobe's success probability.
    Bsdf b = bsdf_of({DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.2f)},
                      DielectricLobe{Color(1.0f), 1.5f, TrowbridgeReitz(0.0f)}});
    expect_rough_sampling_fits_pdf(b, direction(-0.7f, 1.0f));
}

// ---- white furnace: the directional albedo E[f |cos| / pdf] of each lobe

constexpr int kFurnaceSamples = 200'000;

// Mean and standard error of the sample weights f |cos| / pdf (red channel), failed samples
// counting 0, over kFurnaceSamples draws; both transport modes are checked by the callers.
struct Estimate {
    double mean = 0.0;
    double standard_error = 0.0;
};
Estimate directional_albedo(const Bsdf& bsdf, Vec3f wo, TransportMode mode, uint64_t seed) {
    Rng rng(seed, 5);
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < kFurnaceSamples; ++i) {
        float uc = rng.next_float();
        auto s = bsdf.sample(wo, uc, rng.next_vec2f(), mode);
        double w = s ? double(s->f[0]) * double(std::abs(s->wi.z)) / double(s->pdf) : 0.0;
        sum += w;
        sum_sq += w * w;
    }
    double n = kFurnaceSamples, mean = sum / n;
    double variance = std::max(0.0, sum_sq / n - mean * mean);
    return {mean, std::sqrt(variance / (n - 1.0))};
}

// The estimate must be within 5 standard errors (plus float rounding, and the error of
// `expected` itself when a quadrature computed it) of `expected`.
void expect_albedo(const Estimate& e, double expected, double expected_error = 0.0) {
    EXPECT_NEAR(e.mean, expected, 5.0 * e.standard_error + 1e-5 * expected + expected_error);
}

constexpr double kNoClosedForm = std::numeric_limits<double>::quiet_NaN();

TEST(LobeFurnace, EveryLobeSampledGivesItsDirectionalAlbedo) {
    // Importance mode: no eta^2 factor. The expected albedo in closed form per lobe: Lambertian
    // and mirror their albedo, the dielectric its tint (F + (1 - F) = 1), transmission
    // tint (1 - F) or 0 under total internal reflection, a smooth conductor F(cos wo), a thin
    // pane 1 (R' + T' = 1). Rough lobes: their integral of f |cos| by quadrature, whose error
    // (below 1e-5) the bound allows besides the estimator's.
    for (const LobeCase& c : kLobeCases) {
        // Coated lobes have no closed form: layered_stat_test.cpp checks their furnace against
        // closed forms of special cases and their bound in both modes.
        if (visit([](const auto& l) { return kIsLayered<std::decay_t<decltype(l)>>; }, c.lobe)) continue;
        Bsdf b = bsdf_of({c.lobe});
        for (const Vec3f& wo : probe_directions()) {
            SCOPED_TRACE(testing::Message() << c.name << ", wo.z = " << wo.z);
            double expected = visit(
                Overloaded{[](const LambertianLobe& l) { return double(l.reflectance[0]); },
                           [](const SpecularReflectionLobe& l) { return double(l.reflectance[0]); },
                           [](const FresnelSpecularLobe& l) { return double(l.tint[0]); },
                           [&](const SpecularTransmissionLobe& l) {
                               double f = double(fresnel_dielectric(wo.z, l.eta));
                               return double(l.tint[0]) * (1.0 - f);
                           },
                           [&](const ConductorLobe& l) {
                               if (l.distribution.effectively_smooth())
                                   return double(fresnel_complex(std::abs(wo.z), l.eta, l.k)[0]);
                               return albedo_by_quadrature(l, wo, TransportMode::kImportance);
                           },
                           [&](const DielectricLobe& l) {
                               if (l.is_smooth()) return double(l.tint[0]);
                               return albedo_by_quadrature(l, wo, TransportMode::kImportance);
                           },
                           [](const ThinDielectricLobe&) { return 1.0; },
                           // R + T whatever wo (the two sides' integrals of cos / pi are 1 each).
                           [](const DiffuseTransmissionLobe& l) {
                               return double(l.reflectance[0]) + double(l.transmittance[0]);
                           },
                           // Skipped above.
                           [](const CoatedDiffuseLobe&) { return kNoClosedForm; },
                           [](const CoatedConductorLobe&) { return kNoClosedForm; },
                           // Without absorption a fibre scatters everything; with it, no closed
                           // form (hair_stat_test.cpp compares against uniform sampling).
                           [](const HairLobe& l) { return l.sigma_a == Color(0.0f) ? 1.0 : kNoClosedForm; }},
                c.lobe);
            if (std::isnan(expected)) continue;
            Estimate e = directional_albedo(b, wo, TransportMode::kImportance, 17);
            expect_albedo(e, expected, 1e-5);
            EXPECT_LE(e.mean, 1.0 + 1e-5);
        }
    }
}

TEST(LobeFurnace, PerfectConductorReflectsItsSingleScatteringAlbedo) {
    // F = 1 (a purely imaginary index): what sampling estimates is the energy that single
    // scattering keeps, computed independently by quadrature over the microfacet normals; below
    // 1 at alpha 0.5 and 1 (microfacet_lobes_test.cpp), which is what multiscatter restores.
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
        Bsdf b = bsdf_of({ConductorLobe{TrowbridgeReitz(alpha), Color(0.0f), Color(1.0f)}});
        for (float c : {1.0f, 0.5f, 0.1f, -0.7f}) {
            Vec3f wo = direction(c, 1.0f);
            SCOPED_TRACE(testing::Message() << "alpha " << alpha << ", cos " << c);
            double expected = albedo_by_quadrature(std::get<ConductorLobe>(b.lobes[0]), wo, kRadiance);
            expect_albedo(directional_albedo(b, wo, kRadiance, 31), expected, 1e-5);
        }
    }
}

TEST(LobeFurnace, LambertianEvalIntegratesToItsAlbedo) {
    // Independent of the sampler: integrate f |cos| over the sphere with uniform directions.
    // The estimator 4 pi f |cos| has variance 5 albedo^2 / 3, bounded here by its measured one.
    LambertianLobe lobe{Color(0.7f)};
    for (const Vec3f& wo : {direction(0.8f, 0.0f), direction(-0.3f, 1.0f)}) {
        Rng rng(23, 9);
        double sum = 0.0, sum_sq = 0.0;
        const int n = 400'000;
        for (int i = 0; i < n; ++i) {
            Vec3f wi = sample_uniform_sphere(rng.next_vec2f());
            double f = lobe.eval(wo, wi, kRadiance)[0];
            double w = f * double(std::abs(wi.z)) / double(kInv4Pi);
            sum += w;
            sum_sq += w * w;
        }
        double mean = sum / n, se = std::sqrt((sum_sq / n - mean * mean) / (n - 1.0));
        EXPECT_NEAR(mean, 0.7, 5.0 * se);
    }
}

TEST(LobeFurnace, HalfDiffuseHalfMirrorIsWhite) {
    // Every sample of 0.5 diffuse + 0.5 mirror weighs exactly 1 (see bsdf_test.cpp), so the
    // estimate has no variance.
    Bsdf b = bsdf_of({LambertianLobe{Color(0.5f)}, SpecularReflectionLobe{Color(0.5f)}});
    for (const Vec3f& wo : probe_directions())
        EXPECT_NEAR(directional_albedo(b, wo, kRadiance, 3).mean, 1.0, 1e-5);
}

TEST(LobeFurnace, DielectricReflectsWithTheFresnelFrequency) {
    // The fraction of reflected samples is binomial with p = F: within 5 standard deviations.
    for (bool schlick : {false, true}) {
        FresnelSpecularLobe lobe{Color(1.0f), 1.5f, schlick};
        for (const Vec3f& wo : probe_directions()) {
            Rng rng(29, 3);
            const int n = 100'000;
            int reflected = 0;
            for (int i = 0; i < n; ++i) {
                auto s = lobe.sample(wo, rng.next_float(), rng.next_vec2f(), kRadiance);
                ASSERT_TRUE(s);
                if (!s->is_transmission) ++reflected;
            }
            double p = lobe.reflectance(wo);
            EXPECT_NEAR(double(reflected) / n, p, 5.0 * std::sqrt(p * (1.0 - p) / n) + 1e-9)
                << "schlick " << schlick << ", wo.z = " << wo.z;
        }
    }
}

}  // namespace
}  // namespace candela::test
