#pragma once
// The colour matrices of a measured camera sensor (pbrt-v4's PixelSensor for its named sensors):
// a camera's r, g, b responses are not colour matching functions, so no matrix maps them to CIE
// XYZ exactly; pbrt-v4 takes the 3x3 matrix that does so best, in the least-squares sense, over
// the 24 ColorChecker swatches (spectrum/camera_sensors.h). All in double, once per render.
#include <optional>
#include <span>

#include "candela/math/vec.h"
#include "candela/spectrum/camera_sensors.h"
#include "candela/spectrum/color_space.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// The white balance pbrt-v4 gives a named sensor when the film asks for none (whitebalance 0):
// daylight of 6500 K.
inline constexpr float kCameraDefaultWhiteBalance = 6500.0f;

// The responses (b1, b2, b3) to reflectance `refl` lit by `illum`, each the sum over every nm of
// 360-830 of b refl illum, divided by the sum of b2 illum (pbrt-v4's ProjectReflectance): the
// second response of a perfect white is 1.
Vec3d project_reflectance(const DenseSpectrum& refl, const DenseSpectrum& illum, const DenseSpectrum& b1,
                          const DenseSpectrum& b2, const DenseSpectrum& b3);

// The matrix M that minimizes sum_i |M a_i - b_i|^2 (the normal equations, M = (sum b a^T)
// (sum a a^T)^-1), or nothing when the a_i do not span three dimensions.
std::optional<Matrix3d> least_squares_matrix(std::span<const Vec3d> a, std::span<const Vec3d> b);

// The swatches' camera RGB under daylight of `white_balance_kelvin` (spectrum/blackbody.h,
// cie_daylight), and the XYZ the fit maps them to: the swatches' XYZ under D65 (the output
// colour space's white), scaled by Y/g of the daylight (pbrt-v4's sensorWhiteY / sensorWhiteG)
// so that a white lit by the daylight becomes D65's white of the same luminance. This is the
// white balance: the camera's white under that light is mapped to the display's white.
struct SwatchTargets {
    Vec3d camera_rgb[kColorCheckerSwatches];
    Vec3d xyz[kColorCheckerSwatches];
};
SwatchTargets swatch_targets(const CameraResponse& camera, float white_balance_kelvin);

// pbrt-v4's XYZFromSensorRGB of a named sensor: the least-squares fit of swatch_targets.
Matrix3d xyz_from_camera_rgb(const CameraResponse& camera, float white_balance_kelvin);

// RGB mode's stand-in for the camera (RGB mode has no spectra to integrate against its
// responses): the matrix that maps the swatches' linear sRGB under D65 (the colour an RGB render
// gives a swatch lit by white) to the camera's responses to them, in the sensor's units (the
// sum of response x radiance over nm, divided by the integral of y-bar, as film/sensor.h
// normalizes spectral mode), fitted by least squares.
Matrix3d camera_rgb_from_linear_srgb(const CameraResponse& camera);

}  // namespace candela
