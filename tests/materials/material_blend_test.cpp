// The choice of a blend's part (materials/material_blend.h): amount 0 and 1 choose their part
// outright, the hash is a deterministic function of point, direction and blend, and over many
// points it is uniform on [0, 1) (a chi-square test), so part 1 is chosen with probability amount.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "candela/materials/material_blend.h"
#include "candela/math/frame.h"
#include "support/chi2.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// The points and directions a camera sees on a quad: a 256 x 256 grid on [0, 1]^2 (z = 1.5), each
// seen from (0.3, 0.2, 4).
std::vector<std::array<Vec3f, 2>> shading_points() {
    std::vector<std::array<Vec3f, 2>> points;
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i) {
            const Vec3f p((float(i) + 0.5f) / 256.0f, (float(j) + 0.5f) / 256.0f, 1.5f);
            points.push_back({p, normalize(Vec3f(0.3f, 0.2f, 4.0f) - p)});
        }
    return points;
}

TEST(MaterialBlend, AmountZeroAndOneChooseTheirPartOutright) {
    const TextureSet no_textures;
    MaterialBlend b{{4, 9}, FloatParam{0.0f}};
    for (const auto& [p, wo] : shading_points()) {
        b.amount.value = 0.0f;
        EXPECT_EQ(choose_blend_part(b, 2, no_textures, TextureContext{Vec2f(), p}, wo), 4u);
        b.amount.value = 1.0f;
        ASSERT_EQ(choose_blend_part(b, 2, no_textures, TextureContext{Vec2f(), p}, wo), 9u);
    }
}

TEST(MaterialBlend, TheHashIsAFunctionOfPointDirectionAndBlend) {
    const Vec3f p(0.25f, -3.0f, 7.5f), wo = normalize(Vec3f(1.0f, 2.0f, 3.0f));
    const float u = blend_hash(p, wo, 3);
    EXPECT_EQ(blend_hash(p, wo, 3), u);
    EXPECT_GE(u, 0.0f);
    EXPECT_LT(u, 1.0f);
    // Any input changes it: a nested blend at the same point chooses independently.
    EXPECT_NE(blend_hash(p, wo, 4), u);
    EXPECT_NE(blend_hash(Vec3f(0.25f, -3.0f, std::nextafter(7.5f, 8.0f)), wo, 3), u);
    EXPECT_NE(blend_hash(p, -wo, 3), u);
}

TEST(MaterialBlend, TheHashIsUniform) {
    // Pearson's chi-square over 64 equal bins of [0, 1), 65536 hashes: 1024 expected per bin.
    constexpr int kBins = 64;
    std::array<double, kBins> count{};
    const auto points = shading_points();
    for (const auto& [p, wo] : points) count[size_t(blend_hash(p, wo, 1) * kBins)] += 1.0;
    const double expected = double(points.size()) / kBins;
    double statistic = 0.0;
    for (double c : count) statistic += (c - expected) * (c - expected) / expected;
    EXPECT_GT(test::chi2_p_value(statistic, kBins - 1), test::sidak_alpha(0.01, 1)) << statistic;
}

TEST(MaterialBlend, PartOneIsChosenWithProbabilityAmount) {
    const TextureSet no_textures;
    const auto points = shading_points();
    for (float amount : {0.1f, 0.5f, 0.75f}) {
        const MaterialBlend b{{0, 1}, FloatParam{amount}};
        double ones = 0.0;
        for (const auto& [p, wo] : points) ones += choose_blend_part(b, 5, no_textures, TextureContext{Vec2f(), p}, wo);
        const double n = double(points.size());
        // Binomial: the count's standard deviation is sqrt(n amount (1 - amount)).
        EXPECT_NEAR(ones / n, amount, 5.0 * std::sqrt(double(amount) * (1.0 - double(amount)) / n)) << amount;
    }
}

}  // namespace
}  // namespace candela
