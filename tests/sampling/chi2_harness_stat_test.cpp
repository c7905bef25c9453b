// The chi-square harness can fail: a wrong pdf, samples where the pdf is 0, samples outside the
// domain and a pdf that does not integrate to 1 are all rejected, while correct samplers pass.
#include <gtest/gtest.h>

#include <optional>

#include "candela/sampling/warps.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

// The tests below that must pass, for the Sidak correction.
constexpr int kPassingChi2Tests = 2;

Chi2Options options() {
    Chi2Options opt;
    opt.test_count = kPassingChi2Tests;
    return opt;
}

auto cosine_sampler = [](Sampler& rng) { return sample_cosine_hemisphere(rng.next_vec2f()); };

TEST(Chi2Harness, AcceptsACorrectSampler) {
    Chi2Result r = chi2_test(SphericalDomain{}, cosine_sampler, cosine_hemisphere_pdf, options());
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_GT(r.dof, 1000);
}

TEST(Chi2Harness, RejectsUniformPdfForCosineSamples) {
    // Both integrate to 1 over the same support, so only the chi-square statistic can tell.
    Chi2Result r = chi2_test(SphericalDomain{}, cosine_sampler, uniform_hemisphere_pdf, options());
    EXPECT_FALSE(r.passed) << r.message;
    EXPECT_LT(r.p_value, 1e-12);
    EXPECT_NE(r.message.find("REJECTED"), std::string::npos) << r.message;
}

TEST(Chi2Harness, RejectsASlightlyWrongPdf) {
    // cos^1.1 instead of cos, renormalised: a 10% change of exponent is 1M samples' worth.
    auto pdf = [](Vec3f w) { return w.z > 0.0f ? std::pow(w.z, 1.1f) * 2.1f * kInv2Pi : 0.0f; };
    Chi2Result r = chi2_test(SphericalDomain{}, cosine_sampler, pdf, options());
    EXPECT_FALSE(r.passed) << r.message;
}

// Sobol points alone still reject a wrong pdf, but with less power: being more uniform than
// chance, they give a correct sampler a statistic far below its degrees of freedom, and the test
// (calibrated for independent samples) then needs a larger defect to reject. The 10% change of
// exponent of RejectsASlightlyWrongPdf is below that; this is why the harness also always runs
// with independent samples.
TEST(Chi2Harness, SobolPointsRejectAWrongPdfAndAreMoreUniformThanChance) {
    Chi2Options opt = options();
    opt.sources = {SamplerType::kSobol};
    Chi2Result wrong = chi2_test(SphericalDomain{}, cosine_sampler, uniform_hemisphere_pdf, opt);
    EXPECT_FALSE(wrong.passed) << wrong.message;
    Chi2Result right = chi2_test(SphericalDomain{}, cosine_sampler, cosine_hemisphere_pdf, opt);
    EXPECT_TRUE(right.passed) << right.message;
    // Independent samples would give dof +- sqrt(2 dof) (about 2500 +- 71).
    EXPECT_LT(right.statistic, 0.5 * right.dof) << right.message;
}

TEST(Chi2Harness, FailsAtOnceOnASampleWhereThePdfIsZero) {
    // Uniform sphere samples against the hemisphere's pdf: the lower half integrates to 0.
    auto sphere = [](Sampler& rng) { return sample_uniform_sphere(rng.next_vec2f()); };
    Chi2Options opt = options();
    opt.expected_integral = std::nullopt;
    Chi2Result r = chi2_test(SphericalDomain{}, sphere, uniform_hemisphere_pdf, opt);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("where the pdf integrates to 0"), std::string::npos) << r.message;
}

TEST(Chi2Harness, FailsOnASampleOutsideTheDomain) {
    PlanarDomain unit_square;
    auto sampler = [](Sampler& rng) { return rng.next_vec2f() * 1.01f; };
    Chi2Result r = chi2_test(unit_square, sampler, [](Vec2f) { return 1.0f; }, options());
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("outside the domain"), std::string::npos) << r.message;
}

TEST(Chi2Harness, FailsWhenThePdfDoesNotIntegrateToTheExpectedValue) {
    auto half = [](Vec3f w) { return 0.5f * cosine_hemisphere_pdf(w); };
    Chi2Result r = chi2_test(SphericalDomain{}, cosine_sampler, half, options());
    EXPECT_FALSE(r.passed);
    EXPECT_NEAR(r.pdf_integral, 0.5, 1e-4);
    EXPECT_NE(r.message.find("integrates to 0.5"), std::string::npos) << r.message;
}

TEST(Chi2Harness, AcceptsASamplerThatFailsWithThePdfsMissingMass) {
    // Rejection sampling of the unit disk from the square [-1, 1]^2 succeeds with probability
    // pi / 4; the pdf of the successes is 1/4 per unit area.
    PlanarDomain square{{-1.0, -1.0}, {1.0, 1.0}};
    auto sampler = [](Sampler& rng) -> std::optional<Vec2f> {
        Vec2f u = rng.next_vec2f();
        Vec2f p(2.0f * u.x - 1.0f, 2.0f * u.y - 1.0f);
        if (p.x * p.x + p.y * p.y > 1.0f) return std::nullopt;
        return p;
    };
    auto pdf = [](Vec2f p) { return p.x * p.x + p.y * p.y <= 1.0f ? 0.25f : 0.0f; };
    Chi2Options opt = options();
    opt.res_x = opt.res_y = 50;
    opt.expected_integral = kPiD / 4.0;
    Chi2Result r = chi2_test(square, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace candela::test
