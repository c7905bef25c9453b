#include "candela/film/sensor.h"

#include "candela/core/check.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

namespace {

// The Bradford cone response (Lam 1985; the matrix pbrt-v4's LMSFromXYZ holds): XYZ to LMS.
constexpr Matrix3d kLmsFromXyz = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};

Matrix3d identity_matrix() {
    Matrix3d m;
    for (int i = 0; i < 3; ++i) m.m[i][i] = 1.0;
    return m;
}

Matrix3d scaled(Matrix3d m, double s) {
    for (auto& row : m.m)
        for (double& v : row) v *= s;
    return m;
}

SensorMatrix to_float(const Matrix3d& m) {
    SensorMatrix f;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) f.m[i][j] = float(m.m[i][j]);
    return f;
}

// XYZ of chromaticity (x, y) at luminance Y = 1 (pbrt-v4's XYZ::FromxyY).
Vec3d xyz_of_xy(Vec2<double> xy) { return Vec3d(xy.x / xy.y, 1.0, (1.0 - xy.x - xy.y) / xy.y); }

Vec2<double> xy_of_xyz(const Vec3d& xyz) {
    const double sum = xyz.x + xyz.y + xyz.z;
    return {xyz.x / sum, xyz.y / sum};
}

// Planck's law up to a constant factor, at lambda nm and T kelvin: lambda^-5 / (e^(c2 / lambda T) - 1),
// with the second radiation constant c2 = hc / k_B in nm K (CODATA, as pbrt-v4's Blackbody).
double planck_shape(double lambda_nm, double kelvin) {
    constexpr double kC2 = 1.438776877e7;
    return 1.0 / (std::pow(lambda_nm, 5.0) * std::expm1(kC2 / (lambda_nm * kelvin)));
}

}  // namespace

Vec2<double> white_balance_source_xy(float kelvin) {
    // pbrt-v4's Spectra::D: the nominal temperature to the correlated colour temperature on the
    // current c2 scale (CIE 15:2004, 3.1: the D series was defined with c2 = 1.4380e-2 m K).
    const double cct = double(kelvin) * 1.4388 / 1.4380;
    if (cct < 4000.0) {
        // The CIE daylight formulas start at 4000 K; below, pbrt-v4 uses a blackbody. Its
        // chromaticity as the sensor sees it: Planck's law at every tabulated nm, through the
        // same sums as every other spectrum's XYZ.
        // Normalized to 1 at Wien's peak (as pbrt-v4's BlackbodySpectrum) to stay in float range.
        const double peak = planck_shape(2.897771955e6 / cct, cct);
        DenseSpectrum b;
        for (int i = 0; i < kDenseSamples; ++i) b.v[size_t(i)] = float(planck_shape(kDenseLambdaMin + i, cct) / peak);
        return xy_of_xyz(spectrum_to_xyz(b));
    }
    // The chromaticity of CIE daylight at cct (CIE 15:2004, equations 3.3 and 3.4). pbrt-v4
    // integrates the D-series spectrum (S0 + M1 S1 + M2 S2, whose M1, M2 come from this same x_D,
    // y_D) against the matching functions instead; the two differ only by the rounding of the
    // 10-nm S tables and the 1-nm matching functions, about 1e-4 in x and y. The spectrum is
    // spectrum/blackbody.h's cie_daylight (another branch); when it lands, its spectrum_to_xyz
    // may replace this.
    const double t = 1.0 / cct;
    const double x = cct <= 7000.0 ? ((-4.6070e9 * t + 2.9678e6) * t + 0.09911e3) * t + 0.244063
                                   : ((-2.0064e9 * t + 1.9018e6) * t + 0.24748e3) * t + 0.237040;
    const double y = -3.0 * x * x + 2.870 * x - 0.275;
    return {x, y};
}

Matrix3d white_balance_matrix(Vec2<double> from, Vec2<double> to) {
    // Von Kries: scale each cone response so that the source white's becomes the target's
    // (pbrt-v4's WhiteBalance; Fairchild, Color Appearance Models, 2013, 9.1).
    const Vec3d from_lms = kLmsFromXyz * xyz_of_xy(from);
    const Vec3d to_lms = kLmsFromXyz * xyz_of_xy(to);
    Matrix3d gain;
    gain.m[0][0] = to_lms.x / from_lms.x;
    gain.m[1][1] = to_lms.y / from_lms.y;
    gain.m[2][2] = to_lms.z / from_lms.z;
    // pbrt-v4 writes the inverse Bradford matrix to six digits; the exact inverse makes the
    // adaptation of a white to itself the identity.
    return kLmsFromXyz.inverse() * gain * kLmsFromXyz;
}

Sensor::Sensor(float imaging_ratio, float white_balance_kelvin)
    : imaging_ratio_(imaging_ratio), white_balanced_(white_balance_kelvin != 0.0f) {
    CANDELA_CHECK(imaging_ratio > 0.0f && std::isfinite(imaging_ratio));
    CANDELA_CHECK(white_balance_kelvin == 0.0f || white_balance_kelvin >= 1000.0f);
    const SrgbColorSpace& srgb = srgb_color_space();
    const Matrix3d balance = white_balanced_ ? white_balance_matrix(white_balance_source_xy(white_balance_kelvin),
                                                                    xy_of_xyz(srgb.white_xyz))
                                             : identity_matrix();
    const Matrix3d rgb_from_sensor_xyz = srgb.rgb_from_xyz * balance;
    // spectral_to_rgb sums cie_bar L / p over the four wavelengths: the 1/4 of the average and
    // the 1/kCieYIntegral of the normalization go into its matrix.
    rgb_from_xyz_sum_ =
        to_float(scaled(rgb_from_sensor_xyz, double(imaging_ratio) / (kColorChannels * double(kCieYIntegral))));
    rgb_from_rgb_ = to_float(scaled(rgb_from_sensor_xyz * srgb.xyz_from_rgb, double(imaging_ratio)));
}

Sensor make_sensor(const FilmSettings& film) { return Sensor(imaging_ratio(film), film.white_balance); }

}  // namespace candela
