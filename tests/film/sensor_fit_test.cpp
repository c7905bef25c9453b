// pbrt-v4's named camera sensors (spectrum/camera_sensors.h, film/sensor_fit.h, film/sensor.h):
// the measured responses as pbrt-v4's tables give them, the least-squares colour matrix, the
// white balance it carries, maxcomponentvalue in the camera's space, and RGB mode's stand-in.
#include "candela/film/sensor_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "candela/film/sensor.h"
#include "candela/scene/enum_names.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/cie_tables.h"

namespace candela {
namespace CANDELA_UNITY_ID {

// pbrt-v4's sensor names (PixelSensor::Create looks up NAME_r, NAME_g, NAME_b; Spectra::Init
// lists these 17).
constexpr std::array<std::string_view, 17> kPbrtSensors = {
    "canon_eos_100d",     "canon_eos_1dx_mkii", "canon_eos_200d",    "canon_eos_200d_mkii", "canon_eos_5d",
    "canon_eos_5d_mkii",  "canon_eos_5d_mkiii", "canon_eos_5d_mkiv", "canon_eos_5ds",       "canon_eos_m",
    "hasselblad_l1d_20c", "nikon_d810",         "nikon_d850",        "sony_ilce_6400",      "sony_ilce_7m3",
    "sony_ilce_7rm3",     "sony_ilce_9"};

const CameraResponse& camera(std::string_view name) {
    const int i = camera_response_index(name);
    EXPECT_GE(i, 0) << name;
    return camera_responses()[size_t(i)];
}

TEST(CameraSensors, EveryPbrtSensorHasANameAndResponses) {
    EXPECT_EQ(camera_responses().size(), kPbrtSensors.size());
    for (std::string_view name : kPbrtSensors) {
        ASSERT_GE(camera_response_index(name), 0) << name;
        EXPECT_EQ(sensor_name(*parse_sensor(name)), name);
        // Every response is positive somewhere (the fit needs three independent ones).
        const CameraResponse& c = camera(name);
        EXPECT_GT(c.r.max_value(), 0.0f);
        EXPECT_GT(c.g.max_value(), 0.0f);
        EXPECT_GT(c.b.max_value(), 0.0f);
    }
    EXPECT_EQ(parse_sensor("cie1931"), kCie1931Sensor);
    EXPECT_EQ(sensor_name(kCie1931Sensor), "cie1931");
    EXPECT_FALSE(parse_sensor("canon_eos_5d_mk4"));
    EXPECT_EQ(sensor_names().size(), kPbrtSensors.size() + 1);
}

double sum_over_nm(const DenseSpectrum& s) {
    double sum = 0.0;
    for (float v : s.v) sum += double(v);
    return sum;
}

TEST(CameraSensors, ResponsesSumToWhatPbrtsTablesGive) {
    // The sum over every nm of 360-830 of pbrt-v4's PiecewiseLinearSpectrum of each table
    // (linear between its pairs, the first value below 380 nm and the last above 720 nm),
    // computed in double by a separate Python script from pbrt-v4's src/pbrt/util/spectrum.cpp
    // at 5f7a6068. The dense tables are floats: 471 roundings of 2^-24 each bound the sum's
    // relative error by 471 x 6e-8 < 3e-5.
    struct Spot {
        std::string_view camera;
        char channel;
        double sum;
    };
    const Spot spots[] = {
        {"canon_eos_5d_mkiv", 'r', 50.03319474025001}, {"canon_eos_5d_mkiv", 'g', 102.30596695868408},
        {"canon_eos_5d_mkiv", 'b', 74.88637129445003}, {"sony_ilce_9", 'g', 96.08003497491819},
        {"nikon_d850", 'b', 66.69487830790077},        {"hasselblad_l1d_20c", 'r', 35.02180016489969}};
    for (const Spot& s : spots) {
        const CameraResponse& c = camera(s.camera);
        const DenseSpectrum& d = s.channel == 'r' ? c.r : s.channel == 'g' ? c.g : c.b;
        EXPECT_NEAR(sum_over_nm(d), s.sum, 3e-5 * s.sum) << s.camera << " " << s.channel;
    }
    // A point value: canon_eos_100d's green peaks at 520 nm at 0.9999999999999996 (the table's).
    EXPECT_FLOAT_EQ(camera("canon_eos_100d").g(520.0f), 1.0f);
    EXPECT_FLOAT_EQ(camera("canon_eos_100d").g.max_value(), 1.0f);
}

// The swatches' camera RGB and target XYZ, computed here from the data alone (not through
// swatch_targets): pbrt-v4's ProjectReflectance and its sensorWhiteY / sensorWhiteG scale.
struct Targets {
    std::array<Vec3d, kColorCheckerSwatches> a, b;
};
Targets independent_targets(const CameraResponse& c, float kelvin) {
    const DenseSpectrum illum = cie_daylight(kelvin);
    const DenseSpectrum& d65 = d65_illuminant();
    double illum_g = 0, illum_y = 0, d65_y = 0;
    for (int n = 0; n < kDenseSamples; ++n) {
        illum_g += double(illum.v[size_t(n)]) * double(c.g.v[size_t(n)]);
        illum_y += double(illum.v[size_t(n)]) * double(kCieY[n]);
        d65_y += double(d65.v[size_t(n)]) * double(kCieY[n]);
    }
    Targets t;
    for (int i = 0; i < kColorCheckerSwatches; ++i) {
        const DenseSpectrum& s = color_checker_swatches()[size_t(i)];
        for (int n = 0; n < kDenseSamples; ++n) {
            const double lit = double(s.v[size_t(n)]) * double(illum.v[size_t(n)]);
            t.a[size_t(i)] += Vec3d(c.r.v[size_t(n)], c.g.v[size_t(n)], c.b.v[size_t(n)]) * (lit / illum_g);
            const double lit65 = double(s.v[size_t(n)]) * double(d65.v[size_t(n)]);
            t.b[size_t(i)] += Vec3d(kCieX[n], kCieY[n], kCieZ[n]) * (lit65 / d65_y * illum_y / illum_g);
        }
    }
    return t;
}

double squared_residual(const Matrix3d& m, const Targets& t) {
    double sum = 0.0;
    for (size_t i = 0; i < t.a.size(); ++i) {
        const Vec3d r = m * t.a[i] - t.b[i];
        sum += r.x * r.x + r.y * r.y + r.z * r.z;
    }
    return sum;
}

// The largest entry of sum_i r_i a_i^T (r = M a - b) relative to sum_i |r_i| |a_i|: zero at the
// least-squares optimum (the normal equations), whatever the data's scale.
double normal_equation_defect(const Matrix3d& m, const Targets& t) {
    double g[3][3] = {}, scale = 0.0;
    for (size_t i = 0; i < t.a.size(); ++i) {
        const Vec3d r = m * t.a[i] - t.b[i];
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) g[j][k] += r[j] * t.a[i][k];
        scale += std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z) *
                 std::sqrt(t.a[i].x * t.a[i].x + t.a[i].y * t.a[i].y + t.a[i].z * t.a[i].z);
    }
    double worst = 0.0;
    for (auto& row : g)
        for (double v : row) worst = std::max(worst, std::abs(v));
    return worst / scale;
}

