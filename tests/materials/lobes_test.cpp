// Every BSDF lobe: sample() agrees with eval() and pdf(), delta lobes have no density, the sample
// weights f |cos| / pdf conserve energy, and the transport mode scales refraction only. Then each
// lobe against its closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <type_traits>

#include "candela/materials/bsdf_lobes.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;
constexpr TransportMode kImportance = TransportMode::kImportance;

// f |cos wi| / pdf: what a sample multiplies the path throughput by.
Color weight(const BsdfSample& s) { return s.f * (std::abs(s.wi.z) / s.pdf); }

void expect_rgb_near(const Color& a, const Color& b, float tol) {
    EXPECT_NEAR(a[0], b[0], tol);
    EXPECT_NEAR(a[1], b[1], tol);
    EXPECT_NEAR(a[2], b[2], tol);
}

// Calls check(case, wo, uc, u) for every lobe case, probe direction and 64 random (uc, u).
template <class F>
void for_each_lobe_sample(F check) {
    for (const LobeCase& c : kLobeCases) {
        Rng rng(7, 1);
        for (const Vec3f& wo : probe_directions()) {
            for (int i = 0; i < 64; ++i) {
                float uc = rng.next_float();
                Vec2f u = rng.next_vec2f();
                SCOPED_TRACE(testing::Message() << c.name << ", wo = (" << wo.x << ", " << wo.y
                                                << ", " << wo.z << "), uc = " << uc);
                check(c, wo, uc, u);
            }
        }
    }
}

TEST(BsdfLobes, EveryAlternativeHasACase) {
    std::set<size_t> covered;
    for (const LobeCase& c : kLobeCases) covered.insert(c.lobe.index());
    EXPECT_EQ(covered.size(), std::variant_size_v<BsdfLobe>);
}

TEST(BsdfLobes, SampleAgreesWithEvalAndPdf) {
    for_each_lobe_sample([](const LobeCase& c, Vec3f wo, float uc, Vec2f u) {
        visit([&](const auto& lobe) {
            auto s = lobe.sample(wo, uc, u, kRadiance);
            if (!s) return;
            EXPECT_NEAR(length(s->wi), 1.0f, 1e-5f);
            EXPECT_GT(s->pdf, 0.0f);
            if constexpr (kIsLayered<std::decay_t<decltype(lobe)>>) {
                // A coated lobe reflects only. Its value is an estimate, so sample() matches
                // eval() in expectation (layered_stat_test.cpp); its density is pdf() exactly,
                // for MIS, except for delta samples (the smooth coat's mirror reflection, or
                // the walks of a lobe with only specular events).
                EXPECT_FALSE(s->is_transmission);
                EXPECT_GT(s->wi.z * wo.z, 0.0f);
                EXPECT_EQ(s->eta, 1.0f);
                if (lobe.is_delta()) {
                    EXPECT_TRUE(s->is_delta);
                }
                if (!s->is_delta) {
                    EXPECT_EQ(s->pdf, lobe.pdf(wo, s->wi));
                }
                return;
            }
            EXPECT_EQ(s->is_delta, lobe.is_delta());
            EXPECT_EQ(s->is_transmission, s->wi.z * wo.z < 0.0f);
            if (!s->is_transmission) {
                EXPECT_EQ(s->eta, 1.0f);
            }
            if (s->is_delta) {
                // The density and value of a delta lobe live in sample() only.
                EXPECT_EQ(lobe.eval(wo, s->wi, kRadiance), Color(0.0f));
                EXPECT_EQ(lobe.pdf(wo, s->wi), 0.0f);
            } else {
                EXPECT_EQ(s->f, lobe.eval(wo, s->wi, kRadiance));
                EXPECT_EQ(s->pdf, lobe.pdf(wo, s->wi));
            }
        }, c.lobe);
    });
}

