// The tabulated BSSRDF (materials/tabulated_bssrdf.h): the profile is the table scaled to the
// medium, its radial density integrates to 1, the probe segments have the geometry pdf_sp
// assumes, and the exit lobe integrates to 1 against the cosine. Chi-square fits of the
// sampling are in tabulated_bssrdf_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/tabulated_bssrdf.h"
#include "support/printers.h"

namespace candela {
namespace CANDELA_UNITY_ID {

const BssrdfTable& table_133() {
    static const BssrdfTable table = make_beam_diffusion_table(0.0f, 1.33f);
    return table;
}

TEST(TabulatedBssrdf, ProfileIsTheTableScaledToTheMedium) {
    const BssrdfTable& t = table_133();
    // At a table node of albedo and optical radius the spline passes through the entry.
    const float rho = t.rho_samples[70], sigma_t = 2.5f;
    const TabulatedBssrdf b(Vec3f(0.0f), Vec3f(0, 0, 1), 1.33f, Color((1.0f - rho) * sigma_t),
                            Color(rho * sigma_t), &t, 0);
    for (int j : {5, 20, 40}) {
        const float r_optical = t.radius_samples[static_cast<size_t>(j)];
        const float expected = t.eval_profile(70, j) / (2.0f * kPi * r_optical) * sigma_t * sigma_t;
        EXPECT_NEAR(b.sr(r_optical / sigma_t)[0], expected, 1e-5f * expected) << j;
        EXPECT_NEAR(b.pdf_sr(r_optical / sigma_t)[0], expected / t.rho_eff[70], 1e-5f * expected) << j;
        EXPECT_EQ(b.sp(Vec3f(0.0f, r_optical / sigma_t, 0.0f))[1], b.sr(r_optical / sigma_t)[1]);
    }
    // Beyond the table's last radius: nothing.
    EXPECT_TRUE(b.sr(t.radius_samples.back() / sigma_t * 1.01f).is_black());
}

// pdf_sr 2 pi r is the spline of the table's profile over its effective albedo, piecewise cubic
// in r between nodes, so Simpson's rule on each interval integrates it exactly (up to float
// rounding): it integrates to 1 for every channel, here four different media at once.
TEST(TabulatedBssrdf, RadialDensityIntegratesToOne) {
    const BssrdfTable& t = table_133();
    const Color sigma_s = Color::from_channels(0.5f, 3.0f, 9.9f, 0.2f);
    const Color sigma_a = Color::from_channels(0.5f, 1.0f, 0.1f, 0.0001f);
    const TabulatedBssrdf b(Vec3f(0.0f), Vec3f(0, 0, 1), 1.33f, sigma_a, sigma_s, &t, 0);
    for (int c = 0; c < kColorChannels; ++c) {
        const auto sigma_t = static_cast<double>(sigma_a[c] + sigma_s[c]);
        double sum = 0.0;
        for (size_t j = 0; j + 1 < t.radius_samples.size(); ++j) {
            const double r0 = static_cast<double>(t.radius_samples[j]) / sigma_t;
            const double r1 = static_cast<double>(t.radius_samples[j + 1]) / sigma_t;
            auto radial = [&](double r) {
                return 2.0 * kPiD * r * static_cast<double>(b.pdf_sr(static_cast<float>(r))[c]);
            };
            sum += (r1 - r0) / 6.0 * (radial(r0) + 4.0 * radial(0.5 * (r0 + r1)) + radial(r1));
        }
        EXPECT_NEAR(sum, 1.0, 2e-4) << "channel " << c;
    }
}

// A probe segment is a chord of the sphere of radius r_max about po, parallel to one of the
// three axes, at distance r from po (the disk point's radius); the axis is ns for u1 >= 0.5.
TEST(TabulatedBssrdf, ProbeSegmentsAreChordsOfTheRMaxSphere) {
    const BssrdfTable& t = table_133();
    const Vec3f po(1.0f, 2.0f, 3.0f), ns = normalize(Vec3f(0.3f, -0.4f, 0.8f));
    const TabulatedBssrdf b(po, ns, 1.33f, Color(0.2f), Color(1.8f), &t, 0);
    const float r_max = *b.sample_sr(0.999f);
    int found = 0;
    for (int i = 0; i < 64; ++i) {
        const float u1 = (static_cast<float>(i) + 0.5f) / 64.0f;
        const float u2a = static_cast<float>((i * 37) % 64) / 64.0f, u2b = static_cast<float>((i * 11) % 64) / 64.0f;
        std::optional<BssrdfProbeSegment> seg = b.sample_sp(u1, u2a, u2b);
        if (!seg) continue;
        ++found;
        const float r = *b.sample_sr(u2a);
        const Vec3f mid = (seg->p0 + seg->p1) * 0.5f, axis = normalize(seg->p1 - seg->p0);
        EXPECT_NEAR(length(mid - po), r, 1e-4f);
        EXPECT_NEAR(length(seg->p0 - po), r_max, 1e-4f);
        EXPECT_NEAR(length(seg->p1 - po), r_max, 1e-4f);
        EXPECT_NEAR(dot(mid - po, axis), 0.0f, 1e-4f);
        EXPECT_NEAR(std::abs(dot(axis, ns)), u1 >= 0.5f ? 1.0f : 0.0f, 1e-5f) << "u1 " << u1;
    }
    EXPECT_GT(found, 60);
    EXPECT_FALSE(b.sample_sp(0.7f, 0.9995f, 0.2f).has_value());  // r beyond r_max
}

// The exit lobe's directional albedo, 2 pi int_0^1 f(mu) mu dmu by the midpoint rule on 20,000
// steps: 1 for light transport from lights (importance), eta^2 for camera paths, up to the error
// of the Fresnel moment's fit at 1 / eta (< 2e-5, so < 5e-5 here). Control: normalizing by the
// moment at eta instead of 1 / eta (pbrt-v4's header calls its argument invEta) gives 1.8 at
// eta = 1.33.
TEST(NormalizedFresnel, DirectionalAlbedoIsOne) {
    for (float eta : {1.2f, 1.33f, 1.5f, 2.0f}) {
        const NormalizedFresnel lobe{eta};
        double importance = 0.0, radiance = 0.0, control = 0.0;
        const int n = 20000;
        const auto c_wrong = static_cast<double>(1.0f - 2.0f * fresnel_moment1(eta));
        const auto c = static_cast<double>(1.0f - 2.0f * fresnel_moment1(1.0f / eta));
        for (int i = 0; i < n; ++i) {
            const float mu = (static_cast<float>(i) + 0.5f) / n;
            const auto weight = 2.0 * kPiD * static_cast<double>(mu) / n;
            importance += static_cast<double>(lobe.f(mu, TransportMode::kImportance)[0]) * weight;
            radiance += static_cast<double>(lobe.f(mu)[0]) * weight;
            control += static_cast<double>(lobe.f(mu, TransportMode::kImportance)[0]) * (c / c_wrong) * weight;
        }
        const auto eta2 = static_cast<double>(eta * eta);
        EXPECT_NEAR(importance, 1.0, 1e-4) << "eta " << eta;
        EXPECT_NEAR(radiance, eta2, 1e-4 * eta2) << "eta " << eta;
        EXPECT_GT(std::abs(control - 1.0), 0.1) << "eta " << eta;
    }
}

TEST(NormalizedFresnel, SampleAgreesWithEvalAndPdf) {
    const NormalizedFresnel lobe{1.5f};
    for (const Vec3f& wo : {Vec3f(0, 0, 1), normalize(Vec3f(0.5f, 0.2f, -0.7f))}) {
        for (int i = 0; i < 16; ++i) {
            const Vec2f u((static_cast<float>(i) + 0.5f) / 16.0f, (static_cast<float>((i * 7) % 16) + 0.5f) / 16.0f);
            std::optional<BsdfSample> s = lobe.sample(wo, 0.0f, u, TransportMode::kRadiance);
            ASSERT_TRUE(s.has_value());
            EXPECT_TRUE(same_hemisphere(wo, s->wi));
            EXPECT_EQ(s->f, lobe.eval(wo, s->wi, TransportMode::kRadiance));
            EXPECT_EQ(s->pdf, lobe.pdf(wo, s->wi));
            EXPECT_FALSE(s->is_delta);
        }
    }
    EXPECT_TRUE(lobe.eval(Vec3f(0, 0, 1), Vec3f(0, 0, -1), TransportMode::kRadiance).is_black());
    EXPECT_EQ(lobe.pdf(Vec3f(0, 0, 1), Vec3f(0, 0, -1)), 0.0f);
}

}  // namespace CANDELA_UNITY_ID
}  // namespace candela
