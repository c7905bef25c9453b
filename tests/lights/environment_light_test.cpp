// EnvironmentLight: the direction convention (u = atan2(x, -z) / 2pi, v = acos(y) / pi, +Y up),
// bilinear lookup with wrap in u, the to_world rotation, constant maps and power, and the
// agreement of sample() with pdf() and radiance().
#include <gtest/gtest.h>

#include <cmath>

#include "candela/lights/environment_light.h"
#include "candela/sampling/rng.h"

namespace candela {
namespace CANDELA_UNITY_ID {

const Rgb kRed(1.0f, 0.0f, 0.0f);
const Rgb kBlue(0.0f, 0.0f, 1.0f);

// The convention's direction for (u, v), written out independently of the implementation.
Vec3f direction_of(float u, float v) {
    double phi = 2.0 * kPiD * static_cast<double>(u), theta = kPiD * static_cast<double>(v);
    return Vec3f(Vec3d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)));
}

void expect_rgb_near(Rgb a, Rgb b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

// 2 x 1: red centred at u = 0.25, blue at u = 0.75, both at v = 0.5 (the horizon).
Image red_blue_columns() {
    Image img(2, 1);
    img.at(0, 0) = kRed;
    img.at(1, 0) = kBlue;
    return img;
}

TEST(EnvironmentLight, UOfAQuarterIsPlusXAtTheHorizonAndWrapsAroundMinusZ) {
    EnvironmentLight env(red_blue_columns(), 1.0f, Transform(), EnvironmentSampling::kImportance);
    expect_rgb_near(env.radiance(Vec3f(1.0f, 0.0f, 0.0f)), kRed);   // u = 0.25
    expect_rgb_near(env.radiance(Vec3f(-1.0f, 0.0f, 0.0f)), kBlue);  // u = 0.75
    Rgb half = kRed * 0.5f + kBlue * 0.5f;
    expect_rgb_near(env.radiance(Vec3f(0.0f, 0.0f, 1.0f)), half);   // u = 0.5, between the centres
    expect_rgb_near(env.radiance(Vec3f(0.0f, 0.0f, -1.0f)), half);  // u = 0: wraps to blue
}

TEST(EnvironmentLight, VOfZeroIsPlusYAndRowsClampAtThePoles) {
    Image img(1, 2);
    img.at(0, 0) = kRed;
    img.at(0, 1) = kBlue;
    EnvironmentLight env(img, 1.0f, Transform(), EnvironmentSampling::kImportance);
    expect_rgb_near(env.radiance(Vec3f(0.0f, 1.0f, 0.0f)), kRed);
    expect_rgb_near(env.radiance(Vec3f(0.0f, -1.0f, 0.0f)), kBlue);
    expect_rgb_near(env.radiance(normalize(Vec3f(0.3f, 0.0f, 0.7f))), kRed * 0.5f + kBlue * 0.5f);
}

TEST(EnvironmentLight, AHotTexelIsSeenFromItsConventionalDirectionAndSampledThere) {
    constexpr int kW = 8, kH = 4, kX = 2, kY = 1;
    Image img(kW, kH);
    img.at(kX, kY) = Rgb(5.0f);
    EnvironmentLight env(img, 1.0f, Transform(), EnvironmentSampling::kImportance);
    float u0 = (kX + 0.5f) / kW, v0 = (kY + 0.5f) / kH;
    expect_rgb_near(env.radiance(direction_of(u0, v0)), Rgb(5.0f), 1e-4f);
    // Every other texel centre is black.
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (x == kX && y == kY) continue;
            // Bilinear weights at a centre are 0 and 1 up to rounding.
            EXPECT_LT(env.radiance(direction_of((x + 0.5f) / kW, (y + 0.5f) / kH)).luminance(), 1e-4f);
        }
    }
    // The other way: sampled directions map back into the texel.
    Rng rng(3, 0);
    for (int i = 0; i < 2000; ++i) {
        auto s = env.sample(rng.next_vec2f());
        ASSERT_TRUE(s);
        double u = std::atan2(static_cast<double>(s->wi.x), -static_cast<double>(s->wi.z)) / (2.0 * kPiD);
        if (u < 0.0) u += 1.0;
        double v = std::acos(static_cast<double>(s->wi.y)) / kPiD;
        EXPECT_TRUE(u >= 2.0 / kW - 1e-6 && u <= 3.0 / kW + 1e-6) << u;
        EXPECT_TRUE(v >= 1.0 / kH - 1e-6 && v <= 2.0 / kH + 1e-6) << v;
    }
}

