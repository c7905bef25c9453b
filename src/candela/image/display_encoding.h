#pragma once
// How an image's linear values become the values of an 8-bit display file (PNG, PPM): the tone
// map and the transfer curve. The film's settings (film/film_settings.h) carry one; image/ needs
// no more of the film than this.

namespace candela {

enum class Tonemap { kClamp, kExposure, kReinhard, kAces };
enum class Transfer { kSrgb, kGamma };

struct DisplayEncoding {
    Tonemap tonemap = Tonemap::kClamp;
    float exposure = 0.5f;  // the `exposure` tone map's parameter, in [0, 1)
    Transfer transfer = Transfer::kSrgb;
    float gamma = 2.2f;  // for Transfer::kGamma
};

}  // namespace candela
