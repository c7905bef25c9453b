#pragma once
// pbrt-v4's GridMedium (`uniformgrid`): coefficients sigma_a and sigma_s scaled by a density grid,
// and optionally emission, from a temperature grid (blackbody) or a spectrum Le, scaled by a grid
// Le_scale. The grids are GridFields (lattice_grid.h): uniformgrid places pbrt-v4's SampledGrid
// over the box p0..p1; NanoVDB / OpenVDB density and temperature grids are the same struct with
// their voxels' placement.
//
// At a medium-space point p (pbrt-v4's GridMedium::SamplePoint):
//   sigma_a(p) = sigma_a density(p),  sigma_s(p) = sigma_s density(p)
//   Le(p) = 0 unless s = Le_scale(p) > 0; then, with a temperature grid,
//           T = (temperature(p) - temperature_offset) temperature_scale,
//           Le = s blackbody_radiance(T) where T > 100 K (blackbody_emission.h), else 0;
//         and without one, Le = s Le (the spectrum normalized as pbrt-v4 normalizes it, 1 over its
//           photometric integral; in candela's units, luminance Y = 1).
// Le is not multiplied by the density: the path tracer weights it by sigma_a(p), which is.
// pbrt-v4's Le_scale is a grid; without one given it is a 1x1x1 grid of 1 over the box, whose
// lookup (samples at cell centres, zero outside) falls from 1 at the box's centre to 1/2 on its
// faces and 1/8 at its corners. candela reproduces that (make_le_scale_field), as a pbrt-v4
// scene's fire must look the same.
//
// The majorant is pbrt-v4's: a 16^3 MajorantGrid over the box of density bounds, times
// sigma_a + sigma_s; DDA through it along the ray clipped to the box.
#include <optional>

#include "candela/math/ray.h"
#include "candela/math/vec.h"
#include "candela/media/blackbody_emission.h"
#include "candela/media/lattice_grid.h"
#include "candela/media/majorant_grid.h"
#include "candela/media/medium_box.h"
#include "candela/media/medium_point.h"
#include "candela/media/medium_spectrum.h"

namespace candela {

struct GridMedium {
    MediumBox box;
    MediumSpectrum sigma_a, sigma_s;  // per unit length, `scale` applied
    float g = 0.0f;                   // Henyey-Greenstein asymmetry
    GridField density;

    // Emission: a temperature grid (not empty) or Le, times Le_scale.
    GridField temperature;
    float temperature_offset = 0.0f, temperature_scale = 1.0f;
    BlackbodyRgbTable blackbody_rgb;  // RGB mode's blackbody colours; made with a temperature grid
    MediumSpectrum Le;                // normalized; unused with a temperature grid
    GridField Le_scale;
    bool emissive = false;  // a temperature grid, or Le not black

    MajorantGrid majorant;  // density bounds over the box

    CANDELA_HD MediumPoint at(const Vec3f& p_world, const MediumChannels& ch) const {
        const Vec3f p = box.to_medium(p_world);
        const float d = density.at(p);
        MediumPoint mp{sigma_a.at(ch) * d, sigma_s.at(ch) * d, Color(0.0f)};
        if (!emissive) return mp;
        const float s = Le_scale.at(p);
        if (!(s > 0.0f)) return mp;
        if (temperature.empty()) {
            mp.Le = Le.at(ch) * s;
            return mp;
        }
        const float kelvin = (temperature.at(p) - temperature_offset) * temperature_scale;
        if (kelvin > kMinEmittingKelvin)
            mp.Le = (ch.spectral() ? blackbody_radiance(kelvin, *ch.lambda) : Color(blackbody_rgb.at(kelvin))) * s;
        return mp;
    }

    // The majorant segments of a world ray (unit direction) over [0, t_max]: the cells of the
    // majorant grid it crosses inside the box.
    CANDELA_HD DdaMajorantIterator majorants(const Ray& ray, float t_max, const MediumChannels& ch) const {
        Ray r;
        float t0, t1;
        if (!box.clip(ray, t_max, &r, &t0, &t1)) return {};
        return DdaMajorantIterator(r, t0, t1, &majorant, sigma_a.at(ch) + sigma_s.at(ch));
    }
};

// pbrt-v4's default Le_scale (scaled by `value`): a 1x1x1 grid over the box (see above).
GridField make_le_scale_field(float value, const Bounds3f& bounds);

// Completes a GridMedium whose other members are set: the majorant grid of majorant_res^3 cells
// from the density (pbrt-v4: 16 for uniformgrid, 64 for nanovdb), the blackbody table when there
// is a temperature grid, `emissive`. Le_scale must not be empty when the medium emits.
void finish_grid_medium(GridMedium& m, int majorant_res = MajorantGrid::kRes);

}  // namespace candela
