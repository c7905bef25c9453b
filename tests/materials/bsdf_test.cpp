// Bsdf, the sum of lobes: f adds over the lobes, the pdf averages over them (delta lobes count
// with density 0), sampling picks a lobe uniformly; and the materials built from the scene
// file's types.
#include <gtest/gtest.h>

#include <array>
#include <type_traits>

#include "candela/materials/material.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;

Bsdf bsdf_of(std::initializer_list<BsdfLobe> lobes) {
    Bsdf b;
    for (const BsdfLobe& lobe : lobes) b.lobes[b.lobe_count++] = lobe;
    return b;
}

TEST(Bsdf, EmptyIsBlackAndSamplesNothing) {
    Bsdf b;
    Vec3f wo = direction(0.5f, 0.0f), wi = direction(0.7f, 2.0f);
    EXPECT_EQ(b.eval(wo, wi, kRadiance), Color(0.0f));
    EXPECT_EQ(b.pdf(wo, wi), 0.0f);
    EXPECT_FALSE(b.sample(wo, 0.5f, Vec2f(0.5f, 0.5f), kRadiance));
    EXPECT_EQ(b.albedo(), Color(0.0f));
}

TEST(Bsdf, TwoLobesSumTheirValuesAndAverageTheirPdfs) {
    // Two Lambertian lobes: the values add (not divided by the lobe count), and the average of
    // two equal cosine densities is the cosine density.
    Bsdf b = bsdf_of({LambertianLobe{Color(0.2f)}, LambertianLobe{Color(0.3f, 0.4f, 0.5f)}});
    Vec3f wo = direction(0.5f, 0.0f), wi = direction(0.8f, 2.0f);
    Color expected_f = Color(0.5f, 0.6f, 0.7f) * kInvPi;
    Color f = b.eval(wo, wi, kRadiance);
    EXPECT_FLOAT_EQ(f[0], expected_f[0]);
    EXPECT_FLOAT_EQ(f[1], expected_f[1]);
    EXPECT_FLOAT_EQ(f[2], expected_f[2]);
    EXPECT_FLOAT_EQ(b.pdf(wo, wi), 0.8f * kInvPi);
    EXPECT_EQ(b.albedo(), Color(0.5f, 0.6f, 0.7f));
    // Either lobe's sample carries the whole sum.
    for (float uc : {0.1f, 0.9f}) {
        auto s = b.sample(wo, uc, Vec2f(0.3f, 0.6f), kRadiance);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->f, b.eval(wo, s->wi, kRadiance));
        EXPECT_EQ(s->pdf, b.pdf(wo, s->wi));
    }
}

TEST(Bsdf, DeltaLobesAddNoDensityButHalveTheChoice) {
    // Diffuse + mirror: the pdf is half the cosine density; a mirror sample keeps the mirror's
    // f with probability 1/2, so its weight doubles (and averages out over the lobe choice).
    Bsdf b = bsdf_of({LambertianLobe{Color(0.5f)}, SpecularReflectionLobe{Color(0.5f)}});
    Vec3f wo = direction(0.6f, 1.0f), wi = direction(0.3f, -2.0f);
    EXPECT_FLOAT_EQ(b.pdf(wo, wi), 0.5f * 0.3f * kInvPi);
    EXPECT_EQ(b.eval(wo, wi, kRadiance), Color(0.5f * kInvPi));
    EXPECT_FALSE(b.is_delta_only());

    auto diffuse = b.sample(wo, 0.25f, Vec2f(0.3f, 0.6f), kRadiance);
    ASSERT_TRUE(diffuse);
    EXPECT_FALSE(diffuse->is_delta);
    EXPECT_EQ(diffuse->f, b.eval(wo, diffuse->wi, kRadiance));
    EXPECT_EQ(diffuse->pdf, b.pdf(wo, diffuse->wi));

    auto mirror = b.sample(wo, 0.75f, Vec2f(0.3f, 0.6f), kRadiance);
    ASSERT_TRUE(mirror);
    EXPECT_TRUE(mirror->is_delta);
    EXPECT_EQ(mirror->wi, Vec3f(-wo.x, -wo.y, wo.z));
    EXPECT_EQ(mirror->pdf, 0.5f);
    EXPECT_FLOAT_EQ(mirror->f[0], 0.5f / wo.z);
    // Both strategies weigh 1 here: 0.5 diffuse + 0.5 mirror is a white furnace.
    for (const auto& s : {*diffuse, *mirror})
        EXPECT_NEAR(s.f[0] * std::abs(s.wi.z) / s.pdf, 1.0f, 1e-6f);
}

