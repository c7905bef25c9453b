#pragma once
// What a render has accumulated: all it needs to go on. Checkpoints save it and --resume
// restores it, bit for bit.
#include <cstdint>

#include "candela/film/film.h"

namespace candela {

struct RenderState {
    Film film;                     // every pixel: the sum of its samples [0, samples_done)
    uint32_t samples_done = 0;     // per pixel, the same for all pixels (a pass boundary)
    uint64_t dropped_samples = 0;  // NaN/Inf samples among them, counted as zero
};

}  // namespace candela