TEST(BsdfLobes, SampleWeightNeverExceedsAlbedo) {
    // In importance mode (no eta^2 factor) nothing may scatter more than its albedo or tint;
    // a conductor's albedo is its colour at normal incidence, and its Fresnel reflectance rises
    // from there to 1 at grazing, so 1 bounds it.
    for_each_lobe_sample([](const LobeCase& c, Vec3f wo, float uc, Vec2f u) {
        visit([&](const auto& lobe) {
            auto s = lobe.sample(wo, uc, u, kImportance);
            if (!s) return;
            Color w = weight(*s), a = lobe.albedo();
            if (holds_alternative<ConductorLobe>(c.lobe)) a = Color(1.0f);
            // A coated lobe's walk multiplies weights of at most 1 (Fresnel, masking, base and
            // medium albedo, transmittance); its roulette raises the weight to at most 1.
            if (kIsLayered<std::decay_t<decltype(lobe)>>) a = Color(1.0f);
            // Hair's weight sum_p Ap Mp Np / sum_p pdf(p) Mp Np is at most the largest
            // Ap / pdf(p) of a channel, with pdf(p) Ap's channel average over their sum; a
            // channel that absorbs less than the average may exceed 1 (as in pbrt-v4).
            if constexpr (std::is_same_v<std::decay_t<decltype(lobe)>, HairLobe>) {
                const HairLobe::Outgoing o = lobe.outgoing(wo);
                a = Color(0.0f);
                for (int p = 0; p <= kHairPMax; ++p)
                    if (o.ap_pdf[p] > 0.0f)
                        for (int k = 0; k < 4; ++k) a.set(k, std::max(a[k], o.ap[p][k] / o.ap_pdf[p]));
            } else {
                EXPECT_LE(a.max_component(), 1.0f);
            }
            EXPECT_LE(w[0], a[0] * (1.0f + 1e-5f));
            EXPECT_LE(w[1], a[1] * (1.0f + 1e-5f));
            EXPECT_LE(w[2], a[2] * (1.0f + 1e-5f));
        }, c.lobe);
    });
}

TEST(BsdfLobes, RadianceModeDividesTransmissionByEtaSquared) {
    for_each_lobe_sample([](const LobeCase& c, Vec3f wo, float uc, Vec2f u) {
        visit([&](const auto& lobe) {
            auto radiance = lobe.sample(wo, uc, u, kRadiance);
            auto importance = lobe.sample(wo, uc, u, kImportance);
            if constexpr (kIsLayered<std::decay_t<decltype(lobe)>>) {
                // Reflection at the coat (the walk's first step, the coat's own sample) does not
                // depend on the mode. A walk into the layers does in its roulette, which looks
                // at the weight that the mode changes inside the coat, so the two walks part;
                // their expectations agree (layered_stat_test.cpp).
                Vec3f wo_up = wo.z < 0.0f ? -wo : wo;
                auto at_coat = lobe.coat.sample(wo_up, uc, u, kRadiance);
                if (!at_coat || at_coat->is_transmission) return;
                ASSERT_TRUE(radiance && importance);
                EXPECT_EQ(radiance->wi, importance->wi);
                EXPECT_EQ(radiance->wi, wo.z < 0.0f ? -at_coat->wi : at_coat->wi);
                EXPECT_EQ(radiance->pdf, importance->pdf);
                EXPECT_EQ(radiance->f, importance->f);
                return;
            }
            ASSERT_EQ(radiance.has_value(), importance.has_value());
            if (!radiance) return;
            EXPECT_EQ(radiance->wi, importance->wi);
            EXPECT_EQ(radiance->pdf, importance->pdf);
            float scale = radiance->is_transmission ? 1.0f / (radiance->eta * radiance->eta) : 1.0f;
            float tol = 1e-5f * importance->f.max_component();
            expect_rgb_near(radiance->f, importance->f * scale, tol);
        }, c.lobe);
    });
}

TEST(BsdfLobes, NothingScattersFromTheSurfacePlane) {
    for (const LobeCase& c : kLobeCases) {
        visit([&](const auto& lobe) {
            // A fibre scatters over the whole sphere: the surface's plane is not special there.
            if constexpr (std::is_same_v<std::decay_t<decltype(lobe)>, HairLobe>) return;
            EXPECT_FALSE(lobe.sample(Vec3f(1, 0, 0), 0.3f, Vec2f(0.4f, 0.6f), kRadiance)) << c.name;
        }, c.lobe);
    }
}

// ---- Lambertian

