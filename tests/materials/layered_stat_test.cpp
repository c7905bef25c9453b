// Statistical tests of the coated lobes and their parts.
//
// The parts with densities in closed form (the Henyey-Greenstein phase function, the coat
// restricted to reflection or transmission) get the chi-square harness of tests/support/chi2.h.
//
// A coated lobe's pdf() is pbrt-v4's approximation for MIS, not the density of sample() (which
// has no closed form): a histogram of sample() cannot be fitted to it. What the renderer relies
// on, and what is tested here:
//   1. Sampling direction (exact chi-square): for a smooth coat over a white Lambertian base in a
//      clear slab, the walk's exit density has a closed form (materials/coated_closed_forms.h);
//      the harness fits sample()'s histogram to it.
//   2. Sampling weights against eval (weighted chi-square): sample() is unbiased for f |cos|, so
//      on any cell C of directions E[f |cos| / pdf 1{wi in C}] (over samples) equals the integral
//      of eval() |cos| over C (each eval() an estimate with its own random numbers, so a Monte
//      Carlo integral over C converges to it). Both sides are estimated with their variances;
//      the sum over cells of (difference)^2 / (variance of the difference) is chi-square with
//      one degree of freedom per cell (cells with few samples pooled, so each term is close to
//      normal), tested at the Sidak-corrected level.
//   3. Energy: the white furnace against the closed form of 1 (E[f |cos| / pdf] = F + (1 - F)
//      (1 - r^K): what max_depth cuts off is r^K), and E <= 1 for every coated case, in both
//      transport modes, whose expectations agree.
//   4. eval() against its closed form for the smooth coat over a grey base (the geometric
//      series of internal reflections), and reciprocity f(wo, wi) = f(wi, wo), both in
//      expectation: an isotropic lobe is invariant under rotations about the normal, and each
//      rotated pair draws other random numbers, so rotations give independent estimates of the
//      same value, whose mean and standard error are compared.
// z-tests allow 5 standard errors (a false alarm with probability 6e-7 each).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "candela/materials/bsdf.h"
#include "candela/sampling/henyey_greenstein.h"
#include "candela/materials/layered.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "materials/coated_closed_forms.h"
#include "materials/lobe_cases.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;
constexpr TransportMode kImportance = TransportMode::kImportance;

// The chi-square tests in this file (harness and weighted), for the Sidak correction.
constexpr int kChi2Tests = 19;

// The sum of a colour's channels: the tests compare one linear functional of f.
double channel_sum(const Color& c) { return double(c[0]) + double(c[1]) + double(c[2]); }

// Mean and standard error of a stream of values.
struct Moments {
    double sum = 0.0, sum_sq = 0.0;
    int n = 0;
    void add(double v) {
        sum += v;
        sum_sq += v * v;
        ++n;
    }
    double mean() const { return sum / n; }
    double standard_error() const {
        double m = mean();
        return std::sqrt(std::max(0.0, sum_sq / n - m * m) / (n - 1.0));
    }
};

void expect_within_5_se(const Moments& a, double expected, double slack = 0.0) {
    EXPECT_NEAR(a.mean(), expected, 5.0 * a.standard_error() + 1e-5 * std::abs(expected) + slack);
}
void expect_same_expectation(const Moments& a, const Moments& b) {
    double se = std::hypot(a.standard_error(), b.standard_error());
    EXPECT_NEAR(a.mean(), b.mean(), 5.0 * se + 1e-6);
}

// ---- Henyey-Greenstein phase function

void expect_phase_fits(Vec3f wo, float g) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    auto sampler = [&](Sampler& s) { return sample_henyey_greenstein(wo, g, s.next_vec2f()).wi; };
    auto pdf = [&](Vec3f wi) { return henyey_greenstein(dot(wo, wi), g); };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(HenyeyGreensteinChi2, Isotropic) { expect_phase_fits(direction(0.3f, 1.0f), 0.0f); }
TEST(HenyeyGreensteinChi2, Forward) { expect_phase_fits(direction(0.6f, -2.0f), 0.7f); }
TEST(HenyeyGreensteinChi2, Backward) { expect_phase_fits(direction(-0.8f, 0.5f), -0.4f); }

// ---- the coat restricted to one side

