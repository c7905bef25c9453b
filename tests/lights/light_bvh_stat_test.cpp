// Chi-square goodness of fit of LightBvh::sample's choices against LightBvh::pmf at fixed points
// (Pearson's statistic over the lights, cells of expected count < 5 pooled, Sidak-corrected
// alpha 0.01 over the suite: tests/support/chi2.h), with a control that must fail: the same
// counts against power-proportional probabilities, which the BVH does not use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "lights/light_bvh_scene.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kTests = 4;  // chi-square tests in this suite (the control excluded)
constexpr int kSamples = 400000;

// p-value of `counts` against `expected` probabilities; fails at once (returns -1) on a count in a
// cell of probability 0.
double p_value(const std::vector<int>& counts, const std::vector<double>& probability, int n) {
    std::vector<std::pair<double, int>> cells;
    for (size_t i = 0; i < counts.size(); ++i) {
        if (probability[i] == 0.0) {
            if (counts[i] > 0) return -1.0;
            continue;
        }
        cells.emplace_back(probability[i] * n, counts[i]);
    }
    // Pool the cells of expected count < 5, smallest first, until the pool reaches 5.
    std::sort(cells.begin(), cells.end());
    double stat = 0.0, pool_e = 0.0;
    int pool_o = 0, dof = -1;
    for (const auto& [e, o] : cells) {
        if (e < 5.0 || pool_e > 0.0) {
            pool_e += e;
            pool_o += o;
            if (pool_e < 5.0) continue;
            stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
            pool_e = 0.0;
            pool_o = 0;
        } else {
            stat += (o - e) * (o - e) / e;
        }
        ++dof;
    }
    if (pool_e > 0.0) {
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++dof;
    }
    return chi2_p_value(stat, dof);
}

struct Fixture {
    std::vector<std::pair<uint32_t, LightBounds>> bounded = random_light_bounds(48, 11);
    LightBvh bvh{bounded, {48, 49}, 50};

    // Counts of sample()'s choices at (p, n), and pmf() of each light.
    void draw(const Vec3f& p, const Vec3f& n, uint64_t seed, std::vector<int>& counts, std::vector<double>& pmf) const {
        // Cell 50: sample() picked nothing (a dead end of the tree: light_bvh_test.cpp).
        counts.assign(51, 0);
        pmf.assign(51, 0.0);
        double sum = 0.0;
        for (uint32_t l = 0; l < 50; ++l) sum += pmf[l] = static_cast<double>(bvh.pmf(p, n, l));
        pmf[50] = std::max(0.0, 1.0 - sum);
        Rng rng = Rng::for_sample(seed, 0, 3);
        for (int i = 0; i < kSamples; ++i) {
            std::optional<LightBvh::Choice> c = bvh.sample(p, n, rng.next_float());
            if (!c) {
                ++counts[50];
                continue;
            }
            ASSERT_EQ(c->pmf, bvh.pmf(p, n, c->light));  // the pmf sample() used is pmf()'s
            ++counts[c->light];
        }
    }
};

void expect_fits(const Vec3f& p, const Vec3f& n, uint64_t seed) {
    const Fixture f;
    std::vector<int> counts;
    std::vector<double> pmf;
    f.draw(p, n, seed, counts, pmf);
    const double pv = p_value(counts, pmf, kSamples);
    EXPECT_GE(pv, sidak_alpha(0.01, kTests)) << "at " << p.x << " " << p.y << " " << p.z;
}

TEST(LightBvhChi2, MediumPointInsideTheLights) { expect_fits({0.3f, -0.2f, 0.1f}, Vec3f{}, 1); }
TEST(LightBvhChi2, MediumPointOutsideTheLights) { expect_fits({9.0f, 4.0f, -7.0f}, Vec3f{}, 2); }
TEST(LightBvhChi2, SurfacePointFacingUp) { expect_fits({1.0f, 2.0f, -3.0f}, {0.0f, 0.0f, 1.0f}, 3); }
TEST(LightBvhChi2, SurfacePointTilted) { expect_fits({-2.0f, 0.5f, 2.0f}, normalize(Vec3f(1.0f, -1.0f, 0.5f)), 4); }

TEST(LightBvhChi2, ControlPowerProbabilitiesAreRejected) {
    const Fixture f;
    std::vector<int> counts;
    std::vector<double> pmf;
    f.draw({0.3f, -0.2f, 0.1f}, Vec3f{}, 1, counts, pmf);
    // Power-proportional choice among the bounded lights, with the same infinite share.
    double total = 0.0;
    for (const auto& [l, b] : f.bounded) total += static_cast<double>(b.phi);
    std::vector<double> power(51, 1.0 / 3.0);
    power[50] = 0.0;
    for (const auto& [l, b] : f.bounded) power[l] = static_cast<double>(b.phi) / total / 3.0;
    EXPECT_LT(p_value(counts, power, kSamples), 1e-6);
}

}  // namespace
}  // namespace candela::test
