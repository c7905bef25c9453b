// The BVH light sampler (light_bvh.h, LightSelection::kBvh): its probabilities sum, at any
// point, to the probability that sample() picks a light (1 but where a subtree whose bounds reach
// the point has two children that do not: pbrt-v4's sampler then picks nothing, and so do we), sample() returns the pdf that pdf() gives, and a light that cannot reach a point (behind
// a one-sided emitter, outside a spot's cone) has probability 0 there and is never picked.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "lights/light_bvh_scene.h"
#include "support/printers.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

Vec3f random_point(Rng& rng, float half) {
    return Vec3f(rng.next_float(), rng.next_float(), rng.next_float()) * (2.0f * half) - Vec3f(half, half, half);
}

// The fraction of choice numbers on a grid of kChoices for which `picks(uc)` finds a light: each
// light owns one interval of uc, and so does each dead end of the tree, so the fraction is the
// probability of picking a light to within (lights + dead ends + 1) / kChoices.
constexpr int kChoices = 200000;
template <class Picks>
double picked_fraction(Picks&& picks) {
    int picked = 0;
    for (int i = 0; i < kChoices; ++i) picked += picks((float(i) + 0.5f) / float(kChoices)) ? 1 : 0;
    return picked / double(kChoices);
}

// The sum over every light of the probability of choosing it at (p, n).
double total_probability(const LightSet& lights, const Vec3f& p, const Vec3f& n) {
    double sum = static_cast<double>(lights.environment_selection_probability());
    for (uint32_t id = 0; id < AllKindsOfLights::kShapes; ++id)
        sum += static_cast<double>(lights.selection_probability(p, n, id));
    for (uint32_t i = 0; i < AllKindsOfLights::kDeltas; ++i)
        sum += static_cast<double>(lights.delta_selection_probability(p, n, i));
    return sum;
}

TEST(LightBvh, ProbabilitiesSumToOneAtSurfaceAndMediumPoints) {
    const AllKindsOfLights all;
    const LightSet lights = all.light_set(LightSelection::kBvh);
    ASSERT_EQ(lights.size(), 8u);
    Rng rng = Rng::for_sample(1, 0, 0);
    int below_one = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3f p = random_point(rng, 6.0f);
        const Vec3f n = i % 2 ? random_unit(rng) : Vec3f{};  // a surface point, or one in a medium
        const double sum = total_probability(lights, p, n);
        EXPECT_LE(sum, 1.0 + 1e-5);
        if (sum < 1.0 - 1e-5) ++below_one;
    }
    // Seven bounded lights spread apart: dead ends are rare.
    EXPECT_LT(below_one, 100);
}

TEST(LightBvh, ProbabilitiesOfRandomBoundsSumToTheProbabilityOfPickingALight) {
    std::vector<uint32_t> infinite = {64, 65};
    const LightBvh bvh(random_light_bounds(64, 7), infinite, 66);
    EXPECT_FLOAT_EQ(bvh.infinite_pmf(), 1.0f / 3.0f);  // pbrt-v4's share: 2 / (2 + 1), uniformly
    Rng rng = Rng::for_sample(2, 0, 0);
    for (int i = 0; i < 16; ++i) {
        const Vec3f p = random_point(rng, 6.0f);
        const Vec3f n = i % 2 ? random_unit(rng) : Vec3f{};
        double sum = 0.0;
        for (uint32_t l = 0; l < 66; ++l) sum += static_cast<double>(bvh.pmf(p, n, l));
        const double picked = picked_fraction([&](float uc) { return bvh.sample(p, n, uc).has_value(); });
        EXPECT_NEAR(sum, picked, 200.0 / kChoices) << testing::PrintToString(p) << " " << testing::PrintToString(n);
    }
}

