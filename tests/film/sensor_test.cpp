// The sensor (film/sensor.h): spectral radiance to linear sRGB with candela's normalization (D65 of
// Y = 1 is white), the imaging ratio, the white balance, and RGB mode left bit-identical.
#include "candela/film/sensor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "candela/sampling/rng.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// FLT_EPSILON as a double: the unit of the float rounding bounds below.
constexpr double kFloatEps = double(FLT_EPSILON);

// The Monte Carlo checks in this file, for the Sidak correction of their level (0.01 in all),
// each over 3 channels.
constexpr int kMonteCarloChecks = 3 * 3;

// The two-sided standard normal quantile z with P(|Z| > z) = alpha, by bisection on erfc.
double two_sided_z(double alpha) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return hi;
}

double sidak_z() {
    const double alpha = -std::expm1(std::log1p(-0.01) / kMonteCarloChecks);
    return two_sided_z(alpha);
}

Vec3d to_vec(const Rgb& c) { return Vec3d(c.r, c.g, c.b); }

// The chromaticity of XYZ.
Vec2<double> xy_of(const Vec3d& xyz) { return {xyz.x / (xyz.x + xyz.y + xyz.z), xyz.y / (xyz.x + xyz.y + xyz.z)}; }

// The expectation of spectral_to_rgb for radiance s(lambda) under any wavelength density on
// [360, 830]: the integral of rgb_from_xyz * cie_bar(lambda) s(lambda) / kCieYIntegral over
// [360, 830] with the sensor's nearest-nm lookups, that is, every nm's value counted over the nm
// around it, the two ends over half a nm. In double.
Vec3d expected_rgb(const DenseSpectrum& s) {
    Vec3d xyz;
    for (int i = 0; i < kDenseSamples; ++i) {
        const double w = i == 0 || i == kDenseSamples - 1 ? 0.5 : 1.0;
        xyz += Vec3d(cie_x_bar().v[size_t(i)], cie_y_bar().v[size_t(i)], cie_z_bar().v[size_t(i)]) *
               (w * double(s.v[size_t(i)]) / double(kCieYIntegral));
    }
    return srgb_color_space().rgb_from_xyz * xyz;
}

// Four wavelengths from the hero's u, with the secondaries terminated if asked.
SampledWavelengths wavelengths(float u, bool terminated) {
    SampledWavelengths w = SampledWavelengths::sample_visible(u);
    if (terminated) w.terminate_secondary();
    return w;
}

// The sensor's estimate of radiance s at the wavelengths of hero sample u.
Rgb estimate(const Sensor& sensor, const DenseSpectrum& s, float u, bool terminated) {
    const SampledWavelengths w = wavelengths(u, terminated);
    return sensor.spectral_to_rgb(s.eval(w.lambda), w);
}

struct MonteCarloMean {
    Vec3d mean;
    Vec3d standard_error;
};

// The mean of the sensor's estimates over 2 jittered hero samples in each of `strata` equal
// strata of [0, 1), and its standard error: with F_k1, F_k2 the two estimates of stratum k,
// (F_k1 - F_k2)^2 / 2 is an unbiased estimate of the variance within stratum k, and the mean of
// the 2 strata samples has variance sum_k Var_k / (2 strata^2), so the standard error is
// sqrt(sum_k (F_k1 - F_k2)^2) / (2 strata).
MonteCarloMean stratified_mean(const Sensor& sensor, const DenseSpectrum& s, bool terminated, int strata) {
    Rng rng(0x73656e736f72ull /* "sensor" */, 1);
    Vec3d sum, squared_differences;
    for (int k = 0; k < strata; ++k) {
        Vec3d pair[2];
        for (Vec3d& f : pair) {
            const double u = (k + double(rng.next_float())) / strata;
            f = to_vec(estimate(sensor, s, std::min(float(u), 0x1.fffffep-1f), terminated));
            sum += f;
        }
        const Vec3d d = pair[0] - pair[1];
        squared_differences += d * d;
    }
    MonteCarloMean m;
    m.mean = sum / (2.0 * strata);
    m.standard_error = Vec3d(std::sqrt(squared_differences.x), std::sqrt(squared_differences.y),
                             std::sqrt(squared_differences.z)) /
                       (2.0 * strata);
    return m;
}

