#include "candela/film/sensor_fit.h"

#include <algorithm>
#include <cmath>

#include "candela/core/check.h"
#include "candela/spectrum/blackbody.h"
#include "candela/spectrum/cie_tables.h"

namespace candela {

namespace {

Matrix3d outer(const Vec3d& u, const Vec3d& v) {
    Matrix3d m;
    const double a[3] = {u.x, u.y, u.z}, b[3] = {v.x, v.y, v.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.m[i][j] = a[i] * b[j];
    return m;
}

void add(Matrix3d& sum, const Matrix3d& m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sum.m[i][j] += m.m[i][j];
}

double determinant(const Matrix3d& m) {
    return m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
           m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
           m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
}

double inner(const DenseSpectrum& a, const DenseSpectrum& b) {
    double sum = 0.0;
    for (int i = 0; i < kDenseSamples; ++i) sum += double(a.v[size_t(i)]) * double(b.v[size_t(i)]);
    return sum;
}

}  // namespace

Vec3d project_reflectance(const DenseSpectrum& refl, const DenseSpectrum& illum, const DenseSpectrum& b1,
                          const DenseSpectrum& b2, const DenseSpectrum& b3) {
    Vec3d sum;
    double b2_integral = 0.0;
    for (size_t i = 0; i < size_t(kDenseSamples); ++i) {
        const double lit = double(refl.v[i]) * double(illum.v[i]);
        b2_integral += double(b2.v[i]) * double(illum.v[i]);
        sum += Vec3d(double(b1.v[i]), double(b2.v[i]), double(b3.v[i])) * lit;
    }
    return sum / b2_integral;
}

std::optional<Matrix3d> least_squares_matrix(std::span<const Vec3d> a, std::span<const Vec3d> b) {
    CANDELA_CHECK(a.size() == b.size());
    Matrix3d ata, bta;
    for (size_t i = 0; i < a.size(); ++i) {
        add(ata, outer(a[i], a[i]));
        add(bta, outer(b[i], a[i]));
    }
    // A relative test: the a_i's scale is arbitrary (responses are relative).
    double scale = 0.0;
    for (const auto& row : ata.m)
        for (double v : row) scale = std::max(scale, std::abs(v));
    if (!(std::abs(determinant(ata)) > 1e-12 * scale * scale * scale)) return std::nullopt;
    return bta * ata.inverse();
}

SwatchTargets swatch_targets(const CameraResponse& camera, float white_balance_kelvin) {
    const DenseSpectrum illum = cie_daylight(white_balance_kelvin);
    const DenseSpectrum& d65 = d65_illuminant();
    // pbrt-v4's sensorWhiteY / sensorWhiteG.
    const double white_scale = inner(illum, cie_y_bar()) / inner(illum, camera.g);
    SwatchTargets t;
    const std::span<const DenseSpectrum> swatches = color_checker_swatches();
    for (int i = 0; i < kColorCheckerSwatches; ++i) {
        t.camera_rgb[i] = project_reflectance(swatches[size_t(i)], illum, camera.r, camera.g, camera.b);
        t.xyz[i] = project_reflectance(swatches[size_t(i)], d65, cie_x_bar(), cie_y_bar(), cie_z_bar()) * white_scale;
    }
    return t;
}

Matrix3d xyz_from_camera_rgb(const CameraResponse& camera, float white_balance_kelvin) {
    const SwatchTargets t = swatch_targets(camera, white_balance_kelvin);
    const std::optional<Matrix3d> m = least_squares_matrix(t.camera_rgb, t.xyz);
    // The measured responses are independent; the tests fit every camera.
    CANDELA_CHECK(m.has_value());
    return *m;
}

Matrix3d camera_rgb_from_linear_srgb(const CameraResponse& camera) {
    const DenseSpectrum& d65 = d65_illuminant();
    const std::span<const DenseSpectrum> swatches = color_checker_swatches();
    Vec3d srgb[kColorCheckerSwatches], response[kColorCheckerSwatches];
    for (int i = 0; i < kColorCheckerSwatches; ++i) {
        DenseSpectrum lit = swatches[size_t(i)];
        for (size_t n = 0; n < size_t(kDenseSamples); ++n) lit.v[n] *= d65.v[n];
        srgb[i] = srgb_color_space().rgb_from_xyz * spectrum_to_xyz(lit);
        response[i] = Vec3d(inner(lit, camera.r), inner(lit, camera.g), inner(lit, camera.b)) / double(kCieYIntegral);
    }
    const std::optional<Matrix3d> m = least_squares_matrix(srgb, response);
    CANDELA_CHECK(m.has_value());
    return *m;
}

}  // namespace candela