TEST(CameraSensorFit, MatrixIsTheLeastSquaresFitOverTheSwatches) {
    for (std::string_view name : kPbrtSensors) {
        for (float kelvin : {3200.0f, 6500.0f}) {
            const CameraResponse& c = camera(name);
            const Targets t = independent_targets(c, kelvin);
            // The library's targets are these (double sums in another order: 1e-12).
            const SwatchTargets lib = swatch_targets(c, kelvin);
            for (int i = 0; i < kColorCheckerSwatches; ++i)
                for (int k = 0; k < 3; ++k) {
                    EXPECT_NEAR(lib.camera_rgb[i][k], t.a[size_t(i)][k], 1e-12 * (1 + std::abs(t.a[size_t(i)][k])));
                    EXPECT_NEAR(lib.xyz[i][k], t.b[size_t(i)][k], 1e-12 * (1 + std::abs(t.b[size_t(i)][k])));
                }
            const Matrix3d m = xyz_from_camera_rgb(c, kelvin);
            // Optimal: the residual is orthogonal to the data (to double rounding of the 3x3
            // solve, well under 1e-9) ...
            EXPECT_LT(normal_equation_defect(m, t), 1e-9) << name << " " << kelvin;
            // ... and any change of one entry by 1e-4 of the matrix's size leaves more.
            const double base = squared_residual(m, t);
            double size = 0;
            for (auto& row : m.m)
                for (double v : row) size = std::max(size, std::abs(v));
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k)
                    for (double step : {-1e-4, 1e-4}) {
                        Matrix3d moved = m;
                        moved.m[j][k] += step * size;
                        EXPECT_GT(squared_residual(moved, t), base) << name << " " << j << k;
                    }
            // What least squares leaves: a fit, not an identity. Less than 5% of the targets'
            // size, RMS over the swatches (measured: 2.1% to 3.8% for these cameras).
            double target = 0;
            for (const Vec3d& b : t.b) target += b.x * b.x + b.y * b.y + b.z * b.z;
            EXPECT_LT(std::sqrt(base / target), 0.05) << name;
        }
    }
}