// The mean agrees with the expectation within z standard errors, plus the float rounding of the
// sensor's arithmetic (a few float roundings of each estimate: 8 FLT_EPSILON relative).
void expect_mean_near(const MonteCarloMean& m, const Vec3d& expected) {
    const double z = sidak_z();
    for (int c = 0; c < 3; ++c) {
        const double bound = z * m.standard_error[c] + 8.0 * kFloatEps * std::abs(expected[c]);
        EXPECT_NEAR(m.mean[c], expected[c], bound)
            << "channel " << c << ", standard error " << m.standard_error[c] << ", z " << z;
    }
}

constexpr int kStrata = 1 << 16;

TEST(Sensor, D65AtEveryNanometreIsExactlyTheWhiteOfSrgb) {
    // The sensor's sum taken deterministically at every nm (four nm per call, each of pdf 1/4 so
    // that the 1/4 of the average cancels; the padding past 830 nm has pdf 0 and must add
    // nothing) is rgb_from_xyz of D65's XYZ, which is (1, 1, 1) by the colour space's construction.
    const Sensor sensor;
    const DenseSpectrum& d65 = d65_illuminant();
    Vec3d sum, sum_abs;
    for (int first = kDenseLambdaMin; first <= kDenseLambdaMax; first += kColorChannels) {
        SampledWavelengths w;
        for (int i = 0; i < kColorChannels; ++i) {
            w.lambda.set(i, float(first + i));
            w.pdf.set(i, first + i <= kDenseLambdaMax ? 0.25f : 0.0f);
        }
        const Vec3d rgb = to_vec(sensor.spectral_to_rgb(d65.eval(w.lambda), w));
        sum += rgb;
        sum_abs += Vec3d(std::abs(rgb.x), std::abs(rgb.y), std::abs(rgb.z));
    }
    const Vec3d white = to_vec(xyz_to_linear_srgb(spectrum_to_xyz(d65)));
    for (int c = 0; c < 3; ++c) {
        // Each call rounds a few float products and sums of terms no larger than sum_abs.
        EXPECT_NEAR(sum[c], white[c], 8.0 * kFloatEps * sum_abs[c]) << c;
        EXPECT_NEAR(white[c], 1.0, 1e-6) << c;  // float rounding of the white's conversion
    }
}

TEST(Sensor, D65AtSampledWavelengthsAveragesToWhite) {
    const DenseSpectrum& d65 = d65_illuminant();
    const Vec3d expected = expected_rgb(d65);
    // The half-nm ends differ from the whole-nm sum of spectrum_to_xyz by about 1e-6.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(expected[c], 1.0, 1e-5) << c;
    expect_mean_near(stratified_mean(Sensor(), d65, false, kStrata), expected);
}

TEST(Sensor, TerminatedSecondaryWavelengthsStayUnbiased) {
    // After terminate_secondary only the hero counts, with pdf / 4: (1/4) cie L / (p / 4).
    const DenseSpectrum& d65 = d65_illuminant();
    expect_mean_near(stratified_mean(Sensor(), d65, true, kStrata), expected_rgb(d65));
}

TEST(Sensor, ColouredSpectrumAveragesToItsRgb) {
    // A reddish reflectance under D65: the same estimator for a spectrum far from flat.
    const float pairs[] = {400.0f, 0.1f, 500.0f, 0.3f, 600.0f, 0.9f, 700.0f, 0.6f};
    DenseSpectrum s = dense_from_pairs(pairs);
    for (int i = 0; i < kDenseSamples; ++i) s.v[size_t(i)] *= d65_illuminant().v[size_t(i)];
    const Vec3d expected = expected_rgb(s);
    EXPECT_GT(expected.x, 2.0 * expected.z);  // red, not grey: the test can tell channels apart
    expect_mean_near(stratified_mean(Sensor(), s, false, kStrata), expected);
}

// Wavelengths and radiance at a few hero samples, for the linearity checks.
std::vector<std::pair<Color, SampledWavelengths>> some_samples() {
    std::vector<std::pair<Color, SampledWavelengths>> samples;
    for (float u : {0.0f, 0.1f, 0.37f, 0.5f, 0.81f, 0.99f}) {
        const SampledWavelengths w = SampledWavelengths::sample_visible(u);
        samples.emplace_back(d65_illuminant().eval(w.lambda) * Color::from_channels(0.3f, 1.0f, 2.0f, 0.7f), w);
    }
    return samples;
}