// Fits the coat's non-delta samples restricted by `flags` to its restricted pdf. Sampling may
// fail (a microfacet that reflects below the surface, total internal reflection when only
// transmission is allowed), so the pdf integrates to the success probability, measured from
// 1M samples (within 5 binomial standard deviations plus the harness's integration error).
void expect_coat_fits(const CoatInterface& coat, Vec3f wo, ReflTrans flags) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.expected_integral = std::nullopt;
    auto sampler = [&](Sampler& s) -> std::optional<Vec3f> {
        float uc = s.next_float();
        auto bs = coat.sample(wo, uc, s.next_vec2f(), kRadiance, flags);
        if (!bs) return std::nullopt;
        return bs->wi;
    };
    auto pdf = [&](Vec3f wi) { return coat.pdf(wo, wi, flags); };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;

    Rng rng(41, 7);
    const int n = 1'000'000;
    int succeeded = 0;
    for (int i = 0; i < n; ++i) {
        float uc = rng.next_float();
        if (coat.sample(wo, uc, rng.next_vec2f(), kRadiance, flags)) ++succeeded;
    }
    double p = double(succeeded) / n;
    EXPECT_NEAR(r.pdf_integral, p, 5.0 * std::sqrt(p * (1.0 - p) / n) + 1e-4);
}

TEST(CoatInterfaceChi2, TransmissionFromOutside) {
    expect_coat_fits({1.5f, TrowbridgeReitz(0.3f)}, direction(0.6f, 0.5f), ReflTrans::kTransmission);
}
TEST(CoatInterfaceChi2, TransmissionFromInsideNearTheCriticalAngle) {
    expect_coat_fits({1.5f, TrowbridgeReitz(0.2f)}, direction(-0.75f, 2.0f), ReflTrans::kTransmission);
}
TEST(CoatInterfaceChi2, ReflectionFromInside) {
    expect_coat_fits({1.5f, TrowbridgeReitz(0.25f)}, direction(-0.5f, -1.0f), ReflTrans::kReflection);
}
TEST(CoatInterfaceChi2, AnisotropicReflectionFromOutside) {
    expect_coat_fits({1.33f, TrowbridgeReitz(0.1f, 0.4f)}, direction(0.4f, 1.0f), ReflTrans::kReflection);
}

// ---- 1. the exit direction of the smooth coat over a white base, against its closed form

// With a white base no walk weight falls below 1 / eta^2 > 0.25, so no roulette, and a clear
// slab of zero thickness has transmittance 1: the walk is the process coated_closed_forms.h
// describes, and its non-delta samples have the density
//   (1 - F(cos_o)) sum_{k<K} r^k t(wi),  t(wi) = (1 - F(cos_i)) cos_i / (pi eta^2),
// on wo's side, integrating to (1 - F(cos_o)) (1 - r^K), K = (max_depth + 1) / 2.
void expect_smooth_coat_exits_fit(Vec3f wo, int max_depth) {
    const double eta = 1.5;
    CoatedDiffuseLobe lobe{CoatInterface{float(eta), TrowbridgeReitz(0.0f)}, LambertianLobe{Color(1.0f)},
                           Color(0.0f), 0.0f, 0.0f, static_cast<uint16_t>(max_depth), 1};
    const double r = internal_diffuse_reflectance(eta);
    const int k = counted_paths(max_depth);
    const double entered = 1.0 - fresnel_reference(std::abs(double(wo.z)), eta);
    const double visits = (1.0 - std::pow(r, k)) / (1.0 - r);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.expected_integral = entered * (1.0 - std::pow(r, k));
    auto sampler = [&](Sampler& s) -> std::optional<Vec3f> {
        float uc = s.next_float();
        auto bs = lobe.sample(wo, uc, s.next_vec2f(), kRadiance);
        if (!bs || bs->is_delta) return std::nullopt;
        return bs->wi;
    };
    auto pdf = [&](Vec3f wi) {
        if (!(wi.z * wo.z > 0.0f)) return 0.0;
        double c = std::abs(double(wi.z));
        return entered * visits * (1.0 - fresnel_reference(c, eta)) * c / (kPiD * eta * eta);
    };
    Chi2Result res = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(res.passed) << res.message;
}

