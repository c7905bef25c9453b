#pragma once
// pbrt-v4's `homogeneous` medium: the same coefficients and emission everywhere, so its majorant
// is sigma_t itself and one segment covers any ray.
#include <optional>

#include "candela/math/ray.h"
#include "candela/math/vec.h"
#include "candela/media/medium_point.h"
#include "candela/media/medium_spectrum.h"

namespace candela {

struct HomogeneousMedium {
    MediumSpectrum sigma_a, sigma_s;  // per unit length, `scale` applied
    MediumSpectrum Le;                // emitted radiance, normalized and scaled as pbrt-v4 does
    float g = 0.0f;                   // Henyey-Greenstein asymmetry
    bool emissive = false;            // Le is not black
    // The interior of a subsurface random walk (materials/subsurface.h): its scatterings are
    // steps of the walk, not bounces of the path, and do not count toward max_depth.
    bool subsurface = false;

    CANDELA_HD MediumPoint at(const Vec3f&, const MediumChannels& ch) const {
        return {sigma_a.at(ch), sigma_s.at(ch), emissive ? Le.at(ch) : Color(0.0f)};
    }

    // The majorant segments of a ray (unit direction) over [0, t_max]: one, sigma_t.
    struct Majorants {
        std::optional<MajorantSegment> segment;
        CANDELA_HD std::optional<MajorantSegment> next() {
            std::optional<MajorantSegment> s = segment;
            segment.reset();
            return s;
        }
    };
    CANDELA_HD Majorants majorants(const Ray&, float t_max, const MediumChannels& ch) const {
        return {MajorantSegment{0.0f, t_max, sigma_a.at(ch) + sigma_s.at(ch)}};
    }
};

}  // namespace candela