// The magnitudes spectral_to_rgb's float arithmetic works with, per output channel: the sum over
// the matrix row of |rgb_from_xyz| times the summed |cie_bar L / p| (its channels can be small
// differences of large terms, so their rounding is relative to these, not to the result).
Vec3d term_magnitudes(const Color& L, const SampledWavelengths& w,
                      const Matrix3d& rgb_from_xyz = srgb_color_space().rgb_from_xyz) {
    Vec3d xyz;
    for (int i = 0; i < kColorChannels; ++i) {
        if (w.pdf[i] == 0.0f) continue;
        const double weight = std::abs(double(L[i]) / double(w.pdf[i])) / (4.0 * double(kCieYIntegral));
        xyz += Vec3d(cie_x_bar()(w.lambda[i]), cie_y_bar()(w.lambda[i]), cie_z_bar()(w.lambda[i])) * weight;
    }
    const Matrix3d& m = rgb_from_xyz;
    Vec3d t;
    for (int c = 0; c < 3; ++c) t[c] = std::abs(m.m[c][0]) * xyz.x + std::abs(m.m[c][1]) * xyz.y + std::abs(m.m[c][2]) * xyz.z;
    return t;
}

// |a - b| within `ulps` float roundings of `scale`, per channel.
void expect_rgb_near(const Rgb& a, const Rgb& b, double ulps, const Vec3d& scale) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], ulps * kFloatEps * scale[c]) << c;
}

TEST(Sensor, ImagingRatioIsExposureTimeTimesIsoOver100) {
    FilmSettings film;
    EXPECT_EQ(make_sensor(film).imaging_ratio(), 1.0f);
    film.iso = 400.0f;
    film.exposure_time = 0.5f;
    EXPECT_EQ(make_sensor(film).imaging_ratio(), 2.0f);
    film.iso = 50.0f;
    film.exposure_time = 1.0f / 8.0f;
    EXPECT_EQ(make_sensor(film).imaging_ratio(), 0.0625f);
}

TEST(Sensor, ImagingRatioScalesLinearly) {
    const Sensor unit;
    for (float ratio : {0.0625f, 2.5f, 1000.0f}) {
        const Sensor scaled(ratio, 0.0f);
        // The ratio is folded into the float matrix: a few roundings apart from scaling after.
        for (const auto& [L, w] : some_samples())
            expect_rgb_near(scaled.spectral_to_rgb(L, w), unit.spectral_to_rgb(L, w) * ratio, 16.0,
                            term_magnitudes(L, w) * double(ratio));
        // RGB mode without white balance multiplies by the ratio and nothing else.
        EXPECT_EQ(scaled.rgb_to_rgb(Rgb(0.2f, 1.5f, 3.0f)), Rgb(0.2f, 1.5f, 3.0f) * ratio);
    }
    // With white balance too: the ratio scales the balanced result.
    const Sensor balanced(1.0f, 4000.0f), balanced_scaled(3.0f, 4000.0f);
    const SrgbColorSpace& srgb = srgb_color_space();
    const Matrix3d rgb_from_balanced_xyz =
        srgb.rgb_from_xyz * white_balance_matrix(white_balance_source_xy(4000.0f), xy_of(srgb.white_xyz));
    const Matrix3d rgb_from_rgb = rgb_from_balanced_xyz * srgb.xyz_from_rgb;
    const Rgb c(0.2f, 1.5f, 3.0f);
    Vec3d rgb_terms;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rgb_terms[i] += std::abs(rgb_from_rgb.m[i][j] * double(c[j]));
    expect_rgb_near(balanced_scaled.rgb_to_rgb(c), balanced.rgb_to_rgb(c) * 3.0f, 16.0, rgb_terms * 3.0);
    for (const auto& [L, w] : some_samples())
        expect_rgb_near(balanced_scaled.spectral_to_rgb(L, w), balanced.spectral_to_rgb(L, w) * 3.0f, 16.0,
                        term_magnitudes(L, w, rgb_from_balanced_xyz) * 3.0);
}

