// The coated lobes, case by case: what is deterministic about them (their estimates are fixed
// functions of the directions, the closed forms where the walk has no choice left) and how the
// material parameters build them. Their statistical properties are in layered_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/layered.h"
#include "candela/materials/lobe_params.h"
#include "candela/sampling/rng.h"
#include "materials/coated_closed_forms.h"
#include "materials/lobe_cases.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;
constexpr TransportMode kImportance = TransportMode::kImportance;

CoatedDiffuseLobe coated_diffuse(float alpha, Color base, int max_depth = 10, float thickness = 0.01f) {
    return CoatedDiffuseLobe{CoatInterface{1.5f, TrowbridgeReitz(alpha)}, LambertianLobe{base}, Color(0.0f),
                             thickness, 0.0f, static_cast<uint16_t>(max_depth), 1};
}

// Calls check(lobe) for every coated case of kLobeCases.
template <class F>
void for_each_layered_case(F check) {
    for (const LobeCase& c : kLobeCases) {
        visit([&](const auto& lobe) {
            if constexpr (kIsLayered<std::decay_t<decltype(lobe)>>) {
                SCOPED_TRACE(c.name);
                check(lobe);
            }
        }, c.lobe);
    }
}

TEST(LayeredLobe, EstimatesAreFixedFunctionsOfTheirArguments) {
    // The same arguments give the same bits, whatever was evaluated in between; nearby
    // directions draw other random numbers.
    for_each_layered_case([](const auto& lobe) {
        Vec3f wo = direction(0.7f, 0.2f), wi = direction(0.4f, 2.0f), wi2 = direction(0.4f, 2.001f);
        Color f = lobe.eval(wo, wi, kRadiance);
        float pdf = lobe.pdf(wo, wi);
        auto s = lobe.sample(wo, 0.3f, Vec2f(0.6f, 0.1f), kRadiance);
        lobe.eval(wo, wi2, kRadiance);
        lobe.pdf(wo, wi2);
        EXPECT_EQ(lobe.eval(wo, wi, kRadiance), f);
        EXPECT_EQ(lobe.pdf(wo, wi), pdf);
        auto again = lobe.sample(wo, 0.3f, Vec2f(0.6f, 0.1f), kRadiance);
        ASSERT_EQ(s.has_value(), again.has_value());
        if (s) {
            EXPECT_EQ(s->wi, again->wi);
            EXPECT_EQ(s->f, again->f);
            EXPECT_EQ(s->pdf, again->pdf);
        }
    });
}

TEST(LayeredLobe, TwoSidedAndOpaque) {
    // Below the surface the lobe mirrors itself; across it nothing is transmitted, and the
    // density there is pbrt-v4's uniform share 0.1 / (4 pi) (0 for a delta lobe).
    for_each_layered_case([](const auto& lobe) {
        for (const Vec3f& wo : probe_directions()) {
            Vec3f wi = direction(0.5f, 1.0f);
            if (wo.z < 0.0f) wi = -wi;
            EXPECT_EQ(lobe.eval(wo, wi, kRadiance), lobe.eval(-wo, -wi, kRadiance));
            EXPECT_EQ(lobe.pdf(wo, wi), lobe.pdf(-wo, -wi));
            EXPECT_EQ(lobe.eval(wo, -wi, kRadiance), Color(0.0f));
            EXPECT_EQ(lobe.pdf(wo, -wi), lobe.is_delta() ? 0.0f : 0.1f * kInv4Pi);
            if (!lobe.is_delta()) {
                EXPECT_GE(lobe.pdf(wo, wi), 0.1f * kInv4Pi);
            }
        }
    });
}

