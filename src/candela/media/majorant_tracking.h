#pragma once
// Sampling distances against a medium's majorant (pbrt-v4's SampleT_maj): the heart of delta
// tracking (the volumetric path tracer's scattering, absorption and null events) and of ratio
// tracking (transmittance along shadow rays). Both follow the null-scattering path integral of
// Miller, Georgiev and Jarosz (2019).
//
// Along the ray's majorant segments, distances are drawn from the majorant of one channel, the
// path's hero channel (spectral mode: the hero wavelength, channel 0; RGB mode: a channel drawn
// per path), exp(-sigma_maj[hero] t) sigma_maj[hero]. At each drawn point the callback gets the
// point, the medium there, the segment's sigma_maj and T_maj, the majorant transmittance (all
// channels) since the previous point; it returns false to stop. The return value is T_maj from
// the last point to t_max (1 if the callback stopped the walk), which the caller divides by its
// hero value: the probability of passing t_max.
#include <cmath>
#include <limits>
#include <optional>

#include "candela/math/color.h"
#include "candela/math/ray.h"
#include "candela/media/medium_point.h"
#include "candela/media/medium_spectrum.h"
#include "candela/sampling/rng.h"

namespace candela {

// sigma dt per channel; dt may be infinite (a ray leaving a medium that fills space), where a zero
// sigma gives 0, not NaN.
CANDELA_HD inline Color optical_depth(const Color& sigma, float dt) {
    if (std::isinf(dt)) dt = std::numeric_limits<float>::max();
    return sigma * dt;
}

// exp(-tau) per channel; exactly 1 for the depth 0 of a stretch of empty cells.
CANDELA_HD inline Color majorant_transmittance_of_depth(const Color& tau) {
    if (tau.is_black()) return Color(1.0f);
    return exp_channels(tau * -1.0f);
}

// `medium` is one medium type (media/medium.h; the caller visits the Variant once per walk),
// `ray` has any non-zero direction; t_max is in the ray's parameter (as a hit's t is). `u` is the
// first distance's uniform number, `rng` gives the rest.
//
// The distances are drawn as optical depths: one exponential depth tau = -log(1 - u) per point,
// spent segment by segment at the hero's sigma_maj until a segment holds the rest (memorylessness
// makes this the same distribution as pbrt-v4's fresh number per segment). The majorant
// transmittance of all channels is kept as an optical depth too and exponentiated once per
// point. So crossing a cell costs a few products, not a logarithm and four exponentials: on the
// NanoVDB smoke, whose rays crossed some hundred cells of a 64^3 majorant grid, those were a
// quarter of the render (bench/RESULTS.md, 2026-11-29).
template <class M, class F>
CANDELA_HD Color sample_majorant_transmittance(const M& medium, Ray ray, float t_max, float u, Rng& rng,
                                               const MediumChannels& ch, int hero, F&& callback) {
    // In units of length along a unit direction, as the media's segments are.
    const float len = length(ray.d);
    t_max *= len;
    ray.d = ray.d / len;
    auto segments = medium.majorants(ray, t_max, ch);
    Color tau_maj(0.0f);                // majorant optical depth since the last point, per channel
    float tau = -std::log1p(-u);        // the hero's optical depth left to the next point
    for (;;) {
        std::optional<MajorantSegment> seg = segments.next();
        if (!seg) return majorant_transmittance_of_depth(tau_maj);
        const float sigma_h = seg->sigma_maj[hero];
        float t0 = seg->t0;
        for (;;) {
            // Where the depth left runs out, if within this segment (never where sigma_h is 0).
            const float dt_left = seg->t1 - t0;
            if (!(sigma_h > 0.0f) || tau >= sigma_h * dt_left) {
                if (sigma_h > 0.0f) tau -= sigma_h * dt_left;
                tau_maj += optical_depth(seg->sigma_maj, dt_left);
                break;
            }
            const float t = t0 + tau / sigma_h;
            if (t >= seg->t1) {  // rounding put the point at the segment's end: go on past it
                tau = 0.0f;
                tau_maj += optical_depth(seg->sigma_maj, dt_left);
                break;
            }
            const Color T_maj = majorant_transmittance_of_depth(tau_maj + optical_depth(seg->sigma_maj, t - t0));
            const Vec3f p = ray.at(t);
            if (!callback(p, medium.at(p, ch), seg->sigma_maj, T_maj)) return Color(1.0f);
            tau_maj = Color(0.0f);
            tau = -std::log1p(-rng.next_float());
            t0 = t;
        }
    }
}

}  // namespace candela
