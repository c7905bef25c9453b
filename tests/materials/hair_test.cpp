// The hair lobe (materials/hair.h): sample() returns eval() and pdf() exactly, the symmetries the
// model has, sampled white-furnace weights, the reflectance inversion, the material's parameters
// in both colour modes.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/material.h"
#include "candela/sampling/rng.h"
#include "candela/sampling/warps.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;

// A random lobe: h, beta_m, beta_n over their ranges, alpha 2 degrees, brown or white.
HairLobe random_hair(Rng& rng, bool absorbing) {
    const float h = -1.0f + 2.0f * rng.next_float();
    const float beta_m = 0.05f + 0.95f * rng.next_float(), beta_n = 0.05f + 0.95f * rng.next_float();
    const Color sigma_a = absorbing ? Color(0.419f, 0.697f, 1.37f) * (0.2f + 3.0f * rng.next_float()) : Color(0.0f);
    return HairLobe::make(h, 1.55f, sigma_a, beta_m, beta_n, radians(2.0f));
}

TEST(HairLobe, BesselI0AndItsLogarithmAreAccurate) {
    // Reference values from the series summed exactly (rational arithmetic, 300 terms).
    EXPECT_NEAR(hair_i0(0.5f), 1.0634833707f, 1e-6f);
    EXPECT_NEAR(hair_i0(1.0f), 1.2660658778f, 1e-6f);
    EXPECT_NEAR(hair_i0(5.0f), 27.239871824f, 27.24f * 1e-6f);
    EXPECT_NEAR(hair_i0(12.0f), 18948.925349f, 18949.0f * 1e-6f);
    EXPECT_NEAR(hair_log_i0(12.0f), 9.8495024991f, 1e-5f);
    // The asymptote, on both sides of the switch and far out.
    EXPECT_NEAR(hair_log_i0(12.5f), 10.328635515f, 1e-5f);
    EXPECT_NEAR(hair_log_i0(30.0f), 27.384701433f, 1e-5f);
    EXPECT_NEAR(hair_log_i0(100.0f), 96.779732690f, 2e-5f);
}

TEST(HairLobe, MpIsSymmetricInItsTwoDirections) {
    Rng rng(3, 1);
    for (int i = 0; i < 1000; ++i) {
        const float si = 2.0f * rng.next_float() - 1.0f, so = 2.0f * rng.next_float() - 1.0f;
        const float ci = std::sqrt(1.0f - si * si), co = std::sqrt(1.0f - so * so);
        for (float v : {0.001f, 0.05f, 0.1f, 0.3f, 2.0f}) EXPECT_EQ(hair_mp(ci, co, si, so, v), hair_mp(co, ci, so, si, v));
    }
}

TEST(HairLobe, SampleReturnsEvalAndPdfOfItsDirection) {
    Rng rng(5, 2);
    for (int i = 0; i < 2000; ++i) {
        const HairLobe lobe = random_hair(rng, i % 2 == 0);
        const Vec3f wo = sample_uniform_sphere(rng.next_vec2f());
        const float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
        ASSERT_TRUE(s.has_value());
        EXPECT_NEAR(length(s->wi), 1.0f, 1e-5f);
        EXPECT_EQ(s->f, lobe.eval(wo, s->wi, kRadiance));
        EXPECT_EQ(s->pdf, lobe.pdf(wo, s->wi));
        EXPECT_FALSE(s->is_delta);
        EXPECT_EQ(s->is_transmission, s->wi.z * wo.z < 0.0f);
        EXPECT_EQ(s->eta, 1.0f);
    }
}