TEST(EnvironmentLight, ToWorldRotatesTheMap) {
    // 90 degrees about +Y takes the light's +X (red) to world -Z and its -X (blue) to world +Z.
    Transform rot = Transform::rotate(Vec3d(0.0, 1.0, 0.0), kPiD / 2.0);
    EnvironmentLight env(red_blue_columns(), 1.0f, rot, EnvironmentSampling::kImportance);
    expect_rgb_near(env.radiance(Vec3f(0.0f, 0.0f, -1.0f)), kRed);
    expect_rgb_near(env.radiance(Vec3f(0.0f, 0.0f, 1.0f)), kBlue);
    expect_rgb_near(env.radiance(normalize(rot.apply_vector(Vec3f(1.0f, 0.0f, 0.0f)))), kRed);
    // Samples come back rotated too: all of them in the red half lie towards world -Z.
    Image red_only(2, 1);
    red_only.at(0, 0) = kRed;
    EnvironmentLight red(red_only, 1.0f, rot, EnvironmentSampling::kImportance);
    Rng rng(5, 0);
    for (int i = 0; i < 1000; ++i) {
        auto s = red.sample(rng.next_vec2f());
        ASSERT_TRUE(s);
        EXPECT_LE(s->wi.z, 1e-6f);
    }
}

TEST(EnvironmentLight, ConstantMapIsItsColourTimesScaleEverywhereWithPowerPiR2L) {
    const Rgb c(0.5f, 1.0f, 2.0f);
    for (auto [w, h] : {std::pair{1, 1}, std::pair{6, 3}}) {
        Image img(w, h);
        for (Rgb& p : img.pixels) p = c;
        Transform rot = Transform::rotate(Vec3d(1.0, 2.0, 3.0), 0.7);
        EnvironmentLight env(img, 3.0f, rot, EnvironmentSampling::kImportance);
        Rng rng(1, 0);
        for (int i = 0; i < 200; ++i) {
            Vec3f d = normalize(Vec3f(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f));
            expect_rgb_near(env.radiance(d), c * 3.0f);
        }
        expect_rgb_near(env.radiance(Vec3f(0.0f, 1.0f, 0.0f)), c * 3.0f);
        float radius = 2.5f;
        EXPECT_NEAR(env.power(radius), kPi * radius * radius * c.luminance() * 3.0f, 1e-4f);
    }
}

TEST(EnvironmentLight, SamplesAgreeExactlyWithPdfAndRadiance) {
    Image img(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) img.at(x, y) = Rgb(0.1f + static_cast<float>(x * y), 1.0f, static_cast<float>(x));
    for (auto mode : {EnvironmentSampling::kImportance, EnvironmentSampling::kUniform}) {
        EnvironmentLight env(img, 2.0f, Transform::rotate(Vec3d(1.0, 1.0, 0.0), 1.1), mode);
        Rng rng(9, 0);
        for (int i = 0; i < 5000; ++i) {
            auto s = env.sample(rng.next_vec2f());
            ASSERT_TRUE(s);
            EXPECT_NEAR(length(s->wi), 1.0f, 1e-5f);
            EXPECT_GT(s->pdf, 0.0f);
            EXPECT_EQ(s->pdf, env.pdf(s->wi));
            EXPECT_EQ(s->Le, env.radiance(s->wi));
        }
    }
}

TEST(EnvironmentLight, UniformModeHasPdfOneOverFourPi) {
    Image img(4, 2);
    img.at(1, 1) = Rgb(3.0f);
    EnvironmentLight env(img, 1.0f, Transform(), EnvironmentSampling::kUniform);
    EXPECT_EQ(env.pdf(Vec3f(0.0f, 1.0f, 0.0f)), kInv4Pi);
    EXPECT_EQ(env.pdf(normalize(Vec3f(1.0f, -2.0f, 3.0f))), kInv4Pi);
    EXPECT_LE(env.sampling_memory_bytes(), sizeof(Distribution1D));  // no tables
}

TEST(EnvironmentLight, ZeroTexelsHavePdfZeroAndPolesToo) {
    Image img(4, 2);
    img.at(0, 0) = Rgb(1.0f);  // u in [0, 0.25), upper hemisphere
    EnvironmentLight env(img, 1.0f, Transform(), EnvironmentSampling::kImportance);
    EXPECT_GT(env.pdf(direction_of(0.125f, 0.25f)), 0.0f);
    EXPECT_EQ(env.pdf(direction_of(0.6f, 0.25f)), 0.0f);
    EXPECT_EQ(env.pdf(direction_of(0.125f, 0.75f)), 0.0f);
    EXPECT_EQ(env.pdf(Vec3f(0.0f, 1.0f, 0.0f)), 0.0f);  // the pole: sin(theta) = 0
}

TEST(EnvironmentLight, BlackMapCannotBeSampled) {
    Image img(4, 2);
    img.at(2, 1) = Rgb(-1.0f, 0.0f, 0.0f);  // negative luminance counts as black
    for (auto mode : {EnvironmentSampling::kImportance, EnvironmentSampling::kUniform}) {
        EnvironmentLight env(img, 1.0f, Transform(), mode);
        EXPECT_FALSE(env.sample(Vec2f(0.3f, 0.6f)));
        EXPECT_EQ(env.pdf(Vec3f(1.0f, 0.0f, 0.0f)), 0.0f);
        EXPECT_EQ(env.power(10.0f), 0.0f);
    }
}

}  // namespace
}  // namespace candela
