#include "candela/film/sensor.h"

#include "candela/core/check.h"
#include "candela/film/sensor_fit.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/camera_sensors.h"
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

}  // namespace

Vec2<double> white_balance_source_xy(float kelvin) {
    // pbrt-v4's PixelSensor: the xy of the D-series spectrum (a blackbody below 4000 K), through
    // the same sums as every other spectrum's XYZ.
    return xy_of_xyz(spectrum_to_xyz(cie_daylight(kelvin)));
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
    : imaging_ratio_(imaging_ratio), white_balanced_(white_balance_kelvin != 0.0f), maps_rgb_(white_balanced_) {
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
    sensor_from_rgb_ = to_float(scaled(srgb.xyz_from_rgb, double(imaging_ratio)));
}

Sensor::Sensor(float imaging_ratio, float white_balance_kelvin, float max_component_value, int camera_sensor)
    : Sensor(imaging_ratio, camera_sensor == kCie1931Sensor ? white_balance_kelvin : 0.0f) {
    CANDELA_CHECK(max_component_value > 0.0f);
    clamps_ = std::isfinite(max_component_value);
    max_component_value_ = max_component_value;
    sensor_from_xyz_sum_ = float(double(imaging_ratio) / (kColorChannels * double(kCieYIntegral)));
    if (camera_sensor == kCie1931Sensor) return;

    // A measured camera (pbrt-v4's PixelSensor(r, g, b, ...)): its responses, and the fitted
    // matrix in place of the white balance. pbrt-v4 white-balances a named sensor to 6500 K
    // daylight when the film gives no temperature.
    const std::span<const CameraResponse> cameras = camera_responses();
    CANDELA_CHECK(camera_sensor >= 0 && size_t(camera_sensor) < cameras.size());
    const CameraResponse& camera = cameras[size_t(camera_sensor)];
    r_bar_ = camera.r.v.data();
    g_bar_ = camera.g.v.data();
    b_bar_ = camera.b.v.data();
    const float kelvin = white_balance_kelvin == 0.0f ? kCameraDefaultWhiteBalance : white_balance_kelvin;
    white_balanced_ = true;
    maps_rgb_ = true;
    const Matrix3d rgb_from_sensor = srgb_color_space().rgb_from_xyz * xyz_from_camera_rgb(camera, kelvin);
    rgb_from_xyz_sum_ =
        to_float(scaled(rgb_from_sensor, double(imaging_ratio) / (kColorChannels * double(kCieYIntegral))));
    const Matrix3d sensor_from_rgb = camera_rgb_from_linear_srgb(camera);
    rgb_from_rgb_ = to_float(scaled(rgb_from_sensor * sensor_from_rgb, double(imaging_ratio)));
    sensor_from_rgb_ = to_float(scaled(sensor_from_rgb, double(imaging_ratio)));
}

Sensor make_sensor(const FilmSettings& film) {
    return Sensor(imaging_ratio(film), film.white_balance, film.max_component_value, film.camera_sensor);
}

}  // namespace candela