TEST(LambertianLobe, EvalAndPdfAreCosineLawInWosHemisphere) {
    LambertianLobe lobe{Color(0.6f, 0.3f, 0.9f)};
    for (float sign : {1.0f, -1.0f}) {
        Vec3f wo = direction(sign * 0.7f, 1.0f);
        Vec3f same = direction(sign * 0.4f, 2.5f), other = direction(-sign * 0.4f, 2.5f);
        EXPECT_EQ(lobe.eval(wo, same, kRadiance), Color(0.6f, 0.3f, 0.9f) * kInvPi);
        EXPECT_EQ(lobe.eval(wo, other, kRadiance), Color(0.0f));
        EXPECT_FLOAT_EQ(lobe.pdf(wo, same), 0.4f * kInvPi);
        EXPECT_EQ(lobe.pdf(wo, other), 0.0f);
    }
    EXPECT_EQ(lobe.albedo(), Color(0.6f, 0.3f, 0.9f));
    EXPECT_FALSE(lobe.is_delta());
}

TEST(LambertianLobe, SamplesLandOnWosSideWithWeightAlbedo) {
    // Cosine sampling cancels f |cos| / pdf to the albedo exactly (Nori's diffuse.cpp): the
    // directional albedo estimator has no variance, so each sample must give it.
    LambertianLobe lobe{Color(0.8f, 0.5f, 0.2f)};
    Rng rng(3, 4);
    for (const Vec3f& wo : probe_directions()) {
        for (int i = 0; i < 1000; ++i) {
            auto s = lobe.sample(wo, rng.next_float(), rng.next_vec2f(), kRadiance);
            ASSERT_TRUE(s);
            EXPECT_GT(s->wi.z * wo.z, 0.0f);
            expect_rgb_near(weight(*s), lobe.albedo(), 1e-5f);
        }
    }
}

// ---- diffuse transmission

TEST(DiffuseTransmissionLobe, EvalIsReflectanceOnWosSideAndTransmittanceOnTheOther) {
    const DiffuseTransmissionLobe lobe{Color(0.6f, 0.3f, 0.9f), Color(0.2f, 0.1f, 0.3f)};
    // Sides in proportion to max R = 0.9 and max T = 0.3: reflection 3/4, transmission 1/4.
    for (float sign : {1.0f, -1.0f}) {
        Vec3f wo = direction(sign * 0.7f, 1.0f);
        Vec3f same = direction(sign * 0.4f, 2.5f), other = direction(-sign * 0.4f, 2.5f);
        EXPECT_EQ(lobe.eval(wo, same, kRadiance), Color(0.6f, 0.3f, 0.9f) * kInvPi);
        EXPECT_EQ(lobe.eval(wo, other, kRadiance), Color(0.2f, 0.1f, 0.3f) * kInvPi);
        EXPECT_FLOAT_EQ(lobe.pdf(wo, same), 0.75f * 0.4f * kInvPi);
        EXPECT_FLOAT_EQ(lobe.pdf(wo, other), 0.25f * 0.4f * kInvPi);
    }
    EXPECT_EQ(lobe.albedo(), Color(0.8f, 0.4f, 1.2f));
    EXPECT_FALSE(lobe.is_delta());
}

TEST(DiffuseTransmissionLobe, ChoosesTheSideByUcAndWeighsItExactly) {
    // uc below the reflection probability reflects, above it transmits; the weight f |cos| / pdf
    // is then R / P(reflect) or T / P(transmit), with no other variance.
    const DiffuseTransmissionLobe lobe{Color(0.5f), Color(0.5f)};  // R + T = 1: weight 1 always
    Rng rng(5, 6);
    int transmitted = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const Vec3f wo = direction(i % 2 ? 0.6f : -0.6f, 0.2f);
        const float uc = rng.next_float();
        auto s = lobe.sample(wo, uc, rng.next_vec2f(), kRadiance);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->is_transmission, uc >= 0.5f);
        EXPECT_EQ(s->is_transmission, s->wi.z * wo.z < 0.0f);
        EXPECT_EQ(s->eta, 1.0f);
        expect_rgb_near(weight(*s), Color(1.0f), 1e-5f);
        transmitted += s->is_transmission;
    }
    // Half transmit: within 5 binomial standard deviations (sqrt(n / 4) = 71).
    EXPECT_NEAR(transmitted, n / 2, 5 * 71);
    // Both black: nothing scatters.
    const DiffuseTransmissionLobe black{Color(0.0f), Color(0.0f)};
    EXPECT_FALSE(black.sample(direction(0.5f, 0.0f), 0.3f, Vec2f(0.2f, 0.7f), kRadiance));
    EXPECT_EQ(black.pdf(direction(0.5f, 0.0f), direction(-0.5f, 1.0f)), 0.0f);
}

