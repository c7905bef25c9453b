#pragma once
// How samples become pixels (the filter, the sensor) and pixels become display values (tone map,
// transfer).
#include "candela/core/platform.h"

namespace candela {

// The lowest white_balance temperature other than 0: below it a white balance is meaningless
// (a blackbody at 1000 K is a dim red; candles are about 1900 K).
inline constexpr float kMinWhiteBalanceKelvin = 1000.0f;

enum class FilterType { kBox, kTent, kGaussian, kSmallpt };
enum class Tonemap { kClamp, kExposure, kReinhard, kAces };
enum class Transfer { kSrgb, kGamma };

struct FilmSettings {
    FilterType filter = FilterType::kBox;
    Tonemap tonemap = Tonemap::kClamp;
    float exposure = 0.5f;  // the `exposure` tone map's parameter, in [0, 1)
    Transfer transfer = Transfer::kSrgb;
    float gamma = 2.2f;  // for Transfer::kGamma
    // The sensor (film/sensor.h, pbrt-v4's film and sensor options): the imaging ratio is
    // exposure_time * iso / 100, exactly 1 with the defaults; white_balance is the colour
    // temperature (kelvin) of the daylight that becomes white, 0 for none.
    float iso = 100.0f;
    float exposure_time = 1.0f;  // seconds
    float white_balance = 0.0f;  // 0 or >= kMinWhiteBalanceKelvin
};

// The sensor's imaging ratio: exposure_time * iso / 100 (pbrt-v4's PixelSensor::Create), exactly 1
// with the defaults.
CANDELA_HD inline float imaging_ratio(const FilmSettings& film) { return film.exposure_time * film.iso / 100.0f; }

}  // namespace candela
