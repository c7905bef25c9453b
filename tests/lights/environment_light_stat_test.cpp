// Statistical tests of EnvironmentLight: chi-square fits of sample() against pdf() over the whole
// sphere (tests/support/chi2.h) for smooth, peaked, single-texel and half-black maps, rotated or
// not, and in uniform mode; and the irradiance estimator E[Le cos / pdf] of a constant map.
#include <gtest/gtest.h>

#include <cmath>

#include "candela/lights/environment_light.h"
#include "support/chi2.h"

namespace candela::test {
namespace CANDELA_UNITY_ID {

constexpr int kChi2Tests = 7;  // in this file, for the Sidak correction

// The light's +Y turned to world +Z, the harness's pole: the pdf's 1/sin(theta) singularities
// at the map's poles then sit on the domain's edge (z = +-1, where the pdf is 0) instead of at an
// integration node inside it, and u edges (multiples of 1/16) fall on the 128 phi cell edges.
const Transform kZUp = Transform::rotate(Vec3d(1.0, 0.0, 0.0), kPiD / 2.0);
// A generic rotation: texel edges cross cells at odd angles, the poles lie inside cells.
const Transform kTilt = Transform::rotate(Vec3d(1.0, 0.5, -0.3), 0.9);

Image gradient_map() {
    Image img(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            img.at(x, y) = Rgb(0.05f + 0.1f * static_cast<float>(x), 0.2f, 0.1f * static_cast<float>(y * y));
    return img;
}

// A 16 x 8 map, black or `background`, with one texel of 1000.
Image hot_texel_map(float background) {
    Image img(16, 8);
    for (Rgb& p : img.pixels) p = Rgb(background);
    img.at(5, 2) = Rgb(1000.0f);
    return img;
}

// A 16 x 8 map whose columns u >= 0.5 are black.
Image half_black_map() {
    Image img(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) img.at(x, y) = Rgb(1.0f + static_cast<float>((x + y) % 3));
    return img;
}

void expect_fits(const Image& img, const Transform& to_world, EnvironmentSampling mode) {
    EnvironmentLight env(img, 1.0f, to_world, mode);
    Chi2Options opt;
    opt.test_count = kChi2Tests;
    opt.res_x = 128;
    opt.res_y = 64;
    auto sampler = [&](Sampler& rng) -> std::optional<Vec3f> {
        auto s = env.sample(rng.next_vec2f());
        if (!s) return std::nullopt;
        return s->wi;
    };
    // The domain's edge z = +-1 has measure 0; there the rotation's rounding (cos(pi/2) = 6e-17)
    // leaves sin(theta) tiny but not 0, and one huge node value would swamp the cell's integral.
    auto pdf = [&](Vec3f w) { return std::abs(w.z) >= 1.0f ? 0.0f : env.pdf(w); };
    Chi2Result r = chi2_test(SphericalDomain{}, sampler, pdf, opt);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(EnvironmentLightStat, SmoothGradientFits) {
    expect_fits(gradient_map(), kZUp, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, RotatedSmoothGradientFits) {
    expect_fits(gradient_map(), kTilt, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, HotTexelOnADimBackgroundFits) {
    expect_fits(hot_texel_map(0.01f), kZUp, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, SingleHotTexelFits) {
    expect_fits(hot_texel_map(0.0f), kZUp, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, HalfBlackMapFitsAndIsNeverSampledInTheBlack) {
    // The harness fails on any sample in a cell where the pdf integrates to 0.
    expect_fits(half_black_map(), kZUp, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, RotatedHalfBlackMapFits) {
    expect_fits(half_black_map(), kTilt, EnvironmentSampling::kImportance);
}

TEST(EnvironmentLightStat, UniformModeFits) {
    expect_fits(gradient_map(), kTilt, EnvironmentSampling::kUniform);
}

// Mean and standard error of Le.luminance() max(0, dot(n, wi)) / pdf over n samples.
std::pair<double, double> irradiance_estimate(const EnvironmentLight& env, Vec3f n, int count,
                                              uint64_t seed) {
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

TEST(EnvironmentLightStat, ConstantMapIrradianceIsPiL) {
    Image img(64, 32);
    for (Rgb& p : img.pixels) p = Rgb(0.5f, 1.0f, 2.0f);
    const double expected = kPiD * static_cast<double>(Rgb(0.5f, 1.0f, 2.0f).luminance()) * 2.0;
    for (auto mode : {EnvironmentSampling::kImportance, EnvironmentSampling::kUniform}) {
        EnvironmentLight env(img, 2.0f, kTilt, mode);
        auto [mean, error] = irradiance_estimate(env, normalize(Vec3f(0.2f, 1.0f, -0.4f)), 200000, 11);
        EXPECT_GT(error, 0.0);
        EXPECT_NEAR(mean, expected, 5.0 * error) << "standard error " << error;
    }
}

TEST(EnvironmentLightStat, ImportanceAndUniformSamplingAgree) {
    Vec3f n = normalize(Vec3f(0.5f, 0.3f, 1.0f));
    for (const Image& img : {gradient_map(), hot_texel_map(0.01f)}) {
        EnvironmentLight importance(img, 1.0f, kTilt, EnvironmentSampling::kImportance);
        EnvironmentLight uniform(img, 1.0f, kTilt, EnvironmentSampling::kUniform);
        auto [a, ea] = irradiance_estimate(importance, n, 200000, 12);
        auto [b, eb] = irradiance_estimate(uniform, n, 200000, 13);
        EXPECT_NEAR(a, b, 5.0 * std::sqrt(ea * ea + eb * eb));
    }
    // On a peaked map, importance sampling has far lower variance than uniform sampling.
    Image peaked = hot_texel_map(0.01f);
    auto [a, ea] = irradiance_estimate(EnvironmentLight(peaked, 1.0f, kTilt, EnvironmentSampling::kImportance), n, 20000, 14);
    auto [b, eb] = irradiance_estimate(EnvironmentLight(peaked, 1.0f, kTilt, EnvironmentSampling::kUniform), n, 20000, 15);
    EXPECT_LT(ea, 0.5 * eb) << a << " vs " << b;
}

}  // namespace
}  // namespace candela::test
