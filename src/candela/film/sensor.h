#pragma once
// The sensor: how a camera sample's radiance becomes a linear sRGB pixel value (pbrt-v4's
// PixelSensor, and RGBFilm's output matrix). Its responses are the CIE 1931 matching functions
// (pbrt-v4's default "cie1931") or a measured camera's r, g, b curves (pbrt-v4's named sensors,
// spectrum/camera_sensors.h), with a matrix taking the sensor's RGB to XYZ: the white balance
// for cie1931, the least-squares fit of film/sensor_fit.h for a camera.
//
// Spectral mode: a path returns L, its radiance at four wavelengths drawn with pdfs p_i. The
// sensor integrates L against its responses by the Monte Carlo estimate
//     sensor RGB = imaging_ratio * (1/4) sum_i response(lambda_i) L_i / p_i / kCieYIntegral
// (pbrt-v4's ToSensorRGB; a terminated secondary wavelength has p_i = 0 and adds nothing), and
// maps it to linear sRGB: rgb = rgb_from_xyz * xyz_from_sensor * sensor RGB. For cie1931 the
// sensor RGB is XYZ and xyz_from_sensor the white balance.
// Dividing by the integral of y-bar is candela's normalization: an RGB emitter's spectrum is its
// illuminant uplift times D65 scaled to Y = 1 (spectrum/dense_spectrum.h), so an emitter of RGB
// (1, 1, 1) seen directly is pixel (1, 1, 1) in expectation, as in RGB mode. (pbrt-v4 divides
// each light by its photometric integral instead; the image is the same.)
//
// RGB mode: the path's RGB is already linear sRGB. For cie1931 the sensor only applies the
// imaging ratio and the white balance, and with the defaults returns its argument untouched, so
// RGB images do not change by a bit. A camera has no spectra to integrate in RGB mode; its
// sensor RGB is estimated by a fitted linear map from the path's sRGB (film/sensor_fit.h,
// camera_rgb_from_linear_srgb: exact in the mean over the ColorChecker's colours under white
// light, not for every spectrum), then mapped as in spectral mode.
//
// max_component_value (pbrt-v4's RGBFilm::AddSample) scales a sample's value down so that its
// largest sensor value, a component of the sensor RGB (imaging ratio included; before the colour
// matrix), is at most that; in RGB mode the sensor values are those the path's sRGB maps to
// (xyz_from_rgb x rgb for cie1931). Off (infinite) by default: one branch, and the same bits.
//
// A Sensor is built once per render (make_sensor) and used per camera sample.
#include <cmath>

#include "candela/core/platform.h"
#include "candela/film/film_settings.h"
#include "candela/math/color.h"
#include "candela/math/rgb.h"
#include "candela/math/vec.h"
#include "candela/spectrum/cie_tables.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"
#include "candela/spectrum/sampled_wavelengths.h"

namespace candela {

// A 3x3 float matrix (row-major) giving linear sRGB: the sensor's precomputed colour maps.
struct SensorMatrix {
    float m[3][3] = {};
    CANDELA_HD Rgb operator*(const Vec3f& v) const {
        return Rgb(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                   m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
    }
};

class Sensor {
  public:
    // pbrt-v4's default sensor: cie1931, imaging ratio 1, no white balance.
    Sensor() : Sensor(1.0f, 0.0f) {}
    // cie1931: imaging_ratio > 0 and finite; white_balance_kelvin 0 (none) or >= 1000.
    Sensor(float imaging_ratio, float white_balance_kelvin);
    // max_component_value > 0 (infinity: no clamp); camera_sensor an index into
    // camera_responses(), or kCie1931Sensor. A camera's white balance 0 is 6500 K (pbrt-v4's).
    Sensor(float imaging_ratio, float white_balance_kelvin, float max_component_value,
           int camera_sensor = kCie1931Sensor);

    // Spectral mode: the linear sRGB value of a camera sample of radiance L at wavelengths w.
    CANDELA_HD Rgb spectral_to_rgb(const Color& L, const SampledWavelengths& w) const {
        // Sum over the four wavelengths of response * L / p (XYZ for cie1931); 1/4,
        // 1/kCieYIntegral, the imaging ratio and the colour matrix are all in the one matrix.
        Vec3f xyz;
        for (int i = 0; i < kColorChannels; ++i) {
            if (w.pdf[i] == 0.0f) continue;  // a terminated secondary wavelength
            // The nearest tabulated nm, as DenseSpectrum's lookup (the CIE tables share its
            // layout: dense_spectrum.cpp checks; a camera's responses are DenseSpectrum's).
            const int n = dense_index(w.lambda[i]);
            if (n < 0) continue;
            const float weight = L[i] / w.pdf[i];
            xyz += Vec3f(r_bar_[n], g_bar_[n], b_bar_[n]) * weight;
        }
        const Rgb rgb = rgb_from_xyz_sum_ * xyz;
        if (!clamps_) return rgb;
        // The colour maps are linear: scaling the output scales the sensor values alike.
        return rgb * clamp_factor(max_component(xyz) * sensor_from_xyz_sum_);
    }

