#pragma once
// Grid media for the media tests: random density grids in randomly placed boxes, and rays at them.
#include <cmath>

#include "candela/math/transform.h"
#include "candela/media/grid_medium.h"
#include "candela/sampling/rng.h"
#include "candela/spectrum/dense_spectrum.h"

namespace candela::test {

// A coefficient of the same value in both colour modes.
inline MediumSpectrum grey_spectrum(float v) { return {Rgb(v), dense_constant(v)}; }

inline Vec3f random_in(Rng& rng, float lo, float hi) {
    return Vec3f(lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float(), lo + (hi - lo) * rng.next_float());
}

inline Vec3f random_direction(Rng& rng) {
    const float z = 1 - 2 * rng.next_float(), phi = 6.2831853f * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    return Vec3f(r * std::cos(phi), r * std::sin(phi), z);
}

// The CTM of a medium: a rotation, a non-uniform scale and a translation.
inline Transform random_placement(Rng& rng) {
    const Vec3f s = random_in(rng, 0.3f, 3.0f);
    return Transform::translate(Vec3d(random_in(rng, -2.0f, 2.0f))) *
           Transform::rotate(Vec3d(random_direction(rng)), 6.2831853 * double(rng.next_float())) *
           Transform::scale(Vec3d(s));
}

// A uniformgrid of random size with random densities (a fifth of them 0, some spikes), sigma_t
// (sigma_a, sigma_s) in a random box under a random CTM.
// *ctm receives the CTM.
inline GridMedium random_grid_medium(Rng& rng, float sigma_a, float sigma_s, Transform* ctm_out) {
    GridMedium m;
    const Transform ctm = random_placement(rng);
    *ctm_out = ctm;
    m.box.medium_from_world = affine_map_3f(ctm.inverse());
    m.box.bounds = Bounds3f{};
    m.box.bounds.extend(random_in(rng, -1.0f, 0.0f));
    m.box.bounds.extend(random_in(rng, 0.5f, 2.0f));
    LatticeGrid d;
    d.nx = 1 + int(rng.next_float() * 40);
    d.ny = 1 + int(rng.next_float() * 40);
    d.nz = 1 + int(rng.next_float() * 40);
    for (int i = 0; i < d.nx * d.ny * d.nz; ++i) {
        const float r = rng.next_float();
        d.values.push_back(r < 0.2f ? 0.0f : (r < 0.25f ? 50.0f * rng.next_float() : rng.next_float()));
    }
    m.density = cell_centred_field(std::move(d), m.box.bounds);
    m.sigma_a = grey_spectrum(sigma_a);
    m.sigma_s = grey_spectrum(sigma_s);
    finish_grid_medium(m);
    return m;
}

// A unit-direction world ray aimed near a medium's box (medium_to_world: its CTM): through a
// random point of the box grown by a fifth, from a random distance, so that it starts inside or
// outside, and some miss.
inline Ray random_ray_at(const MediumBox& box, const Transform& medium_to_world, Rng& rng) {
    const Vec3f t = random_in(rng, -0.2f, 1.2f);
    const Vec3f target = medium_to_world.apply_point(box.bounds.lo + t * box.bounds.diagonal());
    Ray r;
    r.d = random_direction(rng);
    r.o = target - r.d * (8.0f * rng.next_float());
    return r;
}

}  // namespace candela::test
