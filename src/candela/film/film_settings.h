#pragma once
// How samples become pixels (the filter, the sensor) and pixels become display values (tone map,
// transfer).
#include <array>
#include <cmath>
#include <limits>

#include "candela/core/platform.h"
#include "candela/film/aov_layers.h"
#include "candela/image/display_encoding.h"
#include "candela/math/vec.h"

namespace candela {

// The lowest white_balance temperature other than 0: below it a white balance is meaningless
// (a blackbody at 1000 K is a dim red; candles are about 1900 K).
inline constexpr float kMinWhiteBalanceKelvin = 1000.0f;

// FilmSettings::camera_sensor of pbrt-v4's default sensor, the CIE 1931 observer.
inline constexpr int kCie1931Sensor = -1;

// The first four are the scene file's filter names (film.filter as a string); the last three are
// pbrt-v4's tabulated filters (film.filter as an object). Box and tent take a radius (pbrt-v4's box
// and triangle); kGaussian is candela's truncated normal (sigma 0.5, radius 1.5, sampled exactly),
// kOffsetGaussian pbrt-v4's Gaussian minus its value at the radius.
enum class FilterType { kBox, kTent, kGaussian, kSmallpt, kOffsetGaussian, kMitchell, kLanczos };

// A pixel filter and its parameters (film/pixel_filter.h); pbrt-v4's defaults.
struct FilterSettings {
    FilterType type = FilterType::kBox;
    Vec2f radius{0.5f, 0.5f};  // half-widths in pixels, x and y (kGaussian and kSmallpt: fixed)
    float sigma = 0.5f;        // kOffsetGaussian: the standard deviation, pixels
    float b = 1.0f / 3.0f;     // kMitchell: Mitchell and Netravali's B and C
    float c = 1.0f / 3.0f;
    float tau = 3.0f;  // kLanczos: the number of sinc lobes the window spans

    FilterSettings() = default;
    // The filter the scene file's string `type` names, with its fixed radius (box 0.5, tent 1);
    // implicit, so `film.filter = FilterType::kTent` reads as the scene file's "tent".
    FilterSettings(FilterType t);  // NOLINT(google-explicit-constructor)
    bool operator==(const FilterSettings&) const = default;
};

// pbrt-v4's default radius of each filter type (box 0.5, triangle 2, gaussian 1.5, mitchell 2,
// lanczos 4); kTent's is pbrt's triangle's, not the string "tent"'s (1).
CANDELA_HD inline float default_filter_radius(FilterType type) {
    switch (type) {
        case FilterType::kBox: return 0.5f;
        case FilterType::kTent: return 2.0f;
        case FilterType::kGaussian: return 1.5f;
        case FilterType::kSmallpt: return 0.75f;
        case FilterType::kOffsetGaussian: return 1.5f;
        case FilterType::kMitchell: return 2.0f;
        case FilterType::kLanczos: return 4.0f;
    }
    return 0.5f;
}

inline FilterSettings::FilterSettings(FilterType t) : type(t) {
    const float r = t == FilterType::kTent ? 1.0f : default_filter_radius(t);
    radius = Vec2f(r, r);
}

// A rectangle of pixels [x0, x1) x [y0, y1), y down from the top row.
struct PixelBounds {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

// The display encoding (image/display_encoding.h: tone map, exposure, transfer, gamma) is a base,
// so that film.tonemap reads as the scene file's film.tonemap and image writers take the settings.
struct FilmSettings : DisplayEncoding {
    FilterSettings filter;
    // The part of the image rendered and written (pbrt-v4's cropwindow): [x0, x1, y0, y1] as
    // fractions of the width and height, y from the top; see crop_pixel_bounds.
    std::array<float, 4> crop_window{0.0f, 1.0f, 0.0f, 1.0f};
    // The sensor (film/sensor.h, pbrt-v4's film and sensor options): the imaging ratio is
    // exposure_time * iso / 100, exactly 1 with the defaults; white_balance is the colour
    // temperature (kelvin) of the daylight that becomes white, 0 for none.
    float iso = 100.0f;
    float exposure_time = 1.0f;  // seconds
    float white_balance = 0.0f;  // 0 or >= kMinWhiteBalanceKelvin
    // The sensor's responses (film.sensor): kCie1931Sensor, or an index into camera_responses()
    // (spectrum/camera_sensors.h, pbrt-v4's named sensors; white_balance 0 is then 6500 K).
    int camera_sensor = kCie1931Sensor;
    // pbrt-v4's RGBFilm maxcomponentvalue: each sample's sensor values (its sensor RGB, CIE XYZ
    // for cie1931, times the imaging ratio) are scaled down so that the largest is at most this; infinity (the default): never.
    float max_component_value = std::numeric_limits<float>::infinity();
    // The AOV layers written beside the image (film.aovs, --aov): none by default; the channel
    // names they are written under and the space of position and normal.
    AovLayers aovs;
    AovNames aov_names = AovNames::kCandela;
    AovSpace aov_space = AovSpace::kWorld;
};

// The sensor's imaging ratio: exposure_time * iso / 100 (pbrt-v4's PixelSensor::Create), exactly 1
// with the defaults.
CANDELA_HD inline float imaging_ratio(const FilmSettings& film) { return film.exposure_time * film.iso / 100.0f; }

// The pixels of a width x height image that the crop window covers: from ceil(width * x0) to
// ceil(width * x1), and the same in y (pbrt-v4's FilmBaseParameters), so that the crops of
// adjacent windows tile the image. The whole image for the default window.
inline PixelBounds crop_pixel_bounds(int width, int height, const std::array<float, 4>& crop) {
    auto edge = [](int n, float f) { return int(std::ceil(float(n) * f)); };
    return {edge(width, crop[0]), edge(height, crop[2]), edge(width, crop[1]), edge(height, crop[3])};
}

}  // namespace candela
