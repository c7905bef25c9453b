// Statistical tests of the hair lobe (materials/hair.h): chi-square of sample() against pdf(),
// whose integral over the sphere must be 1, and the white furnace by uniform directions (the
// integral of f |cos| over the sphere is 1 without absorption, for any h and wo).
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/hair.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;
constexpr int kChi2Tests = 6;

// The sphere in the fibre's coordinates: (phi, sin theta) = (atan2(w.z, w.y), w.x), of unit
// Jacobian, so the cells are equal solid angles and lie along the hair's lobes.
struct FibreDomain {
    using Point = Vec3f;
    Vec2d param_min() const { return {-kPiD, -1.0}; }
    Vec2d param_max() const { return {kPiD, 1.0}; }
    Vec2d to_param(Vec3f w) const {
        return {std::atan2(double(w.z), double(w.y)), std::clamp(double(w.x), -1.0, 1.0)};
    }
    Vec3f from_param(Vec2d q) const {
        const double c = std::sqrt(std::max(0.0, 1.0 - q.y * q.y));
        return Vec3f(Vec3d(q.y, c * std::cos(q.x), c * std::sin(q.x)));
    }
    double jacobian(Vec2d) const { return 1.0; }
};

void expect_sampling_fits_pdf(const HairLobe& lobe, Vec3f wo) {
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_y = 100;
    opt.expected_integral = 1.0;  // sampling never fails: the pdf integrates to 1
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        const float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
        if (!s) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](Vec3f wi) { return lobe.pdf(wo, wi); };
    Chi2Result r = chi2_test(FibreDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

const Color kBrown(0.419f * 1.3f, 0.697f * 1.3f, 1.37f * 1.3f);

Vec3f unit(Vec3f v) { return normalize(v); }

TEST(HairChi2, DefaultsAtAnOffset) {
    expect_sampling_fits_pdf(HairLobe::make(0.3f, 1.55f, kBrown, 0.3f, 0.3f, radians(2.0f)), unit(Vec3f(0.4f, 0.5f, 0.7f)));
}
TEST(HairChi2, WhiteRoughNearTheEdge) {
    expect_sampling_fits_pdf(HairLobe::make(-0.95f, 1.55f, Color(0.0f), 0.6f, 0.8f, radians(2.0f)), unit(Vec3f(-0.2f, -0.9f, 0.3f)));
}
TEST(HairChi2, NarrowLongitudinallyAlongTheFibre) {
    expect_sampling_fits_pdf(HairLobe::make(0.0f, 1.55f, Color(0.2f, 0.4f, 0.8f), 0.2f, 0.5f, radians(5.0f)),
                             unit(Vec3f(0.8f, 0.1f, -0.4f)));
}
TEST(HairChi2, NarrowAzimuthally) {
    expect_sampling_fits_pdf(HairLobe::make(0.6f, 1.55f, Color(0.05f), 0.4f, 0.2f, radians(2.0f)), unit(Vec3f(0.1f, 0.3f, 0.9f)));
}
TEST(HairChi2, DarkHairTiltedScales) {
    expect_sampling_fits_pdf(HairLobe::make(-0.4f, 1.6f, Color(3.0f, 5.0f, 8.0f), 0.35f, 0.35f, radians(8.0f)),
                             unit(Vec3f(-0.5f, 0.2f, -0.8f)));
}
TEST(HairChi2, SpectralChannels) {
    expect_sampling_fits_pdf(HairLobe::make(0.8f, 1.55f, Color::from_channels(0.1f, 0.5f, 1.2f, 2.5f), 0.5f, 0.3f,
                                            radians(2.0f)),
                             unit(Vec3f(0.3f, -0.6f, 0.5f)));
}

TEST(HairFurnace, WithoutAbsorptionEverythingIsScattered) {
    // The mean of 4 pi f(wo, wi) |cos wi| over uniform wi, h uniform in [-1, 1] and a random wo
    // (pbrt-v4's WhiteFurnace test), within 5 standard errors of 1, for beta_m, beta_n from 0.1 to
    // 0.9 (below 0.1 the narrow lobes need far more uniform samples than a test can take).
    Rng rng(29, 3);
    for (float beta_m = 0.1f; beta_m < 1.0f; beta_m += 0.2f) {
        for (float beta_n = 0.1f; beta_n < 1.0f; beta_n += 0.2f) {
            const Vec3f wo = sample_uniform_sphere(rng.next_vec2f());
            const int n = beta_m < 0.5f ? 200'000 : 50'000;
            double sum = 0.0, sum_sq = 0.0;
            for (int i = 0; i < n; ++i) {
                const HairLobe lobe = HairLobe::make(-1.0f + 2.0f * rng.next_float(), 1.55f, Color(0.0f), beta_m,
                                                     beta_n, radians(2.0f));
                const Vec3f wi = sample_uniform_sphere(rng.next_vec2f());
                const double w = double(lobe.eval(wo, wi, kRadiance)[0]) * std::abs(double(wi.z)) / double(kInv4Pi);
                sum += w;
                sum_sq += w * w;
            }
            const double mean = sum / n, variance = std::max(0.0, sum_sq / n - mean * mean);
            const double standard_error = std::sqrt(variance / (n - 1.0));
            EXPECT_NEAR(mean, 1.0, 5.0 * standard_error + 1e-4)
                << "beta_m " << beta_m << ", beta_n " << beta_n << ", standard error " << standard_error;
        }
    }
}

TEST(HairFurnace, SampledWeightsAverageToTheUniformEstimate) {
    // With absorption: E[f |cos| / pdf] over sample() equals E[4 pi f |cos|] over uniform
    // directions (pbrt-v4's SamplingConsistency), the two within 5 combined standard errors.
    Rng rng(31, 4);
    for (float beta_m : {0.2f, 0.5f, 0.8f}) {
        for (float beta_n : {0.3f, 0.7f}) {
            const HairLobe lobe = HairLobe::make(0.4f, 1.55f, kBrown * 0.5f, beta_m, beta_n, radians(2.0f));
            const Vec3f wo = sample_uniform_sphere(rng.next_vec2f());
            const int n = 200'000;
            double s1 = 0.0, s1q = 0.0, s2 = 0.0, s2q = 0.0;
            for (int i = 0; i < n; ++i) {
                const float uc = rng.next_float();
                auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
                const double a = s ? double(s->f[1]) * std::abs(double(s->wi.z)) / double(s->pdf) : 0.0;
                s1 += a;
                s1q += a * a;
                const Vec3f wi = sample_uniform_sphere(rng.next_vec2f());
                const double b = double(lobe.eval(wo, wi, kRadiance)[1]) * std::abs(double(wi.z)) / double(kInv4Pi);
                s2 += b;
                s2q += b * b;
            }
            const double m1 = s1 / n, m2 = s2 / n;
            const double v1 = std::max(0.0, s1q / n - m1 * m1) / (n - 1.0);
            const double v2 = std::max(0.0, s2q / n - m2 * m2) / (n - 1.0);
            EXPECT_NEAR(m1, m2, 5.0 * std::sqrt(v1 + v2) + 1e-5) << "beta_m " << beta_m << ", beta_n " << beta_n;
            EXPECT_LT(m1, 1.0);
        }
    }
}

}  // namespace
}  // namespace candela::test