TEST(CoatedDiffuseChi2, SmoothCoatExitsNormalIncidence) { expect_smooth_coat_exits_fit(direction(1.0f, 0.0f), 10); }
TEST(CoatedDiffuseChi2, SmoothCoatExitsOblique) { expect_smooth_coat_exits_fit(direction(0.4f, 1.0f), 10); }
TEST(CoatedDiffuseChi2, SmoothCoatExitsBelowAfterFiveEvents) {
    expect_smooth_coat_exits_fit(direction(-0.7f, 2.0f), 5);
}

// ---- 2. sampling weights against eval, cell by cell

// The weighted chi-square statistic comparing eval() of `lobe` with sample() of `sampled` (see
// the top of the file): its p-value, and a description for failure messages.
struct WeightedChi2 {
    double p_value = 0.0;
    std::string message;
};
template <class Eval, class Sample>
WeightedChi2 sample_weights_vs_eval_of(const Eval& eval, const Sample& sample, Vec3f wo) {
    // Cells of equal solid angle on wo's side: 12 azimuths x 8 bands of |cos theta|.
    constexpr int kPhi = 12, kMu = 8, kCells = kPhi * kMu;
    constexpr double kCellArea = 2.0 * kPiD / kPhi / kMu;
    const float side = wo.z < 0.0f ? -1.0f : 1.0f;
    auto cell_of = [&](Vec3f w) {
        double phi = std::atan2(double(w.y), double(w.x)) + kPiD;
        int i = std::min(kPhi - 1, static_cast<int>(phi / (2.0 * kPiD) * kPhi));
        int j = std::min(kMu - 1, static_cast<int>(std::abs(double(w.z)) * kMu));
        return j * kPhi + i;
    };

    // Samples: the non-delta weights f |cos| / pdf per cell (first and second moments per
    // sample, 0 outside the cell).
    const int n = 1'000'000;
    std::vector<double> m1(kCells, 0.0), m2(kCells, 0.0);
    std::vector<int> count(kCells, 0);
    Rng rng(77, 3);
    for (int s = 0; s < n; ++s) {
        float uc = rng.next_float();
        auto bs = sample(uc, rng.next_vec2f());
        if (!bs || bs->is_delta) continue;
        EXPECT_GT(bs->wi.z * wo.z, 0.0f) << "a sample on the other side";
        if (!(bs->wi.z * wo.z > 0.0f)) return {};
        double w = channel_sum(bs->f) * std::abs(double(bs->wi.z)) / double(bs->pdf);
        int c = cell_of(bs->wi);
        m1[size_t(c)] += w;
        m2[size_t(c)] += w * w;
        ++count[size_t(c)];
    }
    // eval: a Monte Carlo integral of eval |cos| over each cell from uniform points in it.
    const int m = 3000;
    std::vector<double> y(kCells), y_var(kCells);
    Rng points(78, 4);
    for (int c = 0; c < kCells; ++c) {
        int i = c % kPhi, j = c / kPhi;
        Moments g;
        for (int k = 0; k < m; ++k) {
            Vec2f u = points.next_vec2f();
            double phi = -kPiD + 2.0 * kPiD * (i + double(u.x)) / kPhi;
            double mu = (j + double(u.y)) / kMu;
            Vec3f wi = direction(side * float(mu), float(phi));
            g.add(channel_sum(eval(wi)) * mu);
        }
        y[size_t(c)] = kCellArea * g.mean();
        y_var[size_t(c)] = kCellArea * kCellArea * sqr(g.standard_error());
    }

    // Pool cells with fewer than 200 samples (in increasing order of count) into bins of at
    // least 200, so that each bin's sample mean is close to normal.
    std::vector<int> order(kCells);
    for (int c = 0; c < kCells; ++c) order[size_t(c)] = c;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return count[size_t(a)] < count[size_t(b)]; });
    double statistic = 0.0;
    int bins = 0;
    double b1 = 0.0, b2 = 0.0, by = 0.0, by_var = 0.0;
    int bcount = 0;
    double worst = 0.0;
    for (int c : order) {
        b1 += m1[size_t(c)];
        b2 += m2[size_t(c)];
        bcount += count[size_t(c)];
        by += y[size_t(c)];
        by_var += y_var[size_t(c)];
        if (bcount < 200 && c != order.back()) continue;
        double x = b1 / n, x_var = (b2 / n - x * x) / n;
        double var = x_var + by_var;
        if (var > 0.0) {
            double z2 = (x - by) * (x - by) / var;
            statistic += z2;
            worst = std::max(worst, z2);
            ++bins;
        } else {
            EXPECT_EQ(x, by) << "a bin with no variance on either side must agree exactly";
        }
        b1 = b2 = by = by_var = 0.0;
        bcount = 0;
    }
    EXPECT_GT(bins, 10);
    double p = chi2_p_value(statistic, bins);
    return {p, "chi2 = " + std::to_string(statistic) + " over " + std::to_string(bins) + " bins, p = " +
                   std::to_string(p) + ", largest term " + std::to_string(worst)};
}

