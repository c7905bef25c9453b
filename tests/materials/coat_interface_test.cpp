// CoatInterface: unrestricted, it is DielectricLobe without tint; restricted to reflection or
// transmission, it keeps f and divides the density by the probability of the restricted choice
// (pbrt-v4's BxDFReflTransFlags). Chi-square fits of its restricted sampling are in
// layered_stat_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/materials/coat_interface.h"
#include "candela/sampling/rng.h"
#include "materials/lobe_cases.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr TransportMode kRadiance = TransportMode::kRadiance;

const CoatInterface kCoats[] = {{1.5f, TrowbridgeReitz(0.0f)}, {1.5f, TrowbridgeReitz(0.3f)},
                                {1.33f, TrowbridgeReitz(0.05f, 0.4f)}, {1.0f / 1.5f, TrowbridgeReitz(0.2f)}};

// The Fresnel reflectance at the microfacet between wo and wi (generalized half vector), the
// probability with which the unrestricted interface reflects there; for a refraction from the
// cosine on the optically thinner side, which is accurate near the critical angle.
float fresnel_between(const CoatInterface& coat, Vec3f wo, Vec3f wi) {
    bool reflection = wo.z * wi.z > 0.0f;
    float eta_rel = reflection ? 1.0f : (wo.z > 0.0f ? coat.eta : 1.0f / coat.eta);
    Vec3f wm = normalize(wo + wi * eta_rel);
    if (wm.z < 0.0f) wm = -wm;
    bool wo_rarer = reflection || (wo.z > 0.0f) == (coat.eta > 1.0f);
    return fresnel_dielectric(dot(wo_rarer ? wo : wi, wm), coat.eta);
}

TEST(CoatInterface, UnrestrictedIsTheDielectricLobe) {
    Rng rng(11, 2);
    for (const CoatInterface& coat : kCoats) {
        DielectricLobe glass{Color(1.0f), coat.eta, coat.distribution};
        EXPECT_EQ(coat.is_specular(), glass.is_delta());
        for (const Vec3f& wo : probe_directions()) {
            for (int i = 0; i < 200; ++i) {
                float uc = rng.next_float();
                Vec2f u = rng.next_vec2f();
                auto a = coat.sample(wo, uc, u, kRadiance);
                auto b = glass.sample(wo, uc, u, kRadiance);
                ASSERT_EQ(a.has_value(), b.has_value()) << "eta " << coat.eta << ", wo.z " << wo.z;
                if (!a) continue;
                EXPECT_EQ(a->wi, b->wi);
                EXPECT_EQ(a->is_delta, b->is_delta);
                EXPECT_EQ(a->is_transmission, b->is_transmission);
                // The same microfacet, from u: the coat's density uses it as drawn, the lobe's
                // recomputes it from wo and wi, which costs a few float roundings.
                EXPECT_NEAR(a->pdf, b->pdf, 1e-4f * b->pdf);
                EXPECT_NEAR(a->f.max_component(), b->f.max_component(), 1e-4f * b->f.max_component());
                if (!a->is_delta) {
                    EXPECT_EQ(coat.f(wo, a->wi, kRadiance), glass.eval(wo, a->wi, kRadiance));
                    EXPECT_NEAR(coat.pdf(wo, a->wi), glass.pdf(wo, a->wi), 1e-6f * b->pdf);
                }
            }
        }
    }
}

TEST(CoatInterface, RestrictionDividesTheDensityByTheChoice) {
    Rng rng(12, 3);
    for (const CoatInterface& coat : kCoats) {
        if (coat.is_specular()) continue;
        for (const Vec3f& wo : probe_directions()) {
            for (int i = 0; i < 100; ++i) {
                Vec3f wi = sample_uniform_sphere(rng.next_vec2f());
                float all = coat.pdf(wo, wi);
                if (!(all > 0.0f)) continue;
                float f = fresnel_between(coat, wo, wi);
                bool reflection = wo.z * wi.z > 0.0f;
                float chosen = reflection ? f : 1.0f - f;
                SCOPED_TRACE(testing::Message() << "eta " << coat.eta << ", wo.z " << wo.z << ", wi.z " << wi.z);
                ReflTrans same = reflection ? ReflTrans::kReflection : ReflTrans::kTransmission;
                ReflTrans other = reflection ? ReflTrans::kTransmission : ReflTrans::kReflection;
                EXPECT_NEAR(coat.pdf(wo, wi, same) * chosen, all, 1e-4f * all);
                EXPECT_EQ(coat.pdf(wo, wi, other), 0.0f);
            }
        }
    }
}

TEST(CoatInterface, RestrictedSamplesStayOnTheirSide) {
    Rng rng(13, 4);
    for (const CoatInterface& coat : kCoats) {
        for (const Vec3f& wo : probe_directions()) {
            for (int i = 0; i < 100; ++i) {
                float uc = rng.next_float();
                Vec2f u = rng.next_vec2f();
                SCOPED_TRACE(testing::Message() << "eta " << coat.eta << ", wo.z " << wo.z);
                if (auto t = coat.sample(wo, uc, u, kRadiance, ReflTrans::kTransmission)) {
                    EXPECT_TRUE(t->is_transmission);
                    EXPECT_LT(t->wi.z * wo.z, 0.0f);
                    if (t->is_delta) {
                        EXPECT_EQ(t->pdf, 1.0f);
                    } else {
                        EXPECT_NEAR(t->pdf, coat.pdf(wo, t->wi, ReflTrans::kTransmission), 1e-4f * t->pdf);
                    }
                } else if (coat.is_specular()) {
                    // A smooth coat refuses to transmit only under total internal reflection.
                    EXPECT_EQ(fresnel_dielectric(wo.z, coat.eta), 1.0f);
                }
                if (auto r = coat.sample(wo, uc, u, kRadiance, ReflTrans::kReflection)) {
                    EXPECT_FALSE(r->is_transmission);
                    EXPECT_GT(r->wi.z * wo.z, 0.0f);
                    if (r->is_delta) {
                        EXPECT_EQ(r->pdf, 1.0f);
                        EXPECT_NEAR(r->f.max_component() * std::abs(r->wi.z), fresnel_dielectric(wo.z, coat.eta), 1e-6f);
                    } else {
                        EXPECT_NEAR(r->pdf, coat.pdf(wo, r->wi, ReflTrans::kReflection), 1e-4f * r->pdf);
                    }
                }
            }
        }
    }
}

TEST(CoatInterface, SmoothTransmissionWeightIsOneMinusFresnel) {
    // Restricted to transmission, a smooth coat refracts with probability 1: the weight is
    // 1 - F (times 1 / eta'^2 for radiance), the whole transmitted share.
    CoatInterface coat{1.5f, TrowbridgeReitz(0.0f)};
    for (float c : {1.0f, 0.7f, 0.2f, -0.9f, -0.8f}) {
        Vec3f wo = direction(c, 0.3f);
        auto s = coat.sample(wo, 0.0f, Vec2f(0.5f, 0.5f), TransportMode::kImportance, ReflTrans::kTransmission);
        ASSERT_TRUE(s) << c;
        EXPECT_NEAR(s->f.max_component() * std::abs(s->wi.z), 1.0f - fresnel_dielectric(c, 1.5f), 1e-6f);
    }
    // Beyond the critical angle from inside there is nothing to transmit.
    EXPECT_FALSE(coat.sample(direction(-0.5f, 0.3f), 0.9f, Vec2f(), kRadiance, ReflTrans::kTransmission));
}

}  // namespace
}  // namespace candela::test