// ---- mirror

TEST(SpecularReflectionLobe, ReflectsMirrorImageWithWeightAlbedo) {
    SpecularReflectionLobe lobe{Color(0.9f, 0.6f, 0.3f)};
    for (const Vec3f& wo : probe_directions()) {
        auto s = lobe.sample(wo, 0.5f, Vec2f(0.5f, 0.5f), kRadiance);
        ASSERT_TRUE(s);
        EXPECT_EQ(s->wi, Vec3f(-wo.x, -wo.y, wo.z));
        EXPECT_EQ(s->pdf, 1.0f);
        EXPECT_TRUE(s->is_delta);
        expect_rgb_near(weight(*s), lobe.albedo(), 1e-6f);
    }
}

// ---- dielectric

TEST(FresnelSpecularLobe, ReflectionAndRefractionWeightsSumToTintAtEveryAngle) {
    const Color tint(1.0f, 0.9f, 0.8f);
    for (bool schlick : {false, true}) {
        for (float eta : {1.5f, 1.0f / 1.33f}) {
            FresnelSpecularLobe lobe{tint, eta, schlick};
            for (int i = -1000; i <= 1000; ++i) {
                if (i == 0) continue;
                Vec3f wo = direction(static_cast<float>(i) / 1000.0f, 0.1f * static_cast<float>(i));
                SCOPED_TRACE(testing::Message() << "schlick " << schlick << ", eta " << eta
                                                << ", cos " << wo.z);
                float f = lobe.reflectance(wo);
                ASSERT_GE(f, 0.0f);
                ASSERT_LE(f, 1.0f);
                // uc = 0 reflects unless F = 0; uc just below 1 refracts unless F = 1 (TIR).
                auto first = lobe.sample(wo, 0.0f, Vec2f(0.5f, 0.5f), kRadiance);
                auto last = lobe.sample(wo, kOneMinusEpsilon, Vec2f(0.5f, 0.5f), kRadiance);
                ASSERT_TRUE(first && last);
                ASSERT_FALSE(first->is_transmission);
                EXPECT_EQ(first->pdf, f);
                expect_rgb_near(weight(*first), tint, 1e-5f);
                if (f == 1.0f) {  // total internal reflection
                    EXPECT_FALSE(last->is_transmission);
                    EXPECT_EQ(last->pdf, 1.0f);
                    continue;
                }
                ASSERT_TRUE(last->is_transmission);
                EXPECT_FLOAT_EQ(last->pdf, 1.0f - f);
                float eta_rel = wo.z > 0.0f ? eta : 1.0f / eta;
                EXPECT_FLOAT_EQ(last->eta, eta_rel);
                // With the radiance factor 1 / eta'^2 removed, F + (1 - F) = 1: the expected
                // weight is the tint.
                Color transmitted = weight(*last) * (eta_rel * eta_rel);
                expect_rgb_near(transmitted, tint, 1e-4f);
                expect_rgb_near(weight(*first) * first->pdf + transmitted * last->pdf, tint, 1e-4f);
            }
        }
    }
}

TEST(FresnelSpecularLobe, ChoosesReflectionWithProbabilityF) {
    FresnelSpecularLobe lobe{Color(1.0f), 1.5f, false};
    Vec3f wo = direction(0.3f, 0.0f);
    float f = fresnel_dielectric(0.3f, 1.5f);
    EXPECT_EQ(lobe.reflectance(wo), f);
    EXPECT_FALSE(lobe.sample(wo, f * 0.999f, Vec2f(), kRadiance)->is_transmission);
    EXPECT_TRUE(lobe.sample(wo, f * 1.001f, Vec2f(), kRadiance)->is_transmission);
}