template <class Lobe>
WeightedChi2 sample_weights_vs_eval(const Lobe& lobe, const Lobe& sampled, Vec3f wo, TransportMode mode) {
    return sample_weights_vs_eval_of(
        [&](Vec3f wi) { return lobe.eval(wo, wi, mode); },
        [&](float uc, Vec2f u) { return sampled.sample(wo, uc, u, mode); }, wo);
}

template <class Lobe>
void expect_sample_weights_match_eval(const Lobe& lobe, Vec3f wo, TransportMode mode) {
    WeightedChi2 r = sample_weights_vs_eval(lobe, lobe, wo, mode);
    EXPECT_GE(r.p_value, sidak_alpha(0.01, kChi2Tests)) << r.message;
}

TEST(CoatedSamplingAgreesWithEval, SmoothCoatGreyDiffuse) {
    CoatedDiffuseLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)}, LambertianLobe{Color(0.8f, 0.5f, 0.2f)},
                           Color(0.0f), 0.05f, 0.0f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(0.6f, 0.3f), kRadiance);
}
TEST(CoatedSamplingAgreesWithEval, RoughCoatScatteringMediumFromBelow) {
    CoatedDiffuseLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.3f)}, LambertianLobe{Color(0.5f, 0.6f, 0.7f)},
                           Color(0.8f, 0.5f, 0.3f), 0.3f, 0.3f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(-0.5f, 1.0f), kRadiance);
}
TEST(CoatedSamplingAgreesWithEval, SmoothCoatForwardScatteringMediumImportance) {
    CoatedDiffuseLobe lobe{CoatInterface{1.33f, TrowbridgeReitz(0.0f)}, LambertianLobe{Color(0.9f)},
                           Color(0.95f), 0.5f, 0.6f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(0.3f, -1.0f), kImportance);
}
TEST(CoatedSamplingAgreesWithEval, RoughCoatRoughConductor) {
    CoatedConductorLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.15f)},
                             ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta / 1.5f, kGoldK / 1.5f}, Color(0.0f),
                             0.01f, 0.0f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(0.7f, 2.0f), kRadiance);
}
TEST(CoatedSamplingAgreesWithEval, SmoothCoatAnisotropicConductorInMedium) {
    CoatedConductorLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)},
                             ConductorLobe{TrowbridgeReitz(0.05f, 0.4f), kGoldEta / 1.5f, kGoldK / 1.5f},
                             Color(0.7f, 0.8f, 0.9f), 0.2f, -0.3f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(0.5f, 0.7f), kRadiance);
}
TEST(CoatedSamplingAgreesWithEval, RoughCoatSmoothConductorGrazing) {
    CoatedConductorLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.4f)},
                             ConductorLobe{TrowbridgeReitz(0.0f), kGoldEta / 1.5f, kGoldK / 1.5f}, Color(0.0f),
                             0.05f, 0.0f, 10, 1};
    expect_sample_weights_match_eval(lobe, direction(0.15f, 1.0f), kRadiance);
}

TEST(CoatedSamplingAgreesWithEval, ControlDetectsAThreePercentBrighterBase) {
    // The test's power: the sampled lobe's base 3 % brighter than the evaluated one's (about
    // the size of the MIS bias of pbrt-v4's f, layered.h) must be rejected.
    CoatedDiffuseLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.3f)}, LambertianLobe{Color(0.7f)}, Color(0.0f),
                           0.01f, 0.0f, 10, 1};
    CoatedDiffuseLobe brighter = lobe;
    brighter.base.reflectance = Color(0.7f * 1.03f);
    WeightedChi2 r = sample_weights_vs_eval(lobe, brighter, direction(0.6f, 0.3f), kRadiance);
    EXPECT_LT(r.p_value, sidak_alpha(0.01, kChi2Tests)) << r.message;
}