TEST(CoatedDiffuse, OneEventIsTheSingleBounceClosedForm) {
    // With max_depth 1 the walk ends at its first base event, joined to wi through the smooth
    // coat: f = a T(wo) T(wi) exp(-d / cos_to) exp(-d / cos_ti) / (pi eta^2), cos_t the refracted
    // cosines (the slab's transmittance along the refracted paths). Nothing is random.
    const Color a(0.8f, 0.5f, 0.2f);
    const double d = 0.3;
    CoatedDiffuseLobe lobe = coated_diffuse(0.0f, a, 1, float(d));
    auto cos_refracted = [](double c) { return std::sqrt(1.0 - (1.0 - c * c) / 2.25); };
    for (float co : {1.0f, 0.8f, 0.3f, 0.05f}) {
        for (float ci : {0.9f, 0.5f, 0.1f}) {
            double expected = (1.0 - fresnel_reference(co, 1.5)) * (1.0 - fresnel_reference(ci, 1.5)) *
                              std::exp(-d / cos_refracted(co)) * std::exp(-d / cos_refracted(ci)) / (kPiD * 2.25);
            for (TransportMode mode : {kRadiance, kImportance}) {
                Color f = lobe.eval(direction(co, 0.5f), direction(ci, 2.0f), mode);
                EXPECT_NEAR(f[0], double(a[0]) * expected, 2e-6 + 1e-5 * expected) << co << " " << ci;
                EXPECT_NEAR(f[2], double(a[2]) * expected, 2e-6 + 1e-5 * expected) << co << " " << ci;
            }
        }
    }
}

TEST(CoatedDiffuse, SmoothCoatPdfIsPbrtsClosedForm) {
    // pbrt-v4's PDF: 0.1 / (4 pi) + 0.9 (the base's density between the refracted directions),
    // the coat's reflection having no density; the refraction of wo is fixed, so for a
    // Lambertian base this is 0.9 cos_t(wi) / pi, with no randomness.
    for (int n_samples : {1, 3}) {
        CoatedDiffuseLobe lobe = coated_diffuse(0.0f, Color(0.5f));
        lobe.n_samples = static_cast<uint16_t>(n_samples);
        for (float co : {0.9f, -0.4f}) {
            for (float ci : {0.95f, 0.5f, 0.02f}) {
                float cos_t = std::sqrt(1.0f - (1.0f - ci * ci) / 2.25f);
                float expected = 0.1f * kInv4Pi + 0.9f * cos_t * kInvPi;
                Vec3f wo = direction(co, 1.0f), wi = direction(co > 0.0f ? ci : -ci, 3.0f);
                EXPECT_NEAR(lobe.pdf(wo, wi), expected, 1e-6f);
            }
        }
    }
}

TEST(CoatedConductor, SmoothCoatOverSmoothMetalInClearMediumIsDelta) {
    CoatedConductorLobe lobe{CoatInterface{1.5f, TrowbridgeReitz(0.0f)},
                             ConductorLobe{TrowbridgeReitz(0.0f), kGoldEta / 1.5f, kGoldK / 1.5f}, Color(0.0f),
                             0.01f, 0.0f, 10, 1};
    EXPECT_TRUE(lobe.is_delta());
    Vec3f wo = direction(0.6f, 0.4f);
    EXPECT_EQ(lobe.eval(wo, Vec3f(-wo.x, -wo.y, wo.z), kRadiance), Color(0.0f));
    EXPECT_EQ(lobe.pdf(wo, Vec3f(-wo.x, -wo.y, wo.z)), 0.0f);
    Rng rng(3, 3);
    for (int i = 0; i < 100; ++i) {
        auto s = lobe.sample(wo, rng.next_float(), rng.next_vec2f(), kRadiance);
        if (!s) continue;
        EXPECT_TRUE(s->is_delta);
        EXPECT_NEAR(s->wi.x, -wo.x, 1e-5f);
        EXPECT_NEAR(s->wi.z, wo.z, 1e-5f);
    }
    // Medium scattering or a rough layer makes it non-delta.
    lobe.medium_albedo = Color(0.5f);
    EXPECT_FALSE(lobe.is_delta());
    lobe.medium_albedo = Color(0.0f);
    lobe.base.distribution = TrowbridgeReitz(0.1f);
    EXPECT_FALSE(lobe.is_delta());
}

