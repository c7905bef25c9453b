#include "candela/image/tonemap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {
namespace CANDELA_UNITY_ID {

DisplayEncoding film_with(Tonemap tonemap, float exposure = 0.5f) {
    DisplayEncoding film;
    film.tonemap = tonemap;
    film.exposure = exposure;
    return film;
}

float mapped(float c, const DisplayEncoding& film) { return tonemap(Rgb(c), film).r; }

TEST(Tonemap, ClampCutsAtOneAndKeepsSmallerValues) {
    const DisplayEncoding film = film_with(Tonemap::kClamp);
    EXPECT_EQ(mapped(0.0f, film), 0.0f);
    EXPECT_EQ(mapped(0.25f, film), 0.25f);
    EXPECT_EQ(mapped(1.0f, film), 1.0f);
    EXPECT_EQ(mapped(1e6f, film), 1.0f);
    EXPECT_EQ(mapped(-3.0f, film), 0.0f);
}

TEST(Tonemap, ExposureFollowsTheSeedFormula) {
    for (float exposure : {0.0f, 0.5f, 0.9f}) {
        const DisplayEncoding film = film_with(Tonemap::kExposure, exposure);
        EXPECT_EQ(mapped(0.0f, film), 0.0f);
        for (float c : {0.1f, 1.0f, 3.0f})
            EXPECT_NEAR(mapped(c, film), 1.0 - std::exp(-double(c) / (1.0 - double(exposure))), 1e-6) << c;
        EXPECT_NEAR(mapped(1e4f, film), 1.0f, 1e-6f);
    }
    EXPECT_NEAR(mapped(1.0f, film_with(Tonemap::kExposure, 0.0f)), 0.6321206f, 1e-6f);  // 1 - 1/e
    EXPECT_NEAR(mapped(1.0f, film_with(Tonemap::kExposure, 0.5f)), 0.8646647f, 1e-6f);  // 1 - e^-2
}

TEST(Tonemap, ReinhardMapsOneToHalf) {
    const DisplayEncoding film = film_with(Tonemap::kReinhard);
    EXPECT_EQ(mapped(0.0f, film), 0.0f);
    EXPECT_FLOAT_EQ(mapped(1.0f, film), 0.5f);
    EXPECT_FLOAT_EQ(mapped(3.0f, film), 0.75f);
    EXPECT_NEAR(mapped(1e6f, film), 1.0f, 1e-5f);
    EXPECT_LT(mapped(1e6f, film), 1.0f + 1e-7f);
}

TEST(Tonemap, AcesMatchesNarkowiczFit) {
    const DisplayEncoding film = film_with(Tonemap::kAces);
    EXPECT_EQ(mapped(0.0f, film), 0.0f);
    EXPECT_NEAR(mapped(0.18f, film), 0.2668989f, 1e-6f);   // 0.086724 / 0.324932
    EXPECT_NEAR(mapped(1.0f, film), 2.54f / 3.16f, 1e-6f);  // (2.51 + 0.03) / (2.43 + 0.59 + 0.14)
    EXPECT_EQ(mapped(100.0f, film), 1.0f);                 // the fit tends to 2.51 / 2.43 > 1: clamped
}

TEST(Tonemap, WorksPerChannel) {
    const Rgb out = tonemap(Rgb(0.0f, 1.0f, 3.0f), film_with(Tonemap::kReinhard));
    EXPECT_EQ(out.r, 0.0f);
    EXPECT_FLOAT_EQ(out.g, 0.5f);
    EXPECT_FLOAT_EQ(out.b, 0.75f);
}

TEST(Transfer, SrgbIsContinuousAtItsBreakpointAndMapsOneToOne) {
    EXPECT_EQ(encode_srgb(0.0f), 0.0f);
    EXPECT_NEAR(encode_srgb(0.0031308f), 0.04045f, 1e-6f);
    EXPECT_NEAR(encode_srgb(0.0031309f), 0.04045f, 2e-6f);  // the power segment starts there too
    EXPECT_NEAR(encode_srgb(0.001f), 0.01292f, 1e-7f);       // linear segment: 12.92 v
    EXPECT_NEAR(encode_srgb(0.5f), 0.7353570f, 1e-6f);
    EXPECT_FLOAT_EQ(encode_srgb(1.0f), 1.0f);
}

TEST(Transfer, DecodeSrgbInvertsEncode) {
    EXPECT_EQ(decode_srgb(0.0f), 0.0f);
    EXPECT_NEAR(decode_srgb(0.04045f), 0.0031308f, 1e-7f);
    EXPECT_FLOAT_EQ(decode_srgb(1.0f), 1.0f);
    for (int i = 0; i <= 100; ++i) {
        const float v = float(i) / 100.0f;
        EXPECT_NEAR(decode_srgb(encode_srgb(v)), v, 1e-6f) << v;
    }
}

TEST(Transfer, GammaRaisesToOneOverGamma) {
    DisplayEncoding film;
    film.transfer = Transfer::kGamma;
    film.gamma = 2.2f;
    EXPECT_EQ(encode_transfer(0.0f, film), 0.0f);
    EXPECT_NEAR(encode_transfer(0.5f, film), 0.7297400f, 1e-6f);
    EXPECT_FLOAT_EQ(encode_transfer(1.0f, film), 1.0f);
    film.transfer = Transfer::kSrgb;
    EXPECT_NEAR(encode_transfer(0.5f, film), 0.7353570f, 1e-6f);
}

TEST(Display, QuantizeRoundsToNearestAndClamps) {
    EXPECT_EQ(quantize_display(0.0f), 0);
    EXPECT_EQ(quantize_display(1.0f), 255);
    EXPECT_EQ(quantize_display(0.5f), 128);  // 127.5 rounds up
    EXPECT_EQ(quantize_display(0.49f / 255.0f), 0);
    EXPECT_EQ(quantize_display(0.51f / 255.0f), 1);
    EXPECT_EQ(quantize_display(-1.0f), 0);
    EXPECT_EQ(quantize_display(7.0f), 255);
    EXPECT_EQ(quantize_display(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(Display, ClampWithGammaMatchesSmallptToInt) {
    DisplayEncoding film;
    film.tonemap = Tonemap::kClamp;
    film.transfer = Transfer::kGamma;
    film.gamma = 2.2f;
    for (int i = 0; i <= 1200; ++i) {
        const float c = float(i) / 1000.0f;
        // smallpt: int(pow(clamp(x), 1 / 2.2) * 255 + .5)
        const double clamped = std::min(std::max(double(c), 0.0), 1.0);
        const int smallpt = int(std::pow(clamped, 1.0 / 2.2) * 255.0 + 0.5);
        EXPECT_EQ(int(to_display_bytes(Rgb(c), film)[0]), smallpt) << c;
    }
}

TEST(Display, BytesApplyTonemapThenTransferPerChannel) {
    DisplayEncoding film;
    film.tonemap = Tonemap::kReinhard;
    film.transfer = Transfer::kSrgb;
    const auto bytes = to_display_bytes(Rgb(0.0f, 1.0f, 1e9f), film);
    EXPECT_EQ(bytes[0], 0);
    EXPECT_EQ(bytes[1], 188);  // reinhard 0.5 -> sRGB 0.73536 -> 187.52
    EXPECT_EQ(bytes[2], 255);
}

}  // namespace
}  // namespace candela
