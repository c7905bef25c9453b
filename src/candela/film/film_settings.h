#pragma once
// How samples become pixels (the filter) and pixels become display values (tone map, transfer).

namespace candela {

enum class FilterType { kBox, kTent, kGaussian, kSmallpt };
enum class Tonemap { kClamp, kExposure, kReinhard, kAces };
enum class Transfer { kSrgb, kGamma };

struct FilmSettings {
    FilterType filter = FilterType::kBox;
    Tonemap tonemap = Tonemap::kClamp;
    float exposure = 0.5f;  // the `exposure` tone map's parameter, in [0, 1)
    Transfer transfer = Transfer::kSrgb;
    float gamma = 2.2f;  // for Transfer::kGamma
};

}  // namespace candela
