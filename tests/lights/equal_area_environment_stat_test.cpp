// Statistical tests of the equal-area environment map: chi-square fits of sample() against pdf()
// over the whole sphere (tests/support/chi2.h) for smooth, peaked and half-black square maps,
// rotated or not; and the `illuminance` normalization: the map scaled by target /
// environment_up_illuminance gives that illuminance to a surface facing the light frame's up
// direction, measured by the estimator E[luminance(Le) cos / pdf] with its standard error.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/lights/environment_light.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 5;  // in this file, for the Sidak correction

// A generic rotation: texel edges cross the harness's cells at odd angles.
const Transform kTilt = Transform::rotate(Vec3d(1.0, 0.5, -0.3), 0.9);

Image gradient_square(int n) {
    Image img(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            img.at(x, y) = Rgb(0.05f + 0.1f * static_cast<float>(x), 0.2f, 0.02f * static_cast<float>(y * y));
    return img;
}

// A 16 x 16 map, `background` everywhere but one texel of 1000.
Image hot_texel_square(float background) {
    Image img(16, 16);
    for (Rgb& p : img.pixels) p = Rgb(background);
    img.at(11, 4) = Rgb(1000.0f);
    return img;
}

// A 16 x 16 map whose columns u >= 0.5 are black (the hemisphere x < 0 is lit).
Image half_black_square() {
    Image img(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 8; ++x) img.at(x, y) = Rgb(1.0f + static_cast<float>((x + y) % 3));
    return img;
}

void expect_fits(const Image& img, const Transform& to_world) {
    EnvironmentLight env(img, 1.0f, to_world, EnvironmentSampling::kImportance, EnvironmentMapping::kEqualArea);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = 128;
    opt.res_y = 64;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        auto s = env.sample(rng.next_vec2f());
        if (!s) return std::nullopt;
        return s->wi;
    };
    auto pdf = [&](Vec3f w) { return env.pdf(w); };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(EqualAreaEnvironmentStat, SmoothGradientFits) { expect_fits(gradient_square(16), Transform()); }

TEST(EqualAreaEnvironmentStat, RotatedSmoothGradientFits) { expect_fits(gradient_square(16), kTilt); }

TEST(EqualAreaEnvironmentStat, HotTexelOnADimBackgroundFits) { expect_fits(hot_texel_square(0.01f), kTilt); }

TEST(EqualAreaEnvironmentStat, HalfBlackMapFitsAndIsNeverSampledInTheBlack) {
    // The harness fails on any sample in a cell where the pdf integrates to 0.
    expect_fits(half_black_square(), Transform());
}

TEST(EqualAreaEnvironmentStat, RotatedHalfBlackMapFits) { expect_fits(half_black_square(), kTilt); }

// Mean and standard error of luminance(Le) max(0, dot(n, wi)) / pdf over `count` samples.
std::pair<double, double> illuminance_estimate(const EnvironmentLight& env, Vec3f n, int count, uint64_t seed) {
    Rng rng(seed, 0);
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < count; ++i) {
        auto s = env.sample(rng.next_vec2f());
        double x = 0.0;
        if (s) {
            float cos_theta = dot(n, s->wi);
            if (cos_theta > 0.0f) x = static_cast<double>(s->Le.luminance() * cos_theta / s->pdf);
        }
        sum += x;
        sum_sq += x * x;
    }
    double mean = sum / count;
    double variance = std::max(0.0, sum_sq / count - mean * mean);
    return {mean, std::sqrt(variance / count)};
}

TEST(EnvironmentIlluminanceStat, ScaledMapGivesTheRequestedIlluminanceFacingUp) {
    constexpr double kTarget = 3.7;
    struct Case {
        Image map;
        EnvironmentMapping mapping;
        Vec3d up;  // in the light's frame
    };
    Image sky(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) sky.at(x, y) = Rgb(0.2f + 0.05f * static_cast<float>(y), 0.5f, 0.1f * static_cast<float>(x % 5));
    const Case cases[] = {
        {gradient_square(16), EnvironmentMapping::kEqualArea, {0, 0, 1}},
        {hot_texel_square(0.05f), EnvironmentMapping::kEqualArea, {0, 0, 1}},
        {sky, EnvironmentMapping::kEquirectangular, {0, 1, 0}},
    };
    uint64_t seed = 40;
    for (const Case& c : cases)
        for (auto filter : {EnvironmentFilter::kBilinear, EnvironmentFilter::kPoint}) {
            double up = environment_up_illuminance(c.map, c.mapping, filter);
            ASSERT_GT(up, 0.0);
            auto scale = static_cast<float>(kTarget / up);
            EnvironmentLight env(c.map, scale, kTilt, EnvironmentSampling::kImportance, c.mapping, filter);
            Vec3f n(kTilt.apply_vector(c.up));
            auto [mean, error] = illuminance_estimate(env, normalize(n), 400000, ++seed);
            EXPECT_GT(error, 0.0);
            // The estimator's error plus the quadrature's (about 1e-5 relative).
            EXPECT_NEAR(mean, kTarget, 5.0 * error + 1e-4 * kTarget) << "standard error " << error;
        }
}

}  // namespace
}  // namespace candela::test
