#pragma once
// A participating medium (pbrt-v4's Medium): one of pbrt-v4's kinds, each answering two
// questions at a path's channels (medium_spectrum.h):
//   at(p, ch)                 -> MediumPoint: sigma_a, sigma_s and Le at world point p;
//   majorants(ray, t_max, ch) -> an iterator whose next() gives MajorantSegments in order along
//                                the ray (unit direction), each bounding sigma_a + sigma_s.
// The phase function is Henyey-Greenstein with the medium's g (sampling/henyey_greenstein.h).
// Delta and ratio tracking over the segments are in majorant_tracking.h; the volumetric path
// tracer is integrators/volpath_integrator.cpp.
#include <string>

#include "candela/core/variant.h"
#include "candela/media/homogeneous_medium.h"

namespace candela {

using Medium = Variant<HomogeneousMedium>;

// The Henyey-Greenstein asymmetry of medium m.
inline float medium_g(const Medium& m) {
    return visit([](const auto& x) { return x.g; }, m);
}

// Whether medium m emits light anywhere.
inline bool medium_emissive(const Medium& m) {
    return visit([](const auto& x) { return x.emissive; }, m);
}

}  // namespace candela
