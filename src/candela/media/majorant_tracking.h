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

// exp(-sigma dt) per channel; dt may be infinite (a ray leaving a medium that fills space),
// where a zero sigma gives 1, not NaN.
CANDELA_HD inline Color majorant_transmittance(const Color& sigma, float dt) {
    if (std::isinf(dt)) dt = std::numeric_limits<float>::max();
    return exp_channels(sigma * -dt);
}

// `medium` is one medium type (media/medium.h; the caller visits the Variant once per walk),
// `ray` has any non-zero direction; t_max is in the ray's parameter (as a hit's t is). `u` is the
// first distance's uniform number, `rng` gives the rest.
template <class M, class F>
CANDELA_HD Color sample_majorant_transmittance(const M& medium, Ray ray, float t_max, float u, Rng& rng,
                                               const MediumChannels& ch, int hero, F&& callback) {
    // In units of length along a unit direction, as the media's segments are.
    const float len = length(ray.d);
    t_max *= len;
    ray.d = ray.d / len;
    auto segments = medium.majorants(ray, t_max, ch);
    Color T_maj(1.0f);
    for (;;) {
        std::optional<MajorantSegment> seg = segments.next();
        if (!seg) return T_maj;
        const float sigma_h = seg->sigma_maj[hero];
        if (sigma_h == 0.0f) {
            // No collision can be drawn here: only the other channels' majorant attenuates.
            T_maj *= majorant_transmittance(seg->sigma_maj, seg->t1 - seg->t0);
            continue;
        }
        float t0 = seg->t0;
        for (;;) {
            // An exponential distance (pbrt-v4's SampleExponential: -log(1 - u) / a).
            const float t = t0 - std::log1p(-u) / sigma_h;
            u = rng.next_float();
            if (t >= seg->t1) {
                T_maj *= majorant_transmittance(seg->sigma_maj, seg->t1 - t0);
                break;
            }
            T_maj *= majorant_transmittance(seg->sigma_maj, t - t0);
            const Vec3f p = ray.at(t);
            if (!callback(p, medium.at(p, ch), seg->sigma_maj, T_maj)) return Color(1.0f);
            T_maj = Color(1.0f);
            t0 = t;
        }
    }
}

}  // namespace candela
