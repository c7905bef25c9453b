#pragma once
// Spectral mode: the lights' emission at one path's wavelengths, evaluated once per path and light
// instead of at every light sample and emitter hit.
#include <array>
#include <cstdint>

#include "candela/core/platform.h"
#include "candela/math/color.h"
#include "candela/spectrum/spectral_color.h"

namespace candela {

// A light's spectral emission depends only on the light and the path's four wavelengths, which
// stay the same along a path (terminating the secondary wavelengths changes only their pdfs).
// Evaluating it is an RGB uplift (a sigmoid at four wavelengths) times D65 at four table lookups;
// a path evaluated it at every vertex's light sample and at every emitter it hit. The integrator
// keeps one of these per path and passes it to LightSet's spectral sample() and emitted(): a
// direct-mapped table keyed by the light's selection index, so a scene's few lights each cost one
// evaluation per path. The values are the evaluation's, so images do not change.
class SpectralEmissionCache {
  public:
    static constexpr uint32_t kSlots = 4;

    // `emission` (the light of selection index `index`) at the wavelengths `lambda`.
    CANDELA_HD Color get(uint32_t index, const SpectralColor& emission, const Color& lambda) {
        const uint32_t s = index % kSlots;
        if (light_[s] != index) {
            light_[s] = index;
            value_[s] = emission.eval(lambda);
        }
        return value_[s];
    }

  private:
    static constexpr uint32_t kEmpty = UINT32_MAX;
    std::array<uint32_t, kSlots> light_{kEmpty, kEmpty, kEmpty, kEmpty};
    std::array<Color, kSlots> value_;
};

}  // namespace candela