    // RGB mode: the path's linear sRGB through the sensor (see above); exactly `rgb` (the same
    // bits) for cie1931 when the ratio is 1 and there is no white balance.
    CANDELA_HD Rgb rgb_to_rgb(const Rgb& rgb) const {
        if (clamps_)
            return unclamped_rgb_to_rgb(rgb) *
                   clamp_factor((sensor_from_rgb_ * Vec3f(rgb.r, rgb.g, rgb.b)).max_component());
        return unclamped_rgb_to_rgb(rgb);
    }

    // The factor pbrt-v4's film scales a sample by: max_component_value / the largest of its
    // sensor values, or 1 when that is no more than max_component_value.
    CANDELA_HD float clamp_factor(float largest) const {
        return largest > max_component_value_ ? max_component_value_ / largest : 1.0f;
    }

    CANDELA_HD float imaging_ratio() const { return imaging_ratio_; }
    CANDELA_HD bool white_balanced() const { return white_balanced_; }
    CANDELA_HD bool is_camera() const { return r_bar_ != kCieX; }
    CANDELA_HD bool clamps() const { return clamps_; }

  private:
    CANDELA_HD Rgb unclamped_rgb_to_rgb(const Rgb& rgb) const {
        if (!maps_rgb_) return imaging_ratio_ == 1.0f ? rgb : rgb * imaging_ratio_;
        return rgb_from_rgb_ * Vec3f(rgb.r, rgb.g, rgb.b);
    }

    // The responses, 471 values from 360 nm each: the CIE tables, or a camera's DenseSpectrum
    // (static storage: camera_responses()).
    const float* r_bar_ = kCieX;
    const float* g_bar_ = kCieY;
    const float* b_bar_ = kCieZ;
    float imaging_ratio_ = 1.0f;
    bool white_balanced_ = false;
    bool maps_rgb_ = false;  // RGB mode goes through rgb_from_rgb_ (a white balance or a camera)
    // rgb_from_xyz * xyz_from_sensor * imaging_ratio / (4 kCieYIntegral): from the summed sensor
    // RGB (XYZ for cie1931, where xyz_from_sensor is the white balance).
    SensorMatrix rgb_from_xyz_sum_;
    // RGB mode: rgb_from_xyz * white balance * xyz_from_rgb * imaging_ratio for cie1931,
    // rgb_from_xyz * xyz_from_sensor * sensor_from_rgb * imaging_ratio for a camera.
    SensorMatrix rgb_from_rgb_;
    bool clamps_ = false;  // max_component_value_ is finite
    float max_component_value_ = 0.0f;
    float sensor_from_xyz_sum_ = 0.0f;  // imaging_ratio / (4 kCieYIntegral): the sum's sensor values
    // RGB mode's sensor values: xyz_from_rgb * imaging_ratio (cie1931), the fitted
    // camera_rgb_from_linear_srgb * imaging_ratio (a camera).
    SensorMatrix sensor_from_rgb_;
};

// The sensor of a render's film settings (camera_sensor, iso, exposure_time, white_balance,
// max_component_value).
Sensor make_sensor(const FilmSettings& film);

// The chromaticity the white balance adapts from, for a white_balance of `kelvin`: that of the
// CIE daylight illuminant cie_daylight(kelvin) (spectrum/blackbody.h, pbrt-v4's Spectra::D: the
// temperature is first scaled by 1.4388 / 1.4380, so 6500 is D65's 6504 K; below 4000 K, where
// the D series is undefined, a blackbody stands in).
Vec2<double> white_balance_source_xy(float kelvin);

// pbrt-v4's WhiteBalance: the von Kries adaptation in the Bradford cone space (LMS) that takes
// the white of chromaticity `from` to the white of chromaticity `to`, as a matrix on XYZ.
Matrix3d white_balance_matrix(Vec2<double> from, Vec2<double> to);

}  // namespace candela