TEST(CameraSensorFit, ControlAPerturbedMatrixFailsTheNormalEquations) {
    // The check above can fail: 1% on one entry is far from the optimum.
    const CameraResponse& c = camera("canon_eos_5d_mkiv");
    const Targets t = independent_targets(c, 6500.0f);
    Matrix3d m = xyz_from_camera_rgb(c, 6500.0f);
    m.m[1][0] *= 1.01;
    EXPECT_GT(normal_equation_defect(m, t), 1e-6);
}

TEST(LeastSquaresMatrix, RecoversAnExactMapAndRejectsDegenerateData) {
    Matrix3d truth;
    const double v[3][3] = {{0.5, -0.2, 0.1}, {0.3, 1.1, -0.4}, {0.0, 0.2, 0.9}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) truth.m[i][j] = v[i][j];
    const std::array<Vec3d, 4> a = {Vec3d(1, 0, 0), Vec3d(0, 2, 0), Vec3d(0, 0, 3), Vec3d(1, 1, 1)};
    std::array<Vec3d, 4> b;
    for (size_t i = 0; i < a.size(); ++i) b[i] = truth * a[i];
    const auto m = least_squares_matrix(a, b);
    ASSERT_TRUE(m);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(m->m[i][j], truth.m[i][j], 1e-14);
    // All a_i in a plane: no unique fit.
    const std::array<Vec3d, 3> flat = {Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(1, 1, 0)};
    EXPECT_FALSE(least_squares_matrix(flat, std::span<const Vec3d>(b.data(), 3)));
}

// The sensor's output for radiance L summed at every nm (four copies of nm n with pdf 1), as
// film/sensor_test.cpp's every_nm: the expectation of spectral_to_rgb up to the ends' half-nm.
Vec3d every_nm(const Sensor& sensor, const DenseSpectrum& L) {
    Vec3d sum;
    for (int n = kDenseLambdaMin; n <= kDenseLambdaMax; ++n) {
        SampledWavelengths w;
        w.lambda = Color(float(n));
        w.pdf = Color(1.0f);
        const Rgb rgb = sensor.spectral_to_rgb(L.eval(w.lambda), w);
        sum += Vec3d(rgb.r, rgb.g, rgb.b);
    }
    return sum;
}

// The white balance: a white lit by the daylight the balance names comes out grey. Not exactly
// (a least-squares fit need not map any one colour exactly), so the fit's own residual sets the
// bound: white is close to the chart's six neutral swatches, which the fit treats like the rest,
// so its relative error is about a typical swatch's, the fit's RMS relative residual over the
// chart (measured for the 17 cameras at 3200, 4500 and 6500 K: 2.1% to 3.8%; white's largest
// channel error is at most 0.64 of it, 2.4%).
TEST(CameraSensorWhiteBalance, TheBalancedDaylightBecomesGrey) {
    for (std::string_view name : kPbrtSensors) {
        const CameraResponse& c = camera(name);
        for (float kelvin : {3200.0f, 4500.0f, 6500.0f}) {
            const Targets t = independent_targets(c, kelvin);
            const Matrix3d m = xyz_from_camera_rgb(c, kelvin);
            double target = 0;
            for (const Vec3d& b : t.b) target += b.x * b.x + b.y * b.y + b.z * b.z;
            const double rms_relative = std::sqrt(squared_residual(m, t) / target);
            const double bound = rms_relative;
            DenseSpectrum light = cie_daylight(kelvin);
            light *= float(double(kCieYIntegral) / spectrum_to_photometric(light));
            const Vec3d rgb = every_nm(Sensor(1.0f, kelvin, 1e30f, camera_response_index(name)), light);
            const double mean = (rgb.x + rgb.y + rgb.z) / 3;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(rgb[k] / mean, 1.0, bound) << name << " " << kelvin << " channel " << k;
            // Control: the same light through a sensor balanced for 6500 K is not grey.
            if (kelvin == 3200.0f) {
                const Vec3d warm = every_nm(Sensor(1.0f, 6500.0f, 1e30f, camera_response_index(name)), light);
                EXPECT_GT(warm.x, 1.5 * warm.z) << name;
            }
        }
    }
}