TEST(HairLobe, ReciprocalAtTheCentreWithoutScalesForEqualLongitudes) {
    // With h = 0 and alpha = 0 the azimuthal lobes are centred on p pi (even under phi -> -phi),
    // and with |theta_i| = |theta_o| the attenuations Ap(theta) agree: S(wo, wi) = S(wi, wo),
    // S = f |cos wi|, to float rounding. Elsewhere the model is not reciprocal (hair.h).
    Rng rng(9, 3);
    for (int i = 0; i < 500; ++i) {
        const HairLobe lobe = HairLobe::make(0.0f, 1.55f, Color(0.3f, 0.8f, 2.0f), 0.1f + 0.9f * rng.next_float(),
                                             0.1f + 0.9f * rng.next_float(), 0.0f);
        const Vec3f wo = sample_uniform_sphere(rng.next_vec2f());
        const float phi = 2.0f * kPi * rng.next_float();
        const float sign = rng.next_float() < 0.5f ? -1.0f : 1.0f;
        const float c = std::sqrt(std::max(0.0f, 1.0f - wo.x * wo.x));
        const Vec3f wi(sign * wo.x, c * std::cos(phi), c * std::sin(phi));
        const Color a = lobe.eval(wo, wi, kRadiance) * std::abs(wi.z);
        const Color b = lobe.eval(wi, wo, kRadiance) * std::abs(wo.z);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 2e-4f * std::max(a[k], b[k]) + 1e-7f);
    }
}

TEST(HairLobe, WhiteFurnaceSampleWeightsAreOne) {
    // Without absorption sum_p Ap = 1 and the sampling density is f |cos| itself, so every
    // weight f |cos| / pdf is 1 up to rounding (pbrt-v4's SamplingWeights test).
    Rng rng(11, 4);
    for (float beta_m = 0.1f; beta_m < 1.0f; beta_m += 0.2f) {
        for (float beta_n = 0.1f; beta_n < 1.0f; beta_n += 0.2f) {
            for (int i = 0; i < 500; ++i) {
                const HairLobe lobe = HairLobe::make(-1.0f + 2.0f * rng.next_float(), 1.55f, Color(0.0f), beta_m,
                                                     beta_n, radians(2.0f));
                const Vec3f wo = sample_uniform_sphere(rng.next_vec2f());
                const float uc = rng.next_float();
                auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
                ASSERT_TRUE(s.has_value());
                const float w = s->f[0] * std::abs(s->wi.z) / s->pdf;
                EXPECT_NEAR(w, 1.0f, 1e-4f) << "beta_m " << beta_m << ", beta_n " << beta_n;
            }
        }
    }
}

TEST(HairLobe, ReflectanceInversionRoundTrips) {
    // Chiang et al. eq. 4 inverts c = exp(-sqrt(sigma_a) D(beta_n)): the forward map gives c back.
    for (float beta_n = 0.1f; beta_n < 1.0f; beta_n += 0.1f) {
        const float b = beta_n;
        const float d = 5.969f - 0.215f * b + 2.532f * b * b - 10.73f * b * b * b + 5.574f * b * b * b * b +
                        0.245f * b * b * b * b * b;
        for (float c = 0.05f; c < 1.0f; c += 0.05f) {
            const float sigma_a = hair_sigma_a_from_reflectance(c, beta_n);
            EXPECT_GE(sigma_a, 0.0f);
            EXPECT_NEAR(std::exp(-std::sqrt(sigma_a) * d), c, 1e-5f);
        }
        EXPECT_EQ(hair_sigma_a_from_reflectance(1.0f, beta_n), 0.0f);
    }
}

TEST(HairLobe, BrighterReflectanceGivesABrighterFibre) {
    // The fit is for a volume of many fibres, so one fibre's albedo is not c; but it grows with c.
    float previous = 0.0f;
    for (float c = 0.1f; c < 1.0f; c += 0.1f) {
        const Color sigma_a(hair_sigma_a_from_reflectance(c, 0.3f));
        const float albedo = HairLobe::make(0.2f, 1.55f, sigma_a, 0.3f, 0.3f, radians(2.0f)).albedo()[0];
        EXPECT_GT(albedo, previous);
        previous = albedo;
    }
}

TEST(HairLobe, SpectralChannelsAreIndependent) {
    // Each channel of f is the lobe's value for that channel's absorption alone: four
    // wavelengths' sigma_a give, channel by channel, what a grey sigma_a of that value gives.
    Rng rng(13, 5);
    for (int i = 0; i < 200; ++i) {
        const Color sigma_a = Color::from_channels(0.1f, 0.7f, 1.9f, 4.0f) * (0.5f + rng.next_float());
        const float h = -1.0f + 2.0f * rng.next_float();
        const HairLobe lobe = HairLobe::make(h, 1.55f, sigma_a, 0.3f, 0.4f, radians(2.0f));
        const Vec3f wo = sample_uniform_sphere(rng.next_vec2f()), wi = sample_uniform_sphere(rng.next_vec2f());
        const Color f = lobe.eval(wo, wi, kRadiance);
        for (int k = 0; k < 4; ++k) {
            const HairLobe grey = HairLobe::make(h, 1.55f, Color(sigma_a[k]), 0.3f, 0.4f, radians(2.0f));
            EXPECT_EQ(f[k], grey.eval(wo, wi, kRadiance)[k]);
        }
    }
}

