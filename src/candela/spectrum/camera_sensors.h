#pragma once
// pbrt-v4's named camera sensors (its PixelSensor::Create names: "canon_eos_5d_mkiv", ...): the
// measured r, g, b spectral responses of each camera, and the 24 ColorChecker reflectances that
// pbrt-v4 fits a sensor's colour matrix over (film/sensor_fit.h). The data is pbrt-v4's
// (camera_sensor_data.cpp, sources named there), resampled once into dense 1-nm tables as
// pbrt-v4's PiecewiseLinearSpectrum::FromInterleaved does: linear between the measured pairs,
// constant from the first pair down to 360 nm and from the last up to 830 nm.
#include <span>
#include <string_view>

#include "candela/spectrum/dense_spectrum.h"

namespace candela {

// One camera's responses (relative, as measured: not normalized).
struct CameraResponse {
    std::string_view name;
    DenseSpectrum r, g, b;
};

// Every named sensor, in pbrt-v4's order; a film's camera_sensor is an index into it.
std::span<const CameraResponse> camera_responses();

// The index of the sensor called `name` in camera_responses(), or -1 if there is none.
int camera_response_index(std::string_view name);

// The 24 swatches of the ColorChecker chart (reflectances), in the chart's order.
inline constexpr int kColorCheckerSwatches = 24;
std::span<const DenseSpectrum> color_checker_swatches();

}  // namespace candela