TEST(Bsdf, LobeChoiceIsRemappedForTheLobesOwnChoice) {
    // uc in [0.5, 1) picks the dielectric, then is stretched back to [0, 1): the glass reflects
    // when the stretched value is below F (0.04 at normal incidence) and refracts above.
    Bsdf b = bsdf_of({LambertianLobe{Color(0.5f)}, FresnelSpecularLobe{Color(1.0f), 1.5f, false}});
    Vec3f wo(0, 0, 1);
    auto reflected = b.sample(wo, 0.5f + 0.5f * 0.03f, Vec2f(), kRadiance);
    ASSERT_TRUE(reflected);
    EXPECT_FALSE(reflected->is_transmission);
    EXPECT_NEAR(reflected->pdf, 0.5f * 0.04f, 1e-6f);
    auto refracted = b.sample(wo, 0.5f + 0.5f * 0.05f, Vec2f(), kRadiance);
    ASSERT_TRUE(refracted);
    EXPECT_TRUE(refracted->is_transmission);
    EXPECT_NEAR(refracted->pdf, 0.5f * 0.96f, 1e-6f);
    // The largest uc still picks the last lobe.
    auto last = b.sample(wo, kOneMinusEpsilon, Vec2f(), kRadiance);
    ASSERT_TRUE(last);
    EXPECT_TRUE(last->is_delta);
}

TEST(Bsdf, SampleAgreesWithEvalAndPdfForEveryPairOfLobes) {
    Rng rng(11, 2);
    for (const LobeCase& a : kLobeCases) {
        for (const LobeCase& b : kLobeCases) {
            Bsdf bsdf = bsdf_of({a.lobe, b.lobe});
            for (const Vec3f& wo : probe_directions()) {
                for (int i = 0; i < 16; ++i) {
                    auto s = bsdf.sample(wo, rng.next_float(), rng.next_vec2f(), kRadiance);
                    if (!s) continue;
                    SCOPED_TRACE(testing::Message()
                                 << a.name << " + " << b.name << ", wo.z " << wo.z);
                    if (s->is_delta) {
                        // A discrete probability, of which the lobe choice took half.
                        EXPECT_LE(s->pdf, 0.5f);
                    } else if (bsdf.has_estimated_lobe()) {
                        // The chosen lobe's own weight (an estimate: its expectation is checked
                        // in layered_stat_test.cpp), with the mixture's pdf for MIS.
                        EXPECT_EQ(s->pdf, bsdf.pdf(wo, s->wi));
                        EXPECT_TRUE(s->f.is_finite());
                    } else {
                        EXPECT_EQ(s->f, bsdf.eval(wo, s->wi, kRadiance));
                        EXPECT_EQ(s->pdf, bsdf.pdf(wo, s->wi));
                    }
                }
            }
        }
    }
}

TEST(Bsdf, IsDeltaOnlyWhenEveryLobeIs) {
    EXPECT_TRUE(bsdf_of({SpecularReflectionLobe{}, FresnelSpecularLobe{}}).is_delta_only());
    EXPECT_TRUE(bsdf_of({SpecularTransmissionLobe{}}).is_delta_only());
    EXPECT_FALSE(bsdf_of({SpecularReflectionLobe{}, LambertianLobe{}}).is_delta_only());
    EXPECT_FALSE(bsdf_of({LambertianLobe{}}).is_delta_only());
}

