#pragma once
// pbrt-v4's RGBGridMedium (`rgbgrid`): sigma_a, sigma_s and optionally Le given per voxel as RGB,
// over the box p0..p1 (pbrt-v4's SampledGrid: samples at cell centres, trilinear, zero outside).
//
//   sigma_a(p) = scale sigma_a_grid(p)   (1 everywhere when the grid is not given; likewise sigma_s)
//   Le(p)      = Le_scale Le_grid(p)     (when Le is given and Le_scale > 0)
// Spectral mode interpolates each voxel's spectrum at the path's wavelengths: pbrt-v4's
// RGBUnboundedSpectrum for the coefficients, RGBIlluminantSpectrum for Le (rgb_to_spectrum.h).
// RGB mode interpolates the RGB values.
//
// Le is pbrt-v4's radiance, not normalized (unlike a light's or uniformgrid's Le): candela's
// sensor divides by kCieYIntegral where pbrt-v4's does not (blackbody_emission.h), so Le here is
// kCieYIntegral times the voxel's illuminant spectrum, and RGB mode kCieYIntegral times its RGB,
// for the image pbrt-v4 makes.
//
// The majorant is pbrt-v4's: per cell of a 16^3 grid, scale (max sigma_a + max sigma_s) over the
// voxels a lookup in the cell reads, the maximum of each voxel's spectrum over 360-830 nm in
// spectral mode; RGB mode's grid takes the largest RGB channel instead (a spectrum's maximum need
// not bound its RGB).
#include "candela/math/color.h"
#include "candela/math/ray.h"
#include "candela/math/rgb.h"
#include "candela/math/vec.h"
#include "candela/media/lattice_grid.h"
#include "candela/media/majorant_grid.h"
#include "candela/media/medium_box.h"
#include "candela/media/medium_point.h"
#include "candela/media/medium_spectrum.h"
#include "candela/spectrum/cie_tables.h"
#include "candela/spectrum/rgb_to_spectrum.h"

namespace candela {

// A grid of RGB values in both modes' forms.
struct RgbLattice {
    Lattice<Rgb> rgb;               // RGB mode
    Lattice<RgbSpectrum> spectra;   // spectral mode: each voxel's uplift

    CANDELA_HD bool empty() const { return rgb.empty(); }
    // The interpolated value at u in [0, 1]^3 of the box, at the path's channels.
    CANDELA_HD Color lookup(const Vec3f& u, const MediumChannels& ch) const {
        if (ch.spectral()) {
            const Color& lambda = *ch.lambda;
            return spectra.lookup(u, [&](const RgbSpectrum& s) { return s.eval(lambda); });
        }
        return rgb.lookup(u, [](const Rgb& v) { return Color(v); });
    }
};

struct RgbGridMedium {
    MediumBox box;
    RgbLattice sigma_a, sigma_s;  // empty: 1 everywhere
    RgbLattice Le;                // empty: no emission
    float scale = 1.0f, Le_scale = 1.0f;
    float g = 0.0f;
    bool emissive = false;  // Le given and Le_scale > 0

    MajorantGrid majorant_spectral, majorant_rgb;  // bounds on sigma_t, `scale` applied

    CANDELA_HD MediumPoint at(const Vec3f& p_world, const MediumChannels& ch) const {
        const Vec3f u = box.unit(box.to_medium(p_world));
        MediumPoint mp;
        mp.sigma_a = (sigma_a.empty() ? Color(1.0f) : sigma_a.lookup(u, ch)) * scale;
        mp.sigma_s = (sigma_s.empty() ? Color(1.0f) : sigma_s.lookup(u, ch)) * scale;
        mp.Le = emissive ? Le.lookup(u, ch) * (Le_scale * kCieYIntegral) : Color(0.0f);
        return mp;
    }

    CANDELA_HD DdaMajorantIterator majorants(const Ray& ray, float t_max, const MediumChannels& ch) const {
        Ray r;
        float t0, t1;
        if (!box.clip(ray, t_max, &r, &t0, &t1)) return {};
        return DdaMajorantIterator(r, t0, t1, ch.spectral() ? &majorant_spectral : &majorant_rgb, Color(1.0f));
    }
};

// The RgbLattice of nx * ny * nz RGB values (x fastest), each uplifted as pbrt-v4 does:
// RGBIlluminantSpectrum when `illuminant`, else RGBUnboundedSpectrum.
RgbLattice make_rgb_lattice(int nx, int ny, int nz, std::vector<Rgb> values, bool illuminant);

// Completes an RgbGridMedium whose other members are set: both majorant grids and `emissive`.
void finish_rgb_grid_medium(RgbGridMedium& m);

}  // namespace candela