TEST(LightBvh, SampleReturnsThePdfThatPdfGives) {
    const AllKindsOfLights all;
    const LightSet lights = all.light_set(LightSelection::kBvh);
    Rng rng = Rng::for_sample(3, 0, 0);
    int area_samples = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3f p = random_point(rng, 2.5f);
        const Vec3f n = i % 2 ? random_unit(rng) : Vec3f{};
        const float uc = rng.next_float();
        std::optional<LightSample> s = lights.sample(p, n, uc, rng.next_vec2f());
        if (!s) continue;
        if (s->is_delta && s->infinite) {
            EXPECT_EQ(s->pdf, lights.delta_selection_probability(p, n, 2));
        } else if (s->is_delta) {
            EXPECT_EQ(s->pdf, lights.delta_selection_probability(p, n, s->p.x < -2.0f ? 0 : 1));
        } else if (s->infinite) {
            EXPECT_EQ(s->pdf, lights.environment_pdf(s->wi));
        } else {
            // The shape the point lies on: the quads' and the disk's planes, else the sphere.
            const uint32_t id = s->p.z == -2.0f ? 0 : s->p.x == 3.0f ? 1 : std::abs(s->p.z - 4.0f) < 1e-5f ? 3 : 2;
            EXPECT_EQ(s->pdf, lights.pdf(p, n, id, s->p, s->n)) << "shape " << id;
            ++area_samples;
        }
    }
    EXPECT_GT(area_samples, 500);
}

TEST(LightBvh, NeverPicksALightBehindItsOneSidedEmitterOrOutsideItsSpotCone) {
    const AllKindsOfLights all;
    const LightSet lights = all.light_set(LightSelection::kBvh);
    // Below quad 0 (which faces +z at z = -2) and beside the spot (at (0, -3, 0), pointing +y with
    // a 30 degree cone): neither can light it, with or without a normal.
    const Vec3f p(0.0f, -3.0f, -4.0f);
    for (const Vec3f& n : {Vec3f{}, Vec3f(0.0f, 0.0f, 1.0f), normalize(Vec3f(1.0f, 1.0f, 1.0f))}) {
        EXPECT_EQ(lights.selection_probability(p, n, 0), 0.0f);
        EXPECT_EQ(lights.delta_selection_probability(p, n, 1), 0.0f);
        EXPECT_NEAR(total_probability(lights, p, n), 1.0, 1e-5);
        for (int i = 0; i < 20000; ++i) {
            std::optional<LightSample> s = lights.sample(p, n, (float(i) + 0.5f) / 20000.0f, {0.5f, 0.5f});
            if (!s) continue;
            EXPECT_FALSE(!s->is_delta && !s->infinite && s->p.z == -2.0f) << "the quad behind";
            EXPECT_FALSE(s->is_delta && !s->infinite && s->p.y == -3.0f) << "the spot outside its cone";
        }
    }
    // The control: above the quad and inside the spot's cone both are chosen.
    const Vec3f q(0.0f, 0.0f, -1.0f);
    EXPECT_GT(lights.selection_probability(q, Vec3f{}, 0), 0.0f);
    EXPECT_GT(lights.delta_selection_probability(q, Vec3f{}, 1), 0.0f);
}

TEST(LightBounds, ImportanceIsZeroOnlyWhereTheLightCannotReach) {
    LightBounds patch;  // a one-sided unit patch at the origin facing +z
    patch.bounds.extend(Vec3f(-0.5f, -0.5f, 0.0f));
    patch.bounds.extend(Vec3f(0.5f, 0.5f, 0.0f));
    patch.phi = 1.0f;
    patch.cos_theta_e = 0.0f;
    EXPECT_GT(patch.importance({0.0f, 0.0f, 2.0f}, Vec3f{}), 0.0f);
    EXPECT_GT(patch.importance({3.0f, 0.0f, 0.1f}, Vec3f{}), 0.0f);  // grazing but in front
    EXPECT_EQ(patch.importance({0.0f, 0.0f, -2.0f}, Vec3f{}), 0.0f);
    EXPECT_EQ(patch.importance({3.0f, 0.0f, -1.0f}, Vec3f{}), 0.0f);
    patch.two_sided = true;
    EXPECT_GT(patch.importance({0.0f, 0.0f, -2.0f}, Vec3f{}), 0.0f);
}

TEST(LightBvh, PowerAndUniformSelectionStayTheSameEverywhere) {
    const AllKindsOfLights all;
    for (LightSelection selection : {LightSelection::kPower, LightSelection::kUniform}) {
        const LightSet lights = all.light_set(selection);
        for (uint32_t id = 0; id < AllKindsOfLights::kShapes; ++id)
            EXPECT_EQ(lights.selection_probability({0.0f, 0.0f, -1.0f}, Vec3f(0.0f, 0.0f, 1.0f), id),
                      lights.selection_probability(id));
    }
}

}  // namespace
}  // namespace candela::test