// The integrators skip the lobe-choice random number when uses_choice() is false, so a lobe that
// says it does not read uc must sample the same direction for any uc; and one that says it does
// must be seen to (for some wo, two values of uc give different samples).
TEST(Bsdf, UsesChoiceOnlyWhenALobeReadsIt) {
    Rng rng(5, 9);
    for (const LobeCase& c : kLobeCases) {
        const bool uses = visit([](const auto& lobe) { return bool(std::decay_t<decltype(lobe)>::kUsesChoice); }, c.lobe);
        EXPECT_EQ(bsdf_of({c.lobe}).uses_choice(), uses) << c.name;
        bool differed = false;
        for (const Vec3f& wo : probe_directions()) {
            for (int k = 0; k < 64; ++k) {
                Vec2f u(rng.next_float(), rng.next_float());
                auto a = visit([&](const auto& lobe) { return lobe.sample(wo, 0.02f, u, kRadiance); }, c.lobe);
                auto b = visit([&](const auto& lobe) { return lobe.sample(wo, 0.98f, u, kRadiance); }, c.lobe);
                const bool same = a.has_value() == b.has_value() && (!a || (a->wi == b->wi && a->f == b->f && a->pdf == b->pdf));
                if (!uses) {
                    ASSERT_TRUE(same) << c.name << ": sample() depends on uc";
                }
                differed = differed || !same;
            }
        }
        if (uses) {
            EXPECT_TRUE(differed) << c.name << ": kUsesChoice, but uc never changed a sample";
        }
    }
    // Several lobes: uc picks one of them.
    EXPECT_TRUE(bsdf_of({LambertianLobe{}, LambertianLobe{}}).uses_choice());
    EXPECT_TRUE(bsdf_of({LambertianLobe{}, SpecularReflectionLobe{}}).uses_choice());
    EXPECT_FALSE(Bsdf{}.uses_choice());
}

// ---- materials

TEST(Material, ConstructorsMakeOneLobeOfTheirKind) {
    Material d = make_diffuse(Rgb(0.1f, 0.2f, 0.3f));
    ASSERT_EQ(d.bsdf.lobe_count, 1u);
    EXPECT_EQ(std::get<LambertianLobe>(d.bsdf.lobes[0]).reflectance, Color(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(material_albedo(d), Color(0.1f, 0.2f, 0.3f));

    Material m = make_mirror(Rgb(0.9f));
    EXPECT_EQ(std::get<SpecularReflectionLobe>(m.bsdf.lobes[0]).reflectance, Color(0.9f));

    Material g = make_dielectric(1.33f, Rgb(0.5f), true);
    const auto& glass = std::get<FresnelSpecularLobe>(g.bsdf.lobes[0]);
    EXPECT_EQ(glass.eta, 1.33f);
    EXPECT_EQ(glass.tint, Color(0.5f));
    EXPECT_TRUE(glass.schlick);
    EXPECT_EQ(material_albedo(g), Color(0.5f));

    Material t = make_transmission(2.4f, Rgb(0.7f));
    const auto& transmission = std::get<SpecularTransmissionLobe>(t.bsdf.lobes[0]);
    EXPECT_EQ(transmission.eta, 2.4f);
    EXPECT_EQ(transmission.tint, Color(0.7f));
}

TEST(Material, MixConcatenatesLobesAndSumsAlbedos) {
    std::array<Material, 3> parts = {make_diffuse(Rgb(0.25f)), make_mirror(Rgb(0.5f)),
                                     make_dielectric(1.5f)};
    Material mix = make_mix(parts);
    ASSERT_EQ(mix.bsdf.lobe_count, 3u);
    EXPECT_TRUE(std::holds_alternative<LambertianLobe>(mix.bsdf.lobes[0]));
    EXPECT_TRUE(std::holds_alternative<SpecularReflectionLobe>(mix.bsdf.lobes[1]));
    EXPECT_TRUE(std::holds_alternative<FresnelSpecularLobe>(mix.bsdf.lobes[2]));
    EXPECT_EQ(material_albedo(mix), Color(1.75f));
}

}  // namespace
}  // namespace candela::test
