#pragma once
// A participating medium (pbrt-v4's Medium): one of pbrt-v4's kinds, each answering two
// questions at a path's channels (medium_spectrum.h):
//   at(p, ch)                 -> MediumPoint: sigma_a, sigma_s and Le at world point p;
//   majorants(ray, t_max, ch) -> an iterator whose next() gives MajorantSegments in order along
//                                the ray (unit direction), each bounding sigma_a + sigma_s.
// The kinds: homogeneous (homogeneous_medium.h), uniformgrid (grid_medium.h: a density grid, and
// emission from a temperature grid or Le), rgbgrid (rgb_grid_medium.h: RGB coefficients per
// voxel), cloud (cloud_medium.h: pbrt-v4's procedural cloud).
// The phase function is Henyey-Greenstein with the medium's g (sampling/henyey_greenstein.h).
// Delta and ratio tracking over the segments are in majorant_tracking.h; the volumetric path
// tracer is integrators/volpath_integrator.cpp.
#include <concepts>
#include <optional>
#include <string>

#include "candela/core/variant.h"
#include "candela/media/cloud_medium.h"
#include "candela/media/grid_medium.h"
#include "candela/media/homogeneous_medium.h"
#include "candela/media/rgb_grid_medium.h"

namespace candela {

// What every medium type answers (see above); a type missing one fails here, at its name.
template <class T>
concept MediumType = requires(const T& m, const Vec3f& p, const Ray& ray, float t_max, const MediumChannels& ch) {
    { m.g } -> std::convertible_to<float>;
    { m.emissive } -> std::convertible_to<bool>;
    { m.at(p, ch) } -> std::same_as<MediumPoint>;
    { m.majorants(ray, t_max, ch).next() } -> std::same_as<std::optional<MajorantSegment>>;
};
static_assert(MediumType<HomogeneousMedium> && MediumType<GridMedium> && MediumType<RgbGridMedium> &&
              MediumType<CloudMedium>);

using Medium = Variant<HomogeneousMedium, GridMedium, RgbGridMedium, CloudMedium>;

// The Henyey-Greenstein asymmetry of medium m.
inline float medium_g(const Medium& m) {
    return visit([](const auto& x) { return x.g; }, m);
}

// Whether a scattering in medium m counts toward the path's max_depth: not in a subsurface random
// walk's interior (homogeneous_medium.h), whose walk takes hundreds of steps at high albedo.
inline bool medium_counts_bounces(const Medium& m) {
    const HomogeneousMedium* h = get_if<HomogeneousMedium>(&m);
    return !h || !h->subsurface;
}

// Whether medium m emits light anywhere.
inline bool medium_emissive(const Medium& m) {
    return visit([](const auto& x) { return x.emissive; }, m);
}

}  // namespace candela
