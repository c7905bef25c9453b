#pragma once
// What every camera provides, checked at each camera's definition (STYLE.md: a missing method
// fails at the struct, not inside visit).
#include <concepts>

#include "candela/math/ray.h"
#include "candela/sampling/sampler.h"

namespace candela {

template <class T>
concept CameraModel = requires(const T& camera, Vec2f film, Sampler& sampler) {
    // The ray of continuous film position `film` (pixels: x right, y down, (0, 0) the top-left
    // corner); unit direction, starting `near` along it. A camera with a lens draws its lens
    // point from `sampler` (one 2D request, right after the pixel filter's); one without draws
    // nothing, so the requests of pinhole scenes are those of version 1.
    { camera.generate_ray(film, sampler) } -> std::same_as<Ray>;
};

}  // namespace candela