TEST(Sensor, RgbModeIsBitIdenticalWithTheDefaults) {
    const float inf = std::numeric_limits<float>::infinity();
    const Rgb values[] = {Rgb(0.0f), Rgb(1.0f), Rgb(0.725f, 0.71f, 0.68f), Rgb(-0.0f, 1e-42f, 3e38f),
                          Rgb(-2.0f, 47.83f, inf), Rgb(std::nanf(""), 0.5f, -inf)};
    for (const Sensor& sensor : {Sensor(), make_sensor(FilmSettings{})}) {
        EXPECT_FALSE(sensor.white_balanced());
        for (const Rgb& v : values) {
            const Rgb out = sensor.rgb_to_rgb(v);
            EXPECT_EQ(std::memcmp(&out, &v, sizeof(Rgb)), 0) << v.r << " " << v.g << " " << v.b;
        }
    }
}

// The XYZ (Y = 1) of chromaticity xy.
Vec3d xyz_of_xy(Vec2<double> xy) { return Vec3d(xy.x / xy.y, 1.0, (1.0 - xy.x - xy.y) / xy.y); }


TEST(SensorWhiteBalance, SourceIsTheChromaticityOfCieDaylight) {
    // pbrt-v4's sensor adapts from the xy of Spectra::D(T), which is cie_daylight.
    for (float kelvin : {1000.0f, 2856.0f, 4000.0f, 6500.0f, 25000.0f}) {
        const Vec3d xyz = spectrum_to_xyz(cie_daylight(kelvin));
        EXPECT_EQ(white_balance_source_xy(kelvin), xy_of(xyz)) << kelvin;
    }
    // The chromaticities CIE 15:2004 tabulates (Table T.3) for D65 (6500 K nominal), D50 and D75,
    // within the 2e-4 to which the CIE's rounded M1, M2 and 5-nm tables reproduce them
    // (tests/spectrum/blackbody_test.cpp).
    const double tabulated[3][3] = {{6500, 0.31272, 0.32903}, {5000, 0.34567, 0.35851}, {7500, 0.29902, 0.31485}};
    for (const auto& [kelvin, x, y] : tabulated) {
        const Vec2<double> xy = white_balance_source_xy(float(kelvin));
        EXPECT_NEAR(xy.x, x, 2e-4) << kelvin;
        EXPECT_NEAR(xy.y, y, 2e-4) << kelvin;
    }
    // CIE illuminant A is a blackbody at 2848 K on the c2 = 1.435e-2 m K scale of its definition,
    // 2856 K with today's c2, of chromaticity (0.44757, 0.40745) (CIE 15:2004 T.1). The
    // temperature is scaled by 1.4388 / 1.4380 first, so A is asked for at 2856 * 1.4380 / 1.4388.
    const Vec2<double> a = white_balance_source_xy(float(2856.0 * 1.4380 / 1.4388));
    EXPECT_NEAR(a.x, 0.44757, 2e-4);
    EXPECT_NEAR(a.y, 0.40745, 2e-4);
}

TEST(SensorWhiteBalance, MapsTheDaylightWhiteToTheSrgbWhite) {
    const SrgbColorSpace& srgb = srgb_color_space();
    for (float kelvin : {1000.0f, 2856.0f, 3500.0f, 4000.0f, 5000.0f, 6500.0f, 9000.0f, 25000.0f}) {
        const Sensor sensor(1.0f, kelvin);
        EXPECT_TRUE(sensor.white_balanced());
        // The light of that temperature, at the luminance of the sRGB white, as RGB.
        const Rgb source = xyz_to_linear_srgb(xyz_of_xy(white_balance_source_xy(kelvin)) * srgb.white_xyz.y);
        const Rgb out = sensor.rgb_to_rgb(source);
        // The RGB-to-RGB map in double, to bound the float rounding: the source's own rounding,
        // the matrix's and that of its product, each at most 4 FLT_EPSILON relative per term.
        const Matrix3d m = srgb.rgb_from_xyz *
                           white_balance_matrix(white_balance_source_xy(kelvin), xy_of(srgb.white_xyz)) *
                           srgb.xyz_from_rgb;
        for (int c = 0; c < 3; ++c) {
            double terms = 0.0;
            for (int j = 0; j < 3; ++j) terms += std::abs(m.m[c][j] * double(source[j]));
            EXPECT_NEAR(out[c], 1.0, 4.0 * kFloatEps * terms) << kelvin << " " << c;
        }
    }
    // The adaptation matrix itself: from a white to itself it is the identity.
    const Vec2<double> w = xy_of(srgb.white_xyz);
    const Matrix3d same = white_balance_matrix(w, w);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(same.m[i][j], i == j ? 1.0 : 0.0, 1e-15) << i << j;
}