TEST(FresnelSpecularLobe, RefractsBySnellsLawWithTheRadianceFactor) {
    // Normal incidence on glass: 4% reflected; the transmitted 96% of radiance is compressed into
    // a solid angle 1.5^2 times smaller on the way in, and expands on the way out.
    FresnelSpecularLobe lobe{Color(1.0f), 1.5f, false};
    auto in = lobe.sample(Vec3f(0, 0, 1), 0.5f, Vec2f(), kRadiance);
    ASSERT_TRUE(in && in->is_transmission);
    EXPECT_NEAR(in->wi.z, -1.0f, 1e-6f);
    expect_rgb_near(weight(*in), Color(1.0f / 2.25f), 1e-6f);
    auto in_importance = lobe.sample(Vec3f(0, 0, 1), 0.5f, Vec2f(), kImportance);
    expect_rgb_near(weight(*in_importance), Color(1.0f), 1e-6f);
    auto out = lobe.sample(Vec3f(0, 0, -1), 0.5f, Vec2f(), kRadiance);
    ASSERT_TRUE(out && out->is_transmission);
    EXPECT_FLOAT_EQ(out->eta, 1.0f / 1.5f);
    expect_rgb_near(weight(*out), Color(2.25f), 1e-5f);
    // Oblique: n_i sin(theta_i) = n_t sin(theta_t).
    Vec3f wo = direction(0.5f, 1.0f);
    auto t = lobe.sample(wo, kOneMinusEpsilon, Vec2f(), kRadiance);
    ASSERT_TRUE(t && t->is_transmission);
    auto sin_theta = [](Vec3f w) { return std::sqrt(w.x * w.x + w.y * w.y); };
    EXPECT_NEAR(sin_theta(wo), 1.5f * sin_theta(t->wi), 1e-5f);
}

TEST(FresnelSpecularLobe, SchlickFollowsSmallpt) {
    // smallpt: R0 = ((nt - nc) / (nt + nc))^2, c = 1 - cos of the angle in air (the incident one
    // entering, the refracted one leaving), Re = R0 + (1 - R0) c^5; total internal reflection
    // reflects everything.
    const double n = 1.5;
    FresnelSpecularLobe lobe{Color(1.0f), 1.5f, true};
    for (int i = -99; i <= 99; ++i) {
        if (i == 0) continue;
        double cos_o = i / 100.0;
        Vec3f wo = direction(static_cast<float>(cos_o), 0.0f);
        double r0 = std::pow((n - 1.0) / (n + 1.0), 2.0);
        double cos_air;
        if (cos_o > 0.0) {
            cos_air = cos_o;
        } else {
            double sin_t = n * std::sqrt(1.0 - cos_o * cos_o);
            if (sin_t >= 1.0) {
                EXPECT_EQ(lobe.reflectance(wo), 1.0f) << "cos " << cos_o;
                continue;
            }
            cos_air = std::sqrt(1.0 - sin_t * sin_t);
        }
        double expected = r0 + (1.0 - r0) * std::pow(1.0 - cos_air, 5.0);
        EXPECT_NEAR(lobe.reflectance(wo), expected, 2e-5) << "cos " << cos_o;
    }
}

// ---- transmission

TEST(SpecularTransmissionLobe, WeightIsOneMinusFresnelAndBlackUnderTotalInternalReflection) {
    const Color tint(0.7f, 0.8f, 0.9f);
    SpecularTransmissionLobe lobe{tint, 1.5f};
    for (int i = -999; i <= 999; ++i) {
        if (i == 0) continue;
        Vec3f wo = direction(static_cast<float>(i) / 1000.0f, 0.5f);
        SCOPED_TRACE(testing::Message() << "cos " << wo.z);
        auto s = lobe.sample(wo, 0.5f, Vec2f(0.5f, 0.5f), kImportance);
        float f = fresnel_dielectric(wo.z, 1.5f);
        if (f == 1.0f) {
            EXPECT_FALSE(s);
            continue;
        }
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->is_transmission);
        EXPECT_EQ(s->pdf, 1.0f);
        Vec3f wt;
        ASSERT_TRUE(refract(wo, Vec3f(0, 0, 1), 1.5f, &wt));
        EXPECT_EQ(s->wi, wt);
        expect_rgb_near(weight(*s), tint * (1.0f - f), 1e-5f);
        auto r = lobe.sample(wo, 0.5f, Vec2f(0.5f, 0.5f), kRadiance);
        expect_rgb_near(weight(*r) * (s->eta * s->eta), tint * (1.0f - f), 1e-5f);
    }
}

}  // namespace
}  // namespace candela::test