// A Bsdf of several lobes, one of them coated, samples each lobe for itself (bsdf.cpp): its
// weights must still average to its eval().
TEST(CoatedSamplingAgreesWithEval, MixOfCoatedDiffuseAndLambertian) {
    Bsdf b;
    b.lobes[b.lobe_count++] = CoatedDiffuseLobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)},
                                                LambertianLobe{Color(0.6f, 0.4f, 0.2f)}, Color(0.0f), 0.1f, 0.0f, 10, 1};
    b.lobes[b.lobe_count++] = LambertianLobe{Color(0.3f)};
    Vec3f wo = direction(0.5f, 1.0f);
    WeightedChi2 r = sample_weights_vs_eval_of([&](Vec3f wi) { return b.eval(wo, wi, kRadiance); },
                                               [&](float uc, Vec2f u) { return b.sample(wo, uc, u, kRadiance); }, wo);
    EXPECT_GE(r.p_value, sidak_alpha(0.01, kChi2Tests)) << r.message;
}
TEST(CoatedSamplingAgreesWithEval, MixOfRoughCoatedConductorAndRoughConductor) {
    Bsdf b;
    b.lobes[b.lobe_count++] = ConductorLobe{TrowbridgeReitz(0.2f), kGoldEta, kGoldK};
    b.lobes[b.lobe_count++] = CoatedConductorLobe{CoatInterface{1.5f, TrowbridgeReitz(0.1f)},
                                                  ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta / 1.5f, kGoldK / 1.5f},
                                                  Color(0.0f), 0.01f, 0.0f, 10, 1};
    Vec3f wo = direction(-0.7f, 2.0f);
    WeightedChi2 r = sample_weights_vs_eval_of([&](Vec3f wi) { return b.eval(wo, wi, kImportance); },
                                               [&](float uc, Vec2f u) { return b.sample(wo, uc, u, kImportance); }, wo);
    EXPECT_GE(r.p_value, sidak_alpha(0.01, kChi2Tests)) << r.message;
}

// ---- 3. energy

constexpr int kFurnaceSamples = 50'000;

template <class Lobe>
Moments directional_albedo(const Lobe& lobe, Vec3f wo, TransportMode mode, uint64_t seed) {
    Rng rng(seed, 5);
    Moments m;
    for (int i = 0; i < kFurnaceSamples; ++i) {
        float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), mode);
        // The mean over the channels: its expectation is at most the largest channel's.
        m.add(s ? channel_sum(s->f) / 3.0 * std::abs(double(s->wi.z)) / double(s->pdf) : 0.0);
    }
    return m;
}

TEST(CoatedFurnace, WhiteBaseUnderSmoothCoatLosesWhatMaxDepthCuts) {
    // F + (1 - F)(1 - r^K) from sample() (the mirror reflection F included), and (1 - F)(1 - r^K)
    // from the integral of eval() |cos| by cosine-distributed directions (pi eval per sample).
    // K = (max_depth + 1) / 2: 2 for 3 events, 5 for 10; with max_depth 100, r^50 < 1e-11 and the
    // furnace is white.
    for (int max_depth : {3, 10, 100}) {
        CoatedDiffuseLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)}, LambertianLobe{Color(1.0f)}, Color(0.0f),
                               0.0f, 0.0f, static_cast<uint16_t>(max_depth), 1};
        for (float c : {1.0f, 0.6f, 0.2f, -0.4f}) {
            Vec3f wo = direction(c, 0.5f);
            double f = fresnel_reference(std::abs(double(c)), 1.5);
            SCOPED_TRACE(testing::Message() << "max_depth " << max_depth << ", cos " << c);
            for (TransportMode mode : {kRadiance, kImportance}) {
                expect_within_5_se(directional_albedo(lobe, wo, mode, 19),
                                   f + coated_white_albedo_without_mirror(std::abs(double(c)), 1.5, counted_paths(max_depth)));
                Rng rng(23, 1);
                Moments e;
                for (int i = 0; i < 100'000; ++i) {
                    Vec3f wi = sample_cosine_hemisphere(rng.next_vec2f());
                    if (c < 0.0f) wi = -wi;
                    e.add(kPiD * channel_sum(lobe.eval(wo, wi, mode)) / 3.0);
                }
                expect_within_5_se(e, coated_white_albedo_without_mirror(std::abs(double(c)), 1.5, counted_paths(max_depth)));
            }
        }
    }
}