// The sensor's sum at every nm (four copies of nm n with pdf 1: (1/4) 4 cie_bar(n) L(n)), and the
// sum of the absolute values of its terms (for the float rounding bound).
std::pair<Vec3d, Vec3d> every_nm(const Sensor& sensor, const DenseSpectrum& L) {
    Vec3d sum, sum_abs;
    for (int n = kDenseLambdaMin; n <= kDenseLambdaMax; ++n) {
        SampledWavelengths w;
        w.lambda = Color(float(n));
        w.pdf = Color(1.0f);
        const Vec3d rgb = to_vec(sensor.spectral_to_rgb(L.eval(w.lambda), w));
        sum += rgb;
        sum_abs += Vec3d(std::abs(rgb.x), std::abs(rgb.y), std::abs(rgb.z));
    }
    return {sum, sum_abs};
}

TEST(SensorWhiteBalance, DaylightRadianceBecomesWhiteInSpectralMode) {
    // End to end in spectral mode: the light the white balance names (cie_daylight, a blackbody
    // below 4000 K), scaled to Y = 1 and integrated at every nm through spectral_to_rgb, comes
    // out white. Its xy is taken through the same sums, so the two agree to float rounding.
    for (float kelvin : {2856.0f, 4500.0f, 6500.0f, 9000.0f}) {
        DenseSpectrum light = cie_daylight(kelvin);
        light *= float(double(kCieYIntegral) / spectrum_to_photometric(light));
        const auto [sum, sum_abs] = every_nm(Sensor(1.0f, kelvin), light);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 16.0 * kFloatEps * sum_abs[c]) << kelvin << " " << c;
        if (kelvin == 2856.0f) {
            // Without white balance the same light is orange: red well above blue.
            const Vec3d plain = every_nm(Sensor(), light).first;
            EXPECT_GT(plain.x, 2.0 * plain.z);
        }
    }
}

TEST(SensorWhiteBalance, D65IsNearlyTheIdentity) {
    // 6500 (6504 K) is D65 by the CIE daylight basis; the sRGB white is D65 by its table. The two
    // chromaticities differ by the tables' rounding, well under 2e-4
    // (SourceIsTheChromaticityOfCieDaylight); 6504 is 3.6 K warmer still.
    const SrgbColorSpace& srgb = srgb_color_space();
    const Vec2<double> white = xy_of(srgb.white_xyz);
    for (float kelvin : {6500.0f, 6504.0f}) {
        const Vec2<double> source = white_balance_source_xy(kelvin);
        const Vec2<double> delta = white - source;
        EXPECT_LT(std::max(std::abs(delta.x), std::abs(delta.y)), 2e-4) << kelvin;
        // Von Kries gains g that take source to white, applied to white itself, move it by
        // J(white) (g - 1) = J(source) (g - 1) + O(delta^2) = delta + O(delta^2) in xy (J: the
        // derivative of xy by the gains). So the balanced white is white + delta, to a relative
        // 1e-2 of delta: over ten times the second-order term (|delta| / y < 6e-4 relative).
        const Rgb out = Sensor(1.0f, kelvin).rgb_to_rgb(Rgb(1.0f));
        const Vec2<double> moved = xy_of(srgb.xyz_from_rgb * to_vec(out));
        // Plus the float rounding of out (a few FLT_EPSILON per channel: well under 1e-6 in xy).
        const double tolerance = 1e-2 * std::hypot(delta.x, delta.y) + 1e-6;
        EXPECT_NEAR(moved.x, white.x + delta.x, tolerance) << kelvin;
        EXPECT_NEAR(moved.y, white.y + delta.y, tolerance) << kelvin;
    }
    // The same law holds far from white, where the white balance does something: 6000 K daylight
    // is yellower than D65, so balancing it makes D65 bluer.
    const Rgb warm = Sensor(1.0f, 6000.0f).rgb_to_rgb(Rgb(1.0f));
    EXPECT_GT(warm.b, 1.05f * warm.r);
}

// pbrt-v4's maxcomponentvalue (RGBFilm::AddSample): a sample whose largest sensor value (a
// component of imaging ratio x XYZ, before the white balance) exceeds the maximum is scaled so
// that it equals it; one that does not is left as it is, bit for bit.