TEST(HairMaterial, IsBuiltPerHitWithItsOffsetFromV) {
    HairParams p;
    p.sigma_a.value = Rgb(0.2f, 0.5f, 1.0f);
    const Material m = make_material(p);
    EXPECT_TRUE(m.textured);
    EXPECT_TRUE(m.anisotropic);
    EXPECT_TRUE(m.needs_shading_geometry);
    EXPECT_TRUE(m.per_hit);
    const TextureSet textures;
    const Bsdf b = build_bsdf(m, textures, TextureContext{Vec2f(0.3f, 0.75f), Vec3f(0.0f), nullptr});
    const HairLobe& lobe = std::get<HairLobe>(b.lobes[0]);
    EXPECT_EQ(lobe.h, 0.5f);
    EXPECT_EQ(lobe.eta, 1.55f);
    EXPECT_EQ(lobe.sigma_a, Color(0.2f, 0.5f, 1.0f));
    const HairLobe expected = HairLobe::make(0.5f, 1.55f, Color(0.2f, 0.5f, 1.0f), 0.3f, 0.3f, radians(2.0f));
    EXPECT_EQ(lobe.v0, expected.v0);
    EXPECT_EQ(lobe.s, expected.s);
    EXPECT_EQ(lobe.sin2k_alpha, expected.sin2k_alpha);
}

TEST(HairMaterial, SpectralModeUpliftsSigmaAUnboundedAndReflectanceAsAnAlbedo) {
    const TextureSet textures;
    const Color lambda = Color::from_channels(420.0f, 510.0f, 580.0f, 660.0f);
    const TextureContext ctx{Vec2f(0.5f, 0.5f), Vec3f(0.0f), &lambda};

    HairParams absorbing;
    absorbing.sigma_a.value = Rgb(0.5f, 1.5f, 3.0f);
    const Material a = make_material(absorbing);
    const HairLobe la = std::get<HairLobe>(build_bsdf(a, textures, ctx).lobes[0]);
    const RgbSpectrum sa = rgb_unbounded_spectrum(Rgb(0.5f, 1.5f, 3.0f));
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(la.sigma_a[k], sa(lambda[k]));

    HairParams coloured;
    coloured.reflectance.value = Rgb(0.6f, 0.4f, 0.2f);
    coloured.from_reflectance = true;
    const Material c = make_material(coloured);
    const HairLobe lc = std::get<HairLobe>(build_bsdf(c, textures, ctx).lobes[0]);
    const RgbSpectrum r = rgb_albedo_spectrum(Rgb(0.6f, 0.4f, 0.2f));
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(lc.sigma_a[k], hair_sigma_a_from_reflectance(r(lambda[k]), 0.3f));
    // RGB mode: per channel of the RGB value.
    const HairLobe rgb = std::get<HairLobe>(build_bsdf(c, textures, TextureContext{Vec2f(0.5f, 0.5f), Vec3f(0.0f), nullptr}).lobes[0]);
    EXPECT_FLOAT_EQ(rgb.sigma_a[1], hair_sigma_a_from_reflectance(0.4f, 0.3f));
}

TEST(HairMaterial, BetasAreClampedAsPbrtV4Does) {
    HairParams p;
    p.beta_m = FloatParam{0.0f};
    p.beta_n = FloatParam{0.0f};
    const Material m = make_material(p);
    const HairLobe lobe = std::get<HairLobe>(m.bsdf.lobes[0]);
    const HairLobe expected = HairLobe::make(-1.0f, 1.55f, lobe.sigma_a, 0.01f, 0.01f, radians(2.0f));
    EXPECT_EQ(lobe.v0, expected.v0);
    EXPECT_EQ(lobe.s, expected.s);
}

}  // namespace
}  // namespace candela::test
