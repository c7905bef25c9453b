#pragma once
// pbrt-v4's CloudMedium (`cloud`): a procedural cloud in the box p0..p1, sigma_a and sigma_s
// scaled by a density in [0, 1] made of Perlin noise (math/perlin_noise.h, pbrt-v4's Noise and
// DNoise), so a pbrt-v4 scene's cloud is the same cloud here. pbrt-v4's CloudMedium::Density, at
// a medium-space point p:
//   pp = frequency p, moved twice along the noise gradient when wispiness > 0
//        (pp += 0.05 wispiness 2^-i DNoise(10 1.99^i pp), i = 0, 1);
//   d  = sum over 5 octaves of 2^-(i+1) Noise(1.99^i pp);
//   d  = clamp((1 - p.y) 4.5 density d, 0, 1) + 2 max(0, 0.5 - p.y), clamped to [0, 1]
// (so the cloud thins with height and is solid below y = 0). It emits nothing.
//
// Its majorant is pbrt-v4's: sigma_a + sigma_s (the density is at most 1) over the stretch of the
// ray inside the box, one segment.
#include "candela/math/perlin_noise.h"
#include "candela/math/ray.h"
#include "candela/math/vec.h"
#include "candela/media/homogeneous_medium.h"
#include "candela/media/medium_box.h"
#include "candela/media/medium_point.h"
#include "candela/media/medium_spectrum.h"

namespace candela {

struct CloudMedium {
    MediumBox box;
    MediumSpectrum sigma_a, sigma_s;  // per unit length, at density 1
    float g = 0.0f;
    float density = 1.0f, wispiness = 1.0f, frequency = 5.0f;
    bool emissive = false;

    // The density at medium-space point p, in [0, 1].
    CANDELA_HD float density_at(const Vec3f& p) const {
        Vec3f pp = p * frequency;
        if (wispiness > 0.0f) {
            float vomega = 0.05f * wispiness, vlambda = 10.0f;
            for (int i = 0; i < 2; ++i) {
                pp += perlin_noise_gradient(pp * vlambda) * vomega;
                vomega *= 0.5f;
                vlambda *= 1.99f;
            }
        }
        float d = 0.0f;
        float omega = 0.5f, lambda = 1.0f;
        for (int i = 0; i < 5; ++i) {
            d += omega * perlin_noise(pp * lambda);
            omega *= 0.5f;
            lambda *= 1.99f;
        }
        d = clamp((1 - p.y) * 4.5f * density * d, 0.0f, 1.0f);
        d += 2 * (0.5f - p.y > 0.0f ? 0.5f - p.y : 0.0f);
        return clamp(d, 0.0f, 1.0f);
    }

    CANDELA_HD MediumPoint at(const Vec3f& p_world, const MediumChannels& ch) const {
        const float d = density_at(box.to_medium(p_world));
        return {sigma_a.at(ch) * d, sigma_s.at(ch) * d, Color(0.0f)};
    }

    CANDELA_HD HomogeneousMedium::Majorants majorants(const Ray& ray, float t_max, const MediumChannels& ch) const {
        Ray r;
        float t0, t1;
        if (!box.clip(ray, t_max, &r, &t0, &t1)) return {};
        return {MajorantSegment{t0, t1, sigma_a.at(ch) + sigma_s.at(ch)}};
    }
};

}  // namespace candela