// The sensor values of an RGB-mode sample: imaging_ratio x xyz_from_rgb x rgb, in double.
Vec3d sensor_values(const Rgb& c, double ratio) { return srgb_color_space().xyz_from_rgb * to_vec(c) * ratio; }

TEST(SensorClamp, RgbModeScalesTheLargestSensorValueToTheMaximum) {
    const Rgb c(10.0f, 5.0f, 1.0f);
    for (float ratio : {1.0f, 2.5f}) {
        const Vec3d xyz = sensor_values(c, ratio);
        const double largest = std::max({xyz.x, xyz.y, xyz.z});
        const Sensor clamped(ratio, 0.0f, 2.0f), free(ratio, 0.0f);
        const Rgb out = clamped.rgb_to_rgb(c);
        const double factor = 2.0 / largest;
        expect_rgb_near(out, free.rgb_to_rgb(c) * float(factor), 8.0, to_vec(c) * double(ratio) * factor);
        // Its sensor values now peak at the maximum.
        const Vec3d after = sensor_values(out, 1.0);  // out already holds the ratio
        EXPECT_NEAR(std::max({after.x, after.y, after.z}), 2.0, 2.0 * 16 * kFloatEps);
        // Below the maximum nothing changes.
        const Rgb dim(0.1f, 0.2f, 0.3f);
        const Rgb kept = clamped.rgb_to_rgb(dim), plain = free.rgb_to_rgb(dim);
        EXPECT_EQ(std::memcmp(&kept, &plain, sizeof(Rgb)), 0);
    }
    // The white balance comes after the clamp: the same factor scales the balanced value.
    const Sensor balanced(1.0f, 4000.0f), balanced_clamped(1.0f, 4000.0f, 2.0f);
    const Vec3d xyz = sensor_values(c, 1.0);
    const double factor = 2.0 / std::max({xyz.x, xyz.y, xyz.z});
    const Rgb b = balanced.rgb_to_rgb(c);
    expect_rgb_near(balanced_clamped.rgb_to_rgb(c), b * float(factor), 8.0, to_vec(b) * factor * 2.0);
}

TEST(SensorClamp, SpectralModeScalesTheLargestSensorValueToTheMaximum) {
    const Sensor free;
    for (const auto& [L, w] : some_samples()) {
        // The sample's sensor values: the XYZ estimate (1/4) sum cie_bar L / p / kCieYIntegral.
        Vec3d xyz;
        for (int i = 0; i < kColorChannels; ++i) {
            if (w.pdf[i] == 0.0f) continue;
            const int n = dense_index(w.lambda[i]);
            xyz += Vec3d(kCieX[n], kCieY[n], kCieZ[n]) *
                   (double(L[i]) / double(w.pdf[i]) / (4.0 * double(kCieYIntegral)));
        }
        const double largest = std::max({xyz.x, xyz.y, xyz.z});
        ASSERT_GT(largest, 0.0);
        const Rgb plain = free.spectral_to_rgb(L, w);
        // Half the largest: scaled by 1/2.
        const Sensor half(1.0f, 0.0f, float(largest / 2));
        expect_rgb_near(half.spectral_to_rgb(L, w), plain * 0.5f, 16.0, term_magnitudes(L, w) * 0.5);
        // Twice the largest: the same bits.
        const Rgb kept = Sensor(1.0f, 0.0f, float(largest * 2)).spectral_to_rgb(L, w);
        EXPECT_EQ(std::memcmp(&kept, &plain, sizeof(Rgb)), 0);
    }
}

TEST(SensorClamp, InfinityIsNoClampAndTheDefault) {
    EXPECT_FALSE(make_sensor(FilmSettings{}).clamps());
    const Sensor infinite(1.0f, 0.0f, std::numeric_limits<float>::infinity());
    EXPECT_FALSE(infinite.clamps());
    EXPECT_TRUE(Sensor(1.0f, 0.0f, 3.0f).clamps());
    const Rgb c(1e30f, 2.0f, 0.5f);
    const Rgb a = infinite.rgb_to_rgb(c), b = Sensor().rgb_to_rgb(c);
    EXPECT_EQ(std::memcmp(&a, &b, sizeof(Rgb)), 0);
}

}  // namespace
}  // namespace candela