TEST(CameraSensor, MakeSensorTakesTheFilmsSensor) {
    FilmSettings film;
    EXPECT_FALSE(make_sensor(film).is_camera());
    film.camera_sensor = camera_response_index("sony_ilce_7m3");
    const Sensor camera = make_sensor(film);
    EXPECT_TRUE(camera.is_camera());
    EXPECT_TRUE(camera.white_balanced());  // 6500 K, pbrt-v4's default for a camera
    // Its colours are the camera's: a saturated red is not what the CIE observer makes of it.
    const Rgb red(0.8f, 0.1f, 0.05f);
    const Rgb a = camera.rgb_to_rgb(red), b = Sensor().rgb_to_rgb(red);
    EXPECT_GT(std::abs(a.g - b.g) + std::abs(a.b - b.b) + std::abs(a.r - b.r), 1e-3f);
}

TEST(CameraSensorWhiteBalance, ZeroMeansPbrtsDefaultOf6500K) {
    const int i = camera_response_index("nikon_d850");
    const Rgb a = Sensor(1.0f, 0.0f, 1e30f, i).rgb_to_rgb(Rgb(0.3f, 0.5f, 0.7f));
    const Rgb b = Sensor(1.0f, 6500.0f, 1e30f, i).rgb_to_rgb(Rgb(0.3f, 0.5f, 0.7f));
    EXPECT_EQ(a.r, b.r);
    EXPECT_EQ(a.g, b.g);
    EXPECT_EQ(a.b, b.b);
}

TEST(CameraSensorClamp, ScalesTheLargestCameraRgbToTheMaximum) {
    // pbrt-v4's RGBFilm clamps the sensor's own RGB (the camera's responses times the imaging
    // ratio), not XYZ: computed here from the responses.
    const int index = camera_response_index("canon_eos_5d_mkiv");
    const CameraResponse& c = camera_responses()[size_t(index)];
    SampledWavelengths w;
    w.lambda = Color::from_channels(450.0f, 530.0f, 610.0f, 680.0f);
    w.pdf = Color(1.0f / 470.0f);
    const Color L = Color::from_channels(30.0f, 20.0f, 40.0f, 10.0f);
    const float ratio = 1.25f;
    Vec3d sensor_rgb;
    for (int i = 0; i < 4; ++i)
        sensor_rgb += Vec3d(c.r(w.lambda[i]), c.g(w.lambda[i]), c.b(w.lambda[i])) *
                      (double(ratio) * double(L[i]) / double(w.pdf[i]) / (4.0 * double(kCieYIntegral)));
    const double largest = std::max({sensor_rgb.x, sensor_rgb.y, sensor_rgb.z});
    const Sensor free(ratio, 4500.0f, 1e30f, index);
    const Sensor clamped(ratio, 4500.0f, float(largest / 3), index);
    const Rgb a = free.spectral_to_rgb(L, w), b = clamped.spectral_to_rgb(L, w);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], a[k] / 3, 1e-5f * (std::abs(a[k]) + 1e-3f)) << k;
    // XYZ's largest value is not the camera's: the cie1931 clamp at the same level is different.
    const Sensor cie(ratio, 4500.0f, float(largest / 3));
    const Rgb d = cie.spectral_to_rgb(L, w), e = Sensor(ratio, 4500.0f).spectral_to_rgb(L, w);
    EXPECT_GT(std::abs(d.g / e.g - 1.0f / 3.0f), 0.01f);
}

TEST(CameraSensorRgbMode, WhiteStaysNearWhiteAndTheRatioScales) {
    // RGB mode's fitted stand-in: sRGB white (the D65 white of spectral mode) through a camera
    // balanced for D65 is white to within the two fits' residuals (measured: at most 0.11% off
    // in any channel; the bound is 0.5%).
    for (std::string_view name : kPbrtSensors) {
        const int i = camera_response_index(name);
        const Rgb w = Sensor(1.0f, 6500.0f, 1e30f, i).rgb_to_rgb(Rgb(1.0f));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], 1.0f, 0.005f) << name;
        const Rgb twice = Sensor(2.0f, 6500.0f, 1e30f, i).rgb_to_rgb(Rgb(1.0f));
        EXPECT_NEAR(twice.g, 2.0f * w.g, 1e-5f);
    }
}

}  // namespace
}  // namespace candela