TEST(CoatedLobes, OnlyASmoothCoatGivesDeltaSamples) {
    Rng rng(4, 1);
    CoatedDiffuseLobe rough = coated_diffuse(0.2f, Color(0.5f));
    CoatedDiffuseLobe smooth = coated_diffuse(0.0f, Color(0.5f));
    Vec3f wo = direction(0.5f, 0.0f);
    int mirror = 0;
    for (int i = 0; i < 2000; ++i) {
        float uc = rng.next_float();
        Vec2f u = rng.next_vec2f();
        auto r = rough.sample(wo, uc, u, kRadiance);
        if (r) {
            EXPECT_FALSE(r->is_delta);
        }
        auto s = smooth.sample(wo, uc, u, kRadiance);
        // The smooth coat's mirror reflection, chosen when uc < F(cos wo).
        if (s && s->is_delta) {
            ++mirror;
            EXPECT_LT(uc, fresnel_dielectric(0.5f, 1.5f));
            EXPECT_EQ(s->pdf, fresnel_dielectric(0.5f, 1.5f));
        }
    }
    EXPECT_GT(mirror, 0);
}

TEST(CoatedParams, BuildTheLobesAsPbrtGetBxDF) {
    const TextureSet textures;
    const TextureContext ctx{};
    CoatedDiffuseParams d;
    d.albedo = ColorParam{Rgb(1.5f, 0.5f, -1.0f)};
    d.coat.roughness.alpha_u = FloatParam{0.2f};
    d.coat.roughness.alpha_v = FloatParam{0.05f};
    d.coat.ior = 0.0f;
    d.coat.medium_albedo = ColorParam{Rgb(2.0f, 0.5f, 0.25f)};
    d.coat.g = FloatParam{-3.0f};
    d.coat.thickness = FloatParam{0.2f};
    d.coat.max_depth = 7;
    d.coat.n_samples = 3;
    auto cd = std::get<CoatedDiffuseLobe>(d.lobe(textures, ctx));
    EXPECT_EQ(cd.base.reflectance, Color(1.0f, 0.5f, 0.0f));  // clamped to [0, 1]
    EXPECT_EQ(cd.coat.eta, 1.0f);                           // pbrt-v4: an index of 0 means 1
    EXPECT_EQ(cd.coat.distribution.alpha_x, 0.2f);
    EXPECT_EQ(cd.coat.distribution.alpha_y, 0.05f);
    EXPECT_EQ(cd.medium_albedo, Color(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(cd.g, -1.0f);
    EXPECT_EQ(cd.thickness, 0.2f);
    EXPECT_EQ(cd.max_depth, 7);
    EXPECT_EQ(cd.n_samples, 3);
    EXPECT_FALSE(d.is_textured());

    // The conductor's index is relative to the coat's; `reflectance` r gives eta = 1,
    // k = 2 sqrt(r) / sqrt(1 - r), before that division.
    CoatedConductorParams c;
    c.coat.ior = 1.25f;
    c.conductor_eta = ColorParam{Rgb(0.5f, 1.0f, 1.5f)};
    c.conductor_k = ColorParam{Rgb(2.5f, 2.0f, 1.25f)};
    c.conductor_roughness.alpha_u = FloatParam{0.3f};
    c.conductor_roughness.alpha_v = FloatParam{0.3f};
    auto cc = std::get<CoatedConductorLobe>(c.lobe(textures, ctx));
    EXPECT_EQ(cc.base.eta, Color(0.4f, 0.8f, 1.2f));
    EXPECT_EQ(cc.base.k, Color(2.0f, 1.6f, 1.0f));
    EXPECT_EQ(cc.base.distribution.alpha_x, 0.3f);
    c.from_reflectance = true;
    c.reflectance = ColorParam{Rgb(0.64f, 1.0f, 0.0f)};
    auto cr = std::get<CoatedConductorLobe>(c.lobe(textures, ctx));
    EXPECT_EQ(cr.base.eta, Color(0.8f));
    // Red: r = 0.64 gives k = 2 (0.8) / 0.6, at normal incidence reflecting r (before the coat's
    // division). Green: r = 1 is clamped to 0.9999, where k stays finite. Blue: r = 0, k = 0.
    EXPECT_NEAR(cr.base.k[0], 2.0f * 0.8f / 0.6f / 1.25f, 1e-5f);
    EXPECT_NEAR(fresnel_complex(1.0f, 1.0f, 2.0f * 0.8f / 0.6f), 0.64f, 1e-5f);
    EXPECT_NEAR(cr.base.k[1], 2.0 * std::sqrt(0.9999) / std::sqrt(0.0001) / 1.25, 0.2);  // 1 - r rounds in float
    EXPECT_EQ(cr.base.k[2], 0.0f);
}

}  // namespace
}  // namespace candela::test