TEST(CoatedFurnace, EveryCaseReflectsAtMostWhatArrivesInBothModesAlike) {
    for (const LobeCase& c : kLobeCases) {
        visit([&](const auto& lobe) {
            if constexpr (kIsLayered<std::decay_t<decltype(lobe)>>) {
                for (const Vec3f& wo : probe_directions()) {
                    SCOPED_TRACE(testing::Message() << c.name << ", wo.z = " << wo.z);
                    Moments radiance = directional_albedo(lobe, wo, kRadiance, 31);
                    Moments importance = directional_albedo(lobe, wo, kImportance, 37);
                    EXPECT_LE(radiance.mean(), 1.0 + 5.0 * radiance.standard_error());
                    EXPECT_LE(importance.mean(), 1.0 + 5.0 * importance.standard_error());
                    expect_same_expectation(radiance, importance);
                }
            }
        }, c.lobe);
    }
}

// ---- 4. eval in expectation

// Independent estimates of eval(wo, wi): the pair rotated about the normal by `rotations`
// angles, each call averaging the lobe's own n_samples walks (isotropic lobes only).
template <class Lobe>
Moments eval_over_rotations(const Lobe& lobe, Vec3f wo, Vec3f wi, TransportMode mode, int rotations) {
    Moments m;
    for (int k = 0; k < rotations; ++k) {
        float a = 2.0f * kPi * (float(k) + 0.5f) / float(rotations);
        float ca = std::cos(a), sa = std::sin(a);
        auto rotate = [&](Vec3f w) { return Vec3f(ca * w.x - sa * w.y, sa * w.x + ca * w.y, w.z); };
        m.add(channel_sum(lobe.eval(rotate(wo), rotate(wi), mode)));
    }
    return m;
}

TEST(CoatedEval, SmoothCoatGreyBaseIsTheSeriesOfInternalReflections) {
    // f = a T(wo) T(wi) / (pi eta^2) sum_{k<K} (a r)^k, K = (max_depth + 1) / 2, for a clear slab
    // of zero thickness (coated_closed_forms.h).
    const float a = 0.6f;
    CoatedDiffuseLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)}, LambertianLobe{Color(a)}, Color(0.0f), 0.0f,
                           0.0f, 10, 16};
    for (auto [co, ci] : {std::pair{0.9f, 0.5f}, std::pair{0.3f, 0.8f}, std::pair{-0.6f, -0.2f}}) {
        SCOPED_TRACE(testing::Message() << co << " " << ci);
        Vec3f wo = direction(co, 0.0f), wi = direction(ci, 2.0f);
        double expected = 3.0 * coated_diffuse_f(std::abs(double(co)), std::abs(double(ci)), 1.5, double(a), counted_paths(10));
        for (TransportMode mode : {kRadiance, kImportance})
            expect_within_5_se(eval_over_rotations(lobe, wo, wi, mode, 400), expected);
    }
}

TEST(CoatedEval, ReciprocalInExpectation) {
    const CoatedDiffuseLobe diffuse{CoatInterface{1.5f, TrowbridgeReitz(0.3f)}, LambertianLobe{Color(0.5f, 0.6f, 0.7f)},
                                    Color(0.8f, 0.5f, 0.3f), 0.3f, 0.3f, 10, 8};
    const CoatedConductorLobe conductor{CoatInterface{1.5f, TrowbridgeReitz(0.2f)},
                                        ConductorLobe{TrowbridgeReitz(0.3f), kGoldEta / 1.5f, kGoldK / 1.5f},
                                        Color(0.6f), 0.2f, -0.4f, 10, 8};
    for (auto [co, ci] : {std::pair{0.9f, 0.4f}, std::pair{0.2f, 0.7f}}) {
        Vec3f a = direction(co, 0.3f), b = direction(ci, 2.5f);
        SCOPED_TRACE(testing::Message() << co << " " << ci);
        expect_same_expectation(eval_over_rotations(diffuse, a, b, kRadiance, 400),
                                eval_over_rotations(diffuse, b, a, kRadiance, 400));
        expect_same_expectation(eval_over_rotations(conductor, a, b, kRadiance, 400),
                                eval_over_rotations(conductor, b, a, kRadiance, 400));
    }
}

}  // namespace
}  // namespace candela::test
